"""figures_core.py -- the figure tables of the core design (tools/figures.py):
the test summary, the checkers' negatives, termination, driver size and
overhead, the co-simulation, CDC, synthesis and FPGA fits (the controller's
area: figures_area.py), the system's latency, delivery and bus, the robot, the proofs.  SECTIONS
maps each block name to the function that makes its table."""
import glob
import os

from figures_common import REPORTS, old_rows, old_lines, old_text, load, missing, table, n, viol


def tests():
    rows = []
    labels = ("exhaustive interleavings, two-word values", "exhaustive interleavings, three-word values (`make test-slow`)",
              "random timing, ratios 1:100..100:1",
              "soak (`make soak`), same harness", "crash: frozen / reset at every access point",
              "independent clocks through albatross_wb_cdc")
    ex, exw, rnd, soak, cr, cdc = (load(f) for f in ("tb_exhaustive.json", "tb_exhaustive_wide.json", "tb_random.json",
                                                    "tb_soak.json", "tb_crash.json", "cdc.json"))
    if not any((ex, exw, rnd, soak, cr, cdc)):
        missing("tb_*.json", "make test")
    for label, rep in zip(labels, (ex, exw, rnd, soak, cr, cdc)):
        if not rep:                       # this report is absent: keep its old row
            rows += old_rows(label)
        elif rep is ex or rep is exw:
            rows.append([label, f"{n(rep['schedules'])} schedules, "
                         f"{n(rep['collisions'])} same-cycle same-byte collisions",
                         n(rep["imports_checked"]), viol(rep)])
        elif rep is cr:
            rows.append([label, f"{n(cr['runs'])} runs, {n(cr['survivor_calls'])} survivor calls", "-", viol(cr)])
        elif rep is cdc:
            chk = cdc.get("checkers", {})
            fails = sum(c.get("failures", 0) for c in chk.values())
            rows.append([label, f"{n(cdc['accesses'])} accesses, {n(cdc['reads_contended'])} contended reads",
                         "-", n(fails)])
        else:                             # random, soak: the same harness
            rows.append([label, f"{n(rep['channels'])} channels, {n(rep['cycles'])} cycles",
                         n(rep["imports_checked"]), viol(rep)])
    return table(["test", "explored", "Imports checked", "violations"], rows)


def termination():
    rnd = load("tb_random.json")
    if not rnd:
        missing("tb_random.json", "make test")
    rows = []
    for b in rnd["termination_by_speed_ratio"]:
        lo, hi = 10 ** b["log10_ratio_from"], 10 ** b["log10_ratio_to"]
        rows.append([f"{lo:.3g} .. {hi:.3g}", n(b["imports"]), f"{b['mean_iterations']:.3f}",
                     b["worst_iterations"], b["worst_control_accesses"]])
    return table(["writer : reader speed", "Imports", "mean loop iterations", "worst iterations",
                  "worst accesses beyond payload"], rows)


def overhead():
    rnd = load("tb_random.json")
    if not rnd:
        missing("tb_random.json", "make test")
    ov = rnd["accesses_beyond_payload"]
    return table(["call (undisturbed)", "required", "measured"],
                 [["Export", 2, ov["export"]], ["Import, no new data", 1, ov["import_old"]],
                  ["Import, new data", 3, ov["import_new"]]])


def negative():
    rows = []
    for f in sorted(os.listdir(REPORTS)) if os.path.isdir(REPORTS) else []:
        if f.startswith("tb_negative_") and f.endswith(".json"):
            rep = load(f)
            if rep:
                rows.append([f"`{rep['variant']}`", rep.get("caught_by", "") or "**not caught**"])
    if not rows:
        missing("tb_negative_*.json", "make test")
    return table(["broken variant", "caught by"], rows)


def driver_size():
    ds = load("driver_size.json")
    if not ds:
        missing("driver_size.json", "make bench")
    rows = []
    for level, d in ds["levels"].items():
        fn = d["functions"]
        rows.append([level, fn["alb_import"]["with_libgcc"], fn["alb_export"]["with_libgcc"], d["text_bytes"]])
    return table(["rv32i", "alb_import (bytes)", "alb_export (bytes)", "whole driver .text"], rows)


