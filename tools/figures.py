#!/usr/bin/env python3
"""figures.py [FILE.md ...] -- regenerate the manual's figure tables from
build/reports/*.json (written by make test and make bench).  Without
arguments: README.md and docs/*.md.

Each table sits between the markers
    <!-- figures:NAME -->   and   <!-- /figures:NAME -->
in any of the files, and is replaced whole.  Every NAME below must appear in
exactly one block of the files given, and every block must name a table this
script knows, so a table can move between pages but never get lost or
doubled.  A table whose report is absent is kept as it is (a row whose own
report is absent is kept from the old table); only a block that is still
empty says which make target produces it.  No measured number is ever typed
into the manual by hand.  Standard library only.
"""
import glob
import json
import os
import re
import sys

REPORTS = "build/reports"


class Absent(Exception):
    """The report a table is made from is absent: keep the table as it is."""


# The text between the markers of the block being regenerated (its old table).
_old = ""


def old_rows(first):
    """The rows of the old table whose first cell is FIRST (cells as strings)."""
    rows = []
    for line in _old.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if line.startswith("| ") and cells[0] == first:
            rows.append(cells)
    return rows


def old_lines(prefix):
    """The lines of the old block that start with PREFIX."""
    return [line for line in _old.splitlines() if line.startswith(prefix)]