def bench():
    b = load("bench_tb.json")
    if not b:
        missing("bench_tb.json", "make bench")
    return table(["figure", "value"], [
        ["RAM accesses by simulated CPUs per second of wall time", f"{b['accesses_per_second'] / 1e6:.2f} M"],
        ["simulated cycles per second, with CPUs", f"{b['cycles_per_second'] / 1e6:.2f} M"],
        ["simulated cycles per second, idle RTL alone", f"{b['idle_rtl_cycles_per_second'] / 1e6:.2f} M"],
        ["with CPUs / idle RTL (same run)", f"{b['with_cpus_over_idle']:.2f}"]])


def cdc():
    c = load("cdc.json")
    if not c:
        missing("cdc.json", "make test")
    rows = []
    for cpu, d in sorted(c["cpus"].items()):
        for case, lat in d["latency"].items():
            rows.append([cpu, case.replace("_", " "), f"`{lat['bound_formula']}`", n(lat["count"]),
                         f"{lat['worst_ratio_to_bound']:.3f}"])
    return table(["CPU", "access", "bound", "accesses", "worst / bound"], rows)


def synth():
    s = load("synth_albatross_dpram.json")
    if not s:
        missing("synth_albatross_dpram.json", "make bench")
    rows = []
    for fam, d in s["families"].items():
        rows.append([fam, d["luts"], d["ffs"], d["brams"], "yes" if d["bram_inferred"] else "**no**"])
    return table([f"family (ADDR_WIDTH={s.get('addr_width', '?')})", "LUTs", "flip-flops", "block RAMs",
                  "block RAM inferred"], rows)


def system_latency():
    if not (load("system_rigid.json") or load("system_possync.json")):
        missing("system_rigid.json", "make test")
    rows = []
    for name, label in (("system_rigid.json", "time-rigid"), ("system_possync.json", "position-synchronised")):
        r = load(name)
        if not r:
            rows += old_rows(label)
            continue
        for c in r["channels"]:
            rows.append([label, c["channel"], c["to_board"], n(c["latency_samples"]), f"{c['latency_mean']:.0f}",
                         c["latency_max"], c["latency_bound"], f"{c['max_over_bound']:.3f}"])
    if not rows:
        missing("system_rigid.json", "make test")
    return table(["mode", "channel", "to board", "values", "mean (clk)", "worst (clk)", "compiler bound",
                  "worst / bound"], rows)


def system_delivery():
    runs = [("system_faults-5.json", "system_faults-5-noredundancy.json", "5 % of accesses faulted"),
            ("system_faults-20-burst-60.json", "system_faults-20-burst-60-noredundancy.json",
             "20 % of accesses, bursts of 60 accesses")]
    if not any(load(red) and load(nored) for red, nored, _ in runs):
        missing("system_faults-5*.json", "make test")
    rows = []
    for red, nored, label in runs:
        a, b = load(red), load(nored)
        if not a or not b:
            rows += old_rows(label)
            continue
        other = {(c["channel"], c["to_board"]): c for c in b["channels"]}
        for c in a["channels"]:
            o = other.get((c["channel"], c["to_board"]))
            if not o or c["kind"] != "copy":
                continue
            rows.append([label, c["channel"], c["to_board"],
                         f"{100 * c['delivered_within_bound']:.1f} %", c["latency_max"], f"{c['max_over_bound']:.2f}",
                         f"{100 * o['delivered_within_bound']:.1f} %", o["latency_max"], f"{o['max_over_bound']:.2f}"])
    if not rows:
        missing("system_faults-5*.json", "make test")
    return table(["faults", "channel", "to board", "redundant: within bound", "worst (clk)", "worst / bound",
                  "one slot a cycle: within bound", "worst (clk)", "worst / bound"], rows)


def system_fault_rates():
    """Nominal against measured fault rate per access, every system run."""
    rows = []
    for path in sorted(glob.glob(os.path.join(REPORTS, "system_*.json"))):
        r = load(os.path.basename(path))
        if not r or "fault_rate_measured" not in r or not r.get("fault_rate"):
            continue
        burst = f"{r['fault_mean_burst']:.3g}" + (" (independent)" if not r.get("burst") else "")
        rows.append([f"`{r['label']}`", r.get("fault_clocking", "access"), f"{r['fault_rate']:.3f}", burst,
                     n(r["fault_accesses"]), n(r["faults_injected"]), f"{r['fault_rate_measured']:.4f}",
                     f"± {r['fault_rate_tolerance']:.4f}", "yes" if r["fault_rate_ok"] else "**no**"])
    if not rows:
        missing("system_faults-5.json", "make test")
    return table(["run", "drawn per", "nominal rate", "mean burst (accesses)", "accesses", "faulted",
                  "measured rate", "tolerance (6 σ)", "within"], rows)


def system_bus():
    r = load("system_bus_bench.json")
    if not r:
        missing("system_bus_bench.json", "make bench")
    rows = [[t["bytes"], n(t["transfers"]), f"{t['mean_cycles']:.1f}", t["minimum_cycles"],
             f"{t['mean_cycles'] / t['minimum_cycles']:.3f}", f"{t['efficiency']:.3f}", f"{t['mean_idle_cycles']:.2f}"]
            for t in r["transfers"]]
    return table(["channel bytes", "transfers", "bus clocks (mean)", "protocol minimum", "measured / minimum",
                  "efficiency (payload / all)", "idle clocks inside"], rows)


def pico_cost():
    b = load("bench_pico.json")
    if not b:
        missing("bench_pico.json", "make bench-pico")
    rows = []
    for e in b["sizes"]:
        ex, new, old = e["export"]["mean"], e["import_new"]["mean"], e["import_old"]["mean"]
        ct, cf = e["copy_to_dpram"]["mean"], e["copy_from_dpram"]["mean"]
        rows.append([e["bytes"], f"{ex:.0f}", f"{new:.0f}", f"{old:.0f}", f"{ct:.0f}", f"{cf:.0f}",
                     f"{ex / ct:.2f}", f"{new / cf:.2f}", f"{ex - ct:+.0f}", f"{new - cf:+.0f}"])
    out = table(["bytes", "Export", "Import, new", "Import, old", "plain copy to DPRAM",
                 "plain copy from DPRAM", "Export / copy", "Import new / copy", "Export − copy",
                 "Import new − copy"], rows)
    pw = b["per_word"]
    out += "\n\n" + table(["cycles", "Export", "Import, new", "Import, old", "plain copy to DPRAM",
                            "plain copy from DPRAM"],
                           [["per payload word (4 → 256 B)"] + [f"{pw[k]['cycles_per_word']:.1f}" for k in
                             ("export", "import_new", "import_old", "copy_to_dpram", "copy_from_dpram")],
                            ["fixed part of a call"] + [f"{pw[k]['fixed_cycles']:.0f}" for k in
                             ("export", "import_new", "import_old", "copy_to_dpram", "copy_from_dpram")]])
    ds = load("driver_size.json")
    lv = ds and ds["levels"].get("-Os")
    if lv:
        fn = lv["functions"]
        out += (f"\n\nCode size, rv32i `-Os` (`{REPORTS}/driver_size.json`): `alb_import` "
                f"{fn['alb_import']['with_helpers']} bytes, `alb_export` {fn['alb_export']['with_helpers']} bytes "
                f"of .text.")
    else:                                 # keep the old line, if any
        out += "".join("\n\n" + line for line in old_lines("Code size"))
    return out