def load(name):
    path = os.path.join(REPORTS, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def missing(name, target):
    raise Absent(f"_Not measured yet: `{target}` writes `{REPORTS}/{name}`._")


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def n(v):
    return f"{v:,.0f}"


def viol(rep):
    return n(rep.get("violations_total", 0))


def tests():
    rows = []
    labels = ("exhaustive interleavings", "random timing, ratios 1:100..100:1",
              "soak (`make soak`), same harness", "crash: frozen / reset at every access point",
              "independent clocks through albatross_wb_cdc")
    ex, rnd, soak, cr, cdc = (load(f) for f in ("tb_exhaustive.json", "tb_random.json", "tb_soak.json",
                                               "tb_crash.json", "cdc.json"))
    if not any((ex, rnd, soak, cr, cdc)):
        missing("tb_*.json", "make test")
    for label, rep in zip(labels, (ex, rnd, soak, cr, cdc)):
        if not rep:                       # this report is absent: keep its old row
            rows += old_rows(label)
        elif rep is ex:
            rows.append([label, f"{n(ex['schedules'])} schedules, "
                         f"{n(ex['collisions'])} same-cycle same-byte collisions",
                         n(ex["imports_checked"]), viol(ex)])
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
                       ("serv_boards", "motor board on SERV")):
        r = load(name + ".json")
        if not r:
            kept = old_rows(what)
            rows += kept or [[what, f"_not measured yet: `make test` writes `{REPORTS}/{name}.json`_"] + [""] * 5]
            continue
        worst = max((e["age"]["max"] / e["bound"] for e in r["series"]
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


def controller_area():
    r = load("controller_area.json")
    if not r:
        missing("controller_area.json", "make area")
    fams = list(r["picorv32_luts"])
    head = ["controller variant", "what is tied off"] + [f"{fam} LUTs (/ PicoRV32)" for fam in fams]
    rows = [["one PicoRV32 (as pico_core)", "-"] + [n(r["picorv32_luts"][f]) if r["picorv32_luts"][f] else "error"
                                                   for f in fams]]
    for name in dict.fromkeys(e["variant"] for e in r["rows"]):
        cells = []
        for fam in fams:
            e = next(x for x in r["rows"] if x["variant"] == name and x["family"] == fam)
            cells.append(f"{n(e['luts'])} ({e['over_picorv32']:.2f})" if "over_picorv32" in e else "error")
        desc = next(x["description"] for x in r["rows"] if x["variant"] == name)
        rows.append([name, desc] + cells)
    out = table(head, rows) + (f"\n\nThe goal (issue 12): at most {r['goal_over_picorv32']:.2f} of one PicoRV32, aim "
        f"{r.get('aim_over_picorv32', r['goal_over_picorv32']):.2f} (`{REPORTS}/controller_area.json`).")
    parts = r.get("parts_ice40")
    if parts:
        out += ("\n\nWhere the full controller's LUTs go on iCE40 (synthesised without flattening, so a part's "
                "LUTs are its own; the sum is above the flattened figure):\n\n"
                + table(["part", "ice40 LUTs"], [[f"`{k}`", n(v)] for k, v in sorted(parts.items(), key=lambda kv: -kv[1])]
                        + [["sum", n(sum(parts.values()))]]))
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
        rows += [r for line in _old.splitlines() if line.startswith("| `-D")
                 for r in [[c.strip() for c in line.strip().strip("|").split(" | ")]]]
    return table(["model", "check", "result", "as expected", "states stored",
                  "depth", "pan seconds"], rows)


def formal_rtl():
    rep = load("formal_rtl.json")
    if not rep:
        missing("formal_rtl.json", "make formal")
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


SECTIONS = {"fpga": fpga, "controller-area": controller_area, "robot": robot, "robot-scenarios": robot_scenarios, "sim-speed": sim_speed, "system-latency": system_latency, "system-delivery": system_delivery, "system-bus": system_bus, "system-fault-rates": system_fault_rates,"tests": tests, "termination": termination, "overhead": overhead, "negative": negative,
            "driver-size": driver_size, "bench": bench, "cdc": cdc, "synth": synth,
            "pico-cost": pico_cost, "formal-spin": formal_spin}


SECTIONS["formal-rtl"] = formal_rtl


def fault_plan():
    """The compiler's predictions for the robot at several fault rates (make bench-fault-plan)."""
    rep = load("fault_plan.json")
    if not rep:
        missing("fault_plan.json", "make bench-fault-plan")
    runs = [r for r in rep["runs"] if r.get("independent")]
    head = ["channel -> consumer"] + [f"{100 * r['rate']:g} %" for r in runs]
    keys = []
    for r in runs:
        for c in r.get("channels", []):
            if (c["channel"], c["consumer"]) not in keys:
                keys.append((c["channel"], c["consumer"]))
    rows = [["target probability"] + [f"1 - {1 - r['probability']:.0e}" if r["probability"] > 0.995 else
                                      f"{r['probability']:g}" for r in runs]]
    for ch, co in keys:
        row = [f"{ch} -> {co}"]
        for r in runs:
            c = next((c for c in r.get("channels", []) if (c["channel"], c["consumer"]) == (ch, co)), None)
            if c is None:
                row.append("rejected")
                continue
            miss = c["slot_miss_probability"]
            q = "1" if miss < 1e-14 else f"1 - {miss:.1e}"   # below 1e-14: rounding of the sum
            row.append(f"x{c['slots']}, R {c['retries_per_slot']}, q {q}: "
                       f"{c['age_bound']['fault_free']['us']:.2f} / {c['age_bound']['at_target']['us']:.2f}")
        rows.append(row)
    rows.append(["drop run K"] + [str(r.get("drop_run", "-")) for r in runs])
    bursty = [r for r in rep["runs"] if not r.get("independent")]
    note = "; ".join(f"mean burst {r['mean_burst']:g}, {100 * r['rate']:g} %: "
                     + (f"planned, K = {r['drop_run']}" if r["planned"] else "rejected") for r in bursty)
    return table(head, rows) + (f"\n\nAt 1 - 1e-9 with bursts: {note}." if bursty else "")


SECTIONS["fault-plan"] = fault_plan


def _miss(p):
    """A delivery probability as 1 - miss (or 1)."""
    return "1" if 1 - p < 5e-10 else f"1 - {1 - p:.1e}"


def fault_rates():
    """Per channel, delivery per cycle and worst age against the true fault rate,
    measured beside the compiler's prediction (make bench-fault-rates)."""
    rep = load("fault_rates.json")
    if not rep:
        missing("fault_rates.json", "make bench-fault-rates")
    pts = [p for p in rep["points"] if p.get("planned")]
    head = ["true rate", "plan for", "channel (size)", "delivery/cycle predicted", "measured",
            "worst age us measured", "bound at target us", "checks"]
    rows = []
    for p in pts:
        rate = f"{100 * p['rate']:g} %" + (f", burst {p['mean_burst']:g}" if not p["independent"] else "")
        target = f"1 - {1 - p['probability']:.0e}" if p["probability"] > 0.995 else f"{p['probability']:g}"
        ok = ("tb_system " + ("pass" if p["tb_system_passed"] else "FAIL") + ", ages " +
              ("pass" if not p["check_failures"] else "FAIL"))
        for c in p["channels"]:
            rows.append([rate, target, f"{c['channel']} ({c['size']} B)", _miss(c["predicted_cycle_delivery"]),
                         _miss(c["measured_cycle_delivery"]), f"{c['worst_age'] / 50:.1f}",
                         f"{c['age_bound_at_target'] / 50:.1f}", ok])
            rate = target = ok = ""
    rejected = [p for p in rep["points"] if not p.get("planned")]
    note = "; ".join(f"{100 * p['rate']:g} %" + (f" burst {p['mean_burst']:g}" if p["mean_burst"] else "")
                     for p in rejected)
    return table(head, rows) + (f"\n\nNot planned at any target: {note}." if rejected else "")


def fault_rates_50():
    """Per channel and consumer at 50 % true faults: predicted and measured
    delivery per cycle, tb_system and the robot (make bench-fault-rates)."""
    rep = load("fault_rates.json")
    if not rep:
        missing("fault_rates.json", "make bench-fault-rates")
    sysp = next((p for p in rep["points"] if p["independent"] and p["rate"] == 0.5 and p.get("planned")), None)
    rob = next((r for r in rep.get("robot", []) if r["rate"] == 0.5), None)
    if sysp is None:
        raise Absent()
    head = ["channel (size) -> consumer", "slot q predicted", "slot measured tb_system (missed/slots)",
            "delivery/cycle predicted", "measured tb_system", "measured robot", "worst age us tb_system / robot",
            "bound at target us"]
    rows = []
    for c in sysp["consumers"]:
        r = next((x for x in (rob or {}).get("consumers", []) if (x["channel"], x["board"]) == (c["channel"], c["board"])), None)
        rows.append([f"{c['channel']} ({c['size']} B) -> {c['board']}", f"{c['predicted_slot_delivery']:.4f}",
                     f"{c['measured_slot_delivery']:.4f} ({c['slots_missed']}/{c['slot_trials']})"
                     if "measured_slot_delivery" in c else "-",
                     f"{c['predicted_cycle_delivery']:.4f}", f"{c.get('measured_cycle_delivery', 0):.4f}",
                     f"{r.get('measured_cycle_delivery', 0):.4f}" if r else "-",
                     f"{c.get('worst_age', 0) / 50:.1f} / " + (f"{r.get('worst_age', 0) / 50:.1f}" if r else "-"),
                     f"{c['age_bound_at_target'] / 50:.1f}"])
    return table(head, rows) + (f"\n\nPlanned for {sysp['probability']:g} (K = {sysp['drop_run']}); "
                                f"tb_system {sysp['cycles_measured']} cycles measured, measured fault rate "
                                f"{sysp['fault_rate_measured']:.4f}; the robot's copy channels' ages include "
                                f"their producer's gaps.")


SECTIONS["fault-rates"] = fault_rates
SECTIONS["fault-rates-50"] = fault_rates_50


def formal_sby():
    rep = load("formal_sby.json")
    if not rep:
        missing("formal_sby.json", "make formal")
    rows = []
    for c in rep.get("checks", []):
        if c["expect"] == "pass":
            what = {"prove": "proof", "cover": "covers (non-vacuity)"}.get(c["mode"], c["mode"])
            result = c["result"] if c["ok"] else f"**{c['result']}**"
        else:
            what = "broken variant, must fail on " + " or ".join(f"`{e}`" for e in c["expect"].split("|"))
            hit = [f["property"] for f in c.get("failed", [])
                   if any(f["property"].endswith(e) for e in c["expect"].split("|"))]
            result = (f"caught by `{hit[0].split('.', 1)[-1]}` (step {[f['step'] for f in c['failed'] if f['property'] == hit[0]][0]})"
                      if c["ok"] and hit else "**not caught**")
        depth = c["depth"] if c["depth"] is not None else "unbounded (PDR)"
        rows.append([c["check"], f"`{c['engine']}`", c["mode"], what, depth, result, f"{c['seconds']:.1f}"])
    return table(["check", "engine", "mode", "what", "depth (steps)", "result", "seconds"], rows)


SECTIONS["formal-sby"] = formal_sby


def kinds_cost():
    """Cycles per call of both channel kinds on PicoRV32 and SERV (make bench-kinds),
    and the RAM of one channel instance per kind."""
    runs = [("PicoRV32", "three-buffer", "bench_pico.json"), ("PicoRV32", "four-slot", "bench_pico_four_slot.json"),
            ("SERV", "three-buffer", "bench_serv.json"), ("SERV", "four-slot", "bench_serv_four_slot.json")]
    reps = {f: load(f) for _, _, f in runs}
    ram = load("channel_ram.json")
    absent = [f for f, r in reps.items() if not r] + ([] if ram else ["channel_ram.json"])
    if absent:
        missing(absent[0], "make bench-kinds")
    rams = {e["bytes"]: e for e in ram["sizes"]}
    rows = []
    for cpu, kind, f in runs:
        for e in reps[f]["sizes"]:
            rb = rams.get(e["bytes"])
            key = "four_slot" if kind == "four-slot" else "three_buffer"
            rows.append([cpu, kind, e["bytes"], f"{e['export']['mean']:.0f}", f"{e['import_new']['mean']:.0f}",
                         f"{e['import_old']['mean']:.0f}", rb[key] if rb else "-"])
    return table(["CPU", "kind", "payload bytes", "Export", "Import, New", "Import, Old",
                  "RAM bytes per channel instance"], rows)


SECTIONS["kinds-cost"] = kinds_cost


def vex_cost():
    """Cycles per call on VexRiscv (data cache, DPRAM window uncached) next to PicoRV32,
    the same bench.c and driver, rv32i -Os (make bench-vex)."""
    p, v = load("bench_pico.json"), load("bench_vex.json")
    if not p or not v:
        missing("bench_vex.json" if p else "bench_pico.json", "make bench-vex")
    rows = []
    for ep, ev in zip(p["sizes"], v["sizes"]):
        row = [ep["bytes"]]
        for k in ("export", "import_new", "import_old", "copy_to_dpram", "copy_from_dpram"):
            a, b = ep[k]["mean"], ev[k]["mean"]
            row.append(f"{a:.0f} / {b:.0f} ({a / b:.1f}x)")
        rows.append(row)
    return table(["payload bytes", "Export", "Import, New", "Import, Old", "plain copy to DPRAM",
                  "plain copy from DPRAM"], rows) + (
        "\n\nEach cell: PicoRV32 / VexRiscv cycles per call (mean of "
        f"{v['calls_per_figure']} calls, the counter pair subtracted), and how many times fewer VexRiscv needs.")


SECTIONS["vex-cost"] = vex_cost


def vex_tests():
    """The VexRiscv pair tests and their negatives (make test-vex-*); "-": not a figure of that run
    (the robot runs have their own checks, docs/robot.md)."""
    runs = [("vex_pair.json", "PicoRV32 producer, VexRiscv consumer, window uncached"),
            ("vex_pair_producer.json", "VexRiscv producer, PicoRV32 consumer, window uncached"),
            ("vex_pair_cached_negative.json", "negative: VexRiscv producer, window cached"),
            ("vex_pair_cached_consumer_negative.json", "negative: VexRiscv consumer, channel cached"),
            ("vex_boards.json", "the robot's motor board on VexRiscv"),
            ("vex_boards_alias_negative.json", "negative: cached alias on the normal (robot) board")]
    rows = []
    for f, what in runs:
        r = load(f)
        if not r:
            continue
        vl = r.get("violations", {})
        if not isinstance(vl, dict):   # the robot's report: its own checks, not the pair checker's
            vl = {}

        def g(d, k):
            return n(d[k]) if k in d else "-"
        rows.append([f"`{r['label']}`", what, r["verdict"], g(r, "checked_exports"), g(r, "checked_imports"),
                     g(r, "consumer_reported_imports"), g(vl, "mutual_exclusion"), g(vl, "definite_results"),
                     g(r, "consumer_faulty_imports"), g(r, "stale_imports")])
    if not rows:
        missing("vex_pair.json", "make test-vex-pair")
    return table(["test", "what", "verdict", "Exports watched", "Imports watched at the RAM",
                  "Imports reported by the consumer", "mutual-exclusion violations", "definite-results violations",
                  "faulty values found by the consumer", "stale Imports"], rows)


SECTIONS["vex-tests"] = vex_tests


def sim_excerpt():
    """The head of `make sim`'s console report, as sim/mobot_sim.cpp prints it."""
    r = load("sim.json")
    if not r:
        missing("sim.json", "make sim")
    hz = r["clock_hz"]
    lines = ["```",
             f"{r['label']}: {r['cycles']} cycles ({1e3 * r['cycles'] / hz:.2f} ms at {hz / 1e6:.0f} MHz), "
             f"controller time {r['cycles']}, bus busy {100 * r['bus_busy_fraction']:.1f} %, {r['requests']} requests, "
             f"{r['faults_injected']} faults injected, STATUS: {r['status_retries']} retries, "
             f"{r['status_abandoned']} abandoned"]
    if "fault_rate_measured" in r:
        lines.append(f"  fault rate per access: nominal {r['fault_rate']:.4f}, measured {r['fault_rate_measured']:.4f} "
                     f"(mean burst {r['fault_mean_burst']:.3g} accesses; tolerance +-{r['fault_rate_tolerance']:.4f}, "
                     f"6 sigma){'' if r['fault_rate_ok'] else ': OUT OF TOLERANCE'}")
    lines += ["  %-11s %-11s %7s %7s %9s %9s %9s %9s %6s %11s" % ("channel", "consumer", "New", "Old", "age min",
                                                             "age mean", "age max", "bound", "ratio", "cyc/Import")]
    for s in r["series"][:4]:
        a = s["age"]
        lines.append("  %-11s %-11s %7d %7d %9d %9.0f %9d %9d %6.3f %11.0f" % (
            s["channel"], s["consumer"], s["new"], s["old"], a["min"], a["mean"], a["max"], s["bound"],
            a["max"] / s["bound"] if s["bound"] else 0.0, s["import_cycles"]["mean"]))
    return "\n".join(lines + ["  ...", "```"])


SECTIONS["sim-excerpt"] = sim_excerpt


def host_threads():
    """The real driver on two host threads (make test-host-threads and its negative;
    make soak-host for the long run): every Import checked, with and without the fence."""
    r = load("host_threads.json")
    if not r or "checked" not in r:
        missing("host_threads.json", "make test-host-threads")
    rows = []
    for sec, port in (("checked", "mmio (`lock or` fence)"), ("no_fence", "fence does nothing")):
        for x in r.get(sec, {}).get("runs", []):
            first = x.get("first_violation_at", 0)
            rows.append([port, x["kind"], x["payload_words"], n(x["imports"]), n(x["new"]), n(x["old"]),
                         n(x["overtaken"]), x["torn"], x["back_in_time"], x["stale"], x["wrong_new"],
                         x["wrong_old"], n(first) if first else "-"])
    return (f"Machine: {r['machine']['cpu']}, {r['machine']['cores']} cores. "
            f"{n(r['checked']['imports_total'])} Imports checked with the fence.\n\n"
            + table(["port", "kind", "words", "Imports", "New", "Old", "overtaken", "torn", "back in time",
                     "stale", "wrong New", "wrong Old", "first violation at Import"], rows))


SECTIONS["host-threads"] = host_threads


def host_threads_sites():
    """Each fence site of albatross.c dropped alone (make test-host-threads-sites)."""
    r = load("host_threads.json")
    if not r or "sites" not in r:
        missing("host_threads.json", "make test-host-threads-sites")
    rows = []
    for s in r["sites"]["sites"]:
        x = s.get("run")
        rows.append([s["line"], f"`{s['function']}`", s["comment"] or "-", s["order"],
                     s["kind"] if x else "-", n(x["imports"]) if x else "-",
                     f"{x['violations']} ({x['torn']} torn, {x['wrong_old']} wrong Old, "
                     f"{x['back_in_time'] + x['stale'] + x['wrong_new']} other)" if x else "-",
                     s["verdict"]])
    return table(["line", "function", "the fence orders", "order", "run on", "Imports",
                  "violations", "without this fence alone"], rows)


SECTIONS["host-threads-sites"] = host_threads_sites


def host_threads_reliability():
    """How reliably the fence-less builds fail within their budget (make soak-host)."""
    r = load("host_threads.json")
    if not r or "reliability" not in r:
        missing("host_threads.json", "make soak-host")
    rows = []
    for v in r["reliability"]["variants"]:
        f = sorted(x for x in v["first_violation_at"] if x)
        vi = sorted(v["violations"])
        rows.append([v["variant"], v["kind"], f"{v['failed']} of {v['runs']}", n(v["budget_imports"]),
                     f"{n(f[0])} / {n(f[len(f) // 2])} / {n(f[-1])}" if f else "-",
                     f"{vi[0]} / {vi[len(vi) // 2]} / {vi[-1]}"])
    rel = r["reliability"]
    over = (f" and until the producer overtook {n(rel['min_overtaken'])} of them (up to 40 s)"
            if rel.get("min_overtaken") else "")
    return (f"Payload {rel['words']} words. A run's budget is the Imports in the table{over}; "
            f"it stops at {rel['stop_after']} violations.\n\n"
            + table(["fence left out", "kind", "runs failed", "budget (Imports)",
                     "first violation at Import (min / median / max)", "violations per run (min / median / max)"],
                    rows))


SECTIONS["host-threads-reliability"] = host_threads_reliability


# A marker is a line of its own (a marker quoted inside a sentence is text).
BLOCK = re.compile(r"^<!-- figures:([A-Za-z0-9_-]+) -->\n(.*?)^<!-- /figures:\1 -->$", re.S | re.M)


def main():
    global _old
    paths = sys.argv[1:] or ["README.md"] + sorted(glob.glob("docs/*.md"))
    texts = {}
    for path in paths:
        with open(path) as f:
            texts[path] = f.read()
    # Every table in exactly one block, every block a known table.
    where = {}
    for path, text in texts.items():
        for m in BLOCK.finditer(text):
            name = m.group(1)
            if name not in SECTIONS:
                sys.exit(f"figures.py: {path} has a block for an unknown table '{name}'")
            if name in where:
                sys.exit(f"figures.py: table '{name}' is in two blocks ({where[name]} and {path})")
            where[name] = path
        opened = set(re.findall(r"^<!-- figures:([A-Za-z0-9_-]+) -->$", text, re.M))
        for name in opened - {m.group(1) for m in BLOCK.finditer(text)}:
            sys.exit(f"figures.py: {path}: <!-- figures:{name} --> has no matching <!-- /figures:{name} -->")
    lost = sorted(set(SECTIONS) - set(where))
    if lost:
        sys.exit(f"figures.py: no <!-- figures:NAME --> ... <!-- /figures:NAME --> block for "
                 f"{', '.join(lost)} in {', '.join(paths)}")
    made, kept = [], []

    def regenerate(m):
        global _old
        name, _old = m.group(1), m.group(2)
        try:
            body = SECTIONS[name]()
            made.append(name)
        except Absent as e:
            kept.append(name)
            body = _old.strip("\n") or str(e)   # an empty block says how to fill it
        return f"<!-- figures:{name} -->\n{body}\n<!-- /figures:{name} -->"

    for path, text in texts.items():
        new = BLOCK.sub(regenerate, text)
        if new != text:
            with open(path, "w") as f:
                f.write(new)
    print(f"figures: {len(made)} tables regenerated from {REPORTS}/"
          + (f", {len(kept)} kept as they were (report absent: {', '.join(kept)})" if kept else "")
          + f" in {', '.join(sorted(set(where.values())))}")


if __name__ == "__main__":
    main()