def robot():
    r = load("pico_boards.json")
    if not r:
        missing("pico_boards.json", "make test-pico-boards")
    rows = []
    for e in r["series"]:
        a = e["age"]
        rows.append([e["channel"], e["consumer"], n(e["new"]), n(a["min"]), n(a["mean"]), n(a["max"]),
                     n(e["bound"]), f"{a['max'] / e['bound']:.3f}" if e["bound"] else "-",
                     n(e["import_cycles"]["mean"])])
    out = table(["channel", "consumer", "New", "age min", "age mean", "age max", "bound", "max / bound",
                 "cycles per Import"], rows)
    rows = [[p["channel"], p["producer"], n(p["exports"]), n(p["export_cycles"]["mean"]),
             n(p["export_cycles"]["max"]), n(p["max_gap"])] for p in r["producers"]]
    out += "\n\n" + table(["channel", "producer", "Exports", "cycles per Export (mean)", "(max)",
                           "longest gap between Actual stores"], rows)
    return out + (f"\n\nAges, bounds and gaps in controller clocks (50 MHz); {n(r['cycles'])} cycles, "
                  f"seed {r['seed']}, cores stalled in random bursts (`{REPORTS}/pico_boards.json`).")


def robot_scenarios():
    if not any(load(f + ".json") for f in ("pico_boards", "pico_boards_faults", "pico_boards_crash", "serv_boards")):
        missing("pico_boards*.json", "make test")
    rows = []
    for name, what in (("pico_boards", "fault-free"), ("pico_boards_faults", "bus faults"),
                       ("pico_boards_crash", "radar crashes inside an Export"),
                       ("serv_boards", "motor board on SERV"),
                       ("pico_boards_modes", "two modes, navigation switches"),
                       ("pico_boards_modes_faults", "two modes, switching, bus faults")):
        r = load(name + ".json")
        if not r:
            kept = old_rows(what)
            rows += kept or [[what, f"_not measured yet: `make test` writes `{REPORTS}/{name}.json`_"] + [""] * 5]
            continue
        worst = max((e.get("worst_ratio", e["age"]["max"] / (e["bound"] or 1)) for e in r["series"]
                     if e["bound"] and not (r.get("crash_board") and e["channel"] == "RadarMap")), default=0)
        stale = (f"after {n(r['first_stale_cycle'] - r['crash_cycle'])} clocks" if r.get("crash_board")
                 and r["stale_events"] else n(r["stale_events"]))
        rows.append([what, f"{r['fault_rate']:.2f}", f"{n(r['faults_injected'])} / {n(r['requests'])}",
                     f"{n(r['status_retries'])} / {n(r['status_abandoned'])}", f"{worst:.3f}", stale,
                     r["verdict"]])
    return table(["scenario", "fault rate", "faults / requests", "STATUS retries / abandoned",
                  "worst age / bound (live producers)", "RadarMap stale reported", "verdict"], rows)


def fpga():
    r = load("fpga.json")
    if not r:
        missing("fpga.json", "make synth")
    names = {"dpram": "albatross_dpram (4 KiB)", "controller": "albatross_controller (NB 4, N_CHAN 16)",
             "picorv32": "one PicoRV32 (as pico_core)", "top": "board top (two boards)"}
    rows = []
    for e in r["rows"]:
        if "luts" not in e:
            rows.append([names.get(e["design"], e["design"]), e["family"], "error", "", "", "", "", ""])
            continue
        fm, clocks = e.get("fmax_mhz"), e.get("clocks")
        if clocks:   # a placed top: every clock domain
            fm_text = ", ".join(f"{net} {c['fmax_mhz']:.1f}" for net, c in sorted(clocks.items()))
        else:
            fm_text = f"{fm:.1f}" if fm is not None else None
        rows.append([names.get(e["design"], e["design"]), e["family"], n(e["luts"]), n(e["ffs"]), n(e["carries"]),
                     n(e["brams"]), n(e["lutrams"]),
                     (f"{fm_text} ({e['pnr_part']})" if fm_text else "-")])
    out = table(["design", "family", "LUTs", "FFs", "carries", "block RAMs", "LUT RAMs", "Fmax MHz (part)"], rows)
    for e in r["rows"]:
        if e["design"] != "top" or not e.get("clocks"):
            continue
        out += f"\n\nThe {e['family']} top ({e['top']}, {e['pnr_part']}), per clock domain:"
        for net, c in sorted(e["clocks"].items()):
            cp = c.get("critical_path") or ["?", "?"]
            out += (f"\n- `{net}`: Fmax {c['fmax_mhz']:.1f} MHz against {c['constraint_mhz']:g} MHz; "
                    f"critical path from `{cp[0]}` to `{cp[1]}`")
        for x in e.get("clock_crossings", []):
            out += f"\n- worst path from `{x['from']}` to `{x['to']}`: {x['delay_ns']:.2f} ns"
    ratios = r.get("controller_over_picorv32_luts", {})
    if ratios:
        out += "\n\nController LUTs / one PicoRV32's LUTs: " + ", ".join(
            f"{fam} {x:.2f}" for fam, x in ratios.items()) + f" (`{REPORTS}/fpga.json`)."
    return out


def sim_speed():
    r = load("sim_speed.json")
    if not r:
        missing("sim_speed.json", "make bench-sim-speed")
    return table(["simulator", "cycles run", "wall time (s)", "cycles per second"],
                 [["Verilator 5 (harness with every check)", n(r["verilator_cycles"]), r["verilator_wall_s"],
                   n(r["verilator_cycles_per_s"])],
                  ["Icarus Verilog 11", n(r["icarus_cycles"]), r["icarus_wall_s"], n(r["icarus_cycles_per_s"])],
                  ["Verilator / Icarus", "", "", f"{r['verilator_over_icarus']:.0f}"]])


def formal_spin():
    rows = []
    negatives = sorted(f for f in (os.listdir(REPORTS) if os.path.isdir(REPORTS) else [])
                       if f.startswith("formal_spin_negative_") and f.endswith(".json"))
    if not load("formal_spin.json") and not negatives:
        missing("formal_spin.json", "make formal")
    if not load("formal_spin.json"):      # keep the old rows of the protocol itself
        rows += old_rows("protocol")
    for name in ["formal_spin.json"] + negatives:
        rep = load(name)
        for c in (rep or {}).get("checks", []):
            variant = f"`-D{rep['variant']}`" if rep.get("variant") else "protocol"
            rows.append([variant, c["check"], c["result"],
                         "yes" if c["ok"] else "**no**", n(c["states"]), n(c["depth"]),
                         f"{c['seconds']:.2f}"])
    if not negatives:                     # keep the old rows of the broken variants
        rows += [r for line in old_text().splitlines() if line.startswith("| `-D")
                 for r in [[c.strip() for c in line.strip().strip("|").split(" | ")]]]
    return table(["model", "check", "result", "as expected", "states stored",
                  "depth", "pan seconds"], rows)


def formal_rtl():
    rep = load("formal_rtl.json")
    if not rep:
        missing("formal_rtl.json", "make test-slow")
    rows = []
    for c in (rep or {}).get("checks", []):
        det = c.get("detail") or {}
        if c["expect"] == "pass":
            props = ", ".join(f"`{p}`" for p in c["properties"])
            result = "hold" if c["ok"] else "**fail: " + ", ".join(det.get("failed", [])) + "**"
        else:
            props = "broken variant, must fail on " + " or ".join(f"`{e}`" for e in c["expect"].split("|"))
            failed = det.get("failed", [])
            result = ("caught by " if c["ok"] else "**not caught**: ") + (", ".join(f"`{f}`" for f in failed) or "none")
        rows.append([c["check"], c["engine"], props, result, c["depth"], f"{c['seconds']:.1f}"])
    return table(["check", "engine", "properties", "result", "depth (clocks)", "seconds"], rows)


SECTIONS = {"fpga": fpga, "robot": robot, "robot-scenarios": robot_scenarios, "sim-speed": sim_speed, "system-latency": system_latency, "system-delivery": system_delivery, "system-bus": system_bus, "system-fault-rates": system_fault_rates,"tests": tests, "termination": termination, "overhead": overhead, "negative": negative,
            "driver-size": driver_size, "bench": bench, "cdc": cdc, "synth": synth,
            "pico-cost": pico_cost, "formal-spin": formal_spin}


SECTIONS["formal-rtl"] = formal_rtl


def compile_time():
    """The schedule compiler's time (make bench-compile-time)."""
    r = load("compile_time.json")
    if not r:
        missing("compile_time.json", "make bench-compile-time")
    names = {"robot": "the robot (`sim/mobot3.toml`, `make schedule`)",
             "robot-modes": "the robot with its two modes (`build/schedule/mobot3-modes`)",
             "robot-modes-f20": "the same, planned for 20 % faults (`--faults 0.2`)",
             "modes-share": "two modes that fill the ROM (`compiler/examples/modes_share.toml`)"}
    rows = [[names.get(x["label"], x["description"]), x["rom_entries"], f"{x['cpu_s']:.2f}",
             f"{x['cpu_s_min']:.2f} - {x['cpu_s_max']:.2f}", f"{x['wall_s']:.2f}"] for x in r["runs"]]
    return (table(["description", "ROM entries", "CPU s (median)", "CPU s (range)", "wall s (median)"], rows)
            + f"\n\n(median of {r['runs'][0]['repeats']} runs of `albatross-schedule` each, Python's start "
            f"included; {r['cpus']} cores, load {r['load_average_1min_at_start']:g} at the start; "
            f"`{REPORTS}/compile_time.json`)")


SECTIONS["compile-time"] = compile_time


def schedulability():
    """Acceptance per bus demand: today's single-rate plan, the compiler with
    its multi-rate planner, and the exact search on the power-of-two grid
    (make bench-schedulability)."""
    r = load("schedulability.json")
    if not r:
        missing("schedulability.json", "make bench-schedulability")
    names = r["planners"]
    head = {"single-rate": "single-rate (today)", "exact-grid": "exact grid", "multi-rate": "multi-rate (the compiler)"}
    proofs = ("slot", "pair", "load", "search", "finer", "period")

    def cpu(s):
        return f"{s['median']:.3f} ({s['max']:.2f})" if s else "-"
    rows = []
    for lv in r["levels"]:
        n_ = lv["systems"]
        row = [lv["demand_pct"], n_]
        row += [f"{lv[p]['accepted']} ({100 * lv[p]['accepted'] / n_:.0f} %)" for p in names]
        if "exact-grid" in names:
            e = lv["exact-grid"]
            row.append(e["unknown"])
            why = e["rejected_why"]
            row.append(", ".join(f"{k} {why[k]}" for k in proofs if why.get(k)) or "-")
        if "multi-rate" in names:
            why = lv["multi-rate"]["rejected_why"]
            row.append(", ".join(f"{k} {why[k]}" for k in sorted(why)) or "-")
        row += [cpu(lv[p]["seconds"]) for p in names]
        row.append(f"{lv['redraws']['ram-overflow']}")
        rows.append(row)
    cols = ["demand %", "systems"] + [f"{head.get(p, p)} accepted" for p in names]
    if "exact-grid" in names:
        cols += ["exact: unknown", "exact: proofs of rejection"]
    if "multi-rate" in names:
        cols += ["multi-rate: reasons of rejection"]
    cols += [f"{head.get(p, p)} CPU s, median (max)" for p in names] + ["redrawn: RAM overflow"]
    seeds = [s["seed"] for s in r["systems"]]
    return (table(cols, rows)
            + f"\n\n({r['systems_per_level']} systems per level, seeds {min(seeds)} to {max(seeds)} "
            f"(demand target in percent times {r['generator_ranges']['seed_stride']:,}, plus a count); the exact "
            f"search's limit {r['time_limit_s']:g} units of CP-SAT's deterministic time per system; "
            f"{r['cpus']} cores, load {r['load_average_1min_at_start']:g} at the start, {r['wall_s']:.0f} s in all; "
            f"`{REPORTS}/schedulability.json`, picture `{REPORTS}/schedulability.svg`)")


SECTIONS["schedulability"] = schedulability
