"""figures_integration.py -- the figure tables of faults, channel kinds, cores
and hosts (tools/figures.py): the compiler's fault plan, the fault rates
measured against it, the SymbiYosys proofs, the kinds' cost, VexRiscv's cost
and tests, the make sim excerpt, the schedule modes' switches, the driver on
host threads.  SECTIONS maps
each block name to the function that makes its table."""
import os
import re
import subprocess
import sys

from figures_common import Absent, load, missing, old_rows, old_text, table, n
from suite_report import TARGET   # suite name -> its make target


SECTIONS = {}


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


SIM_LOG = "build/docs/sim.log"   # make sim with its defaults, as make test-docs-pictures runs it


def sim_excerpt():
    """The head of `make sim`'s console report, copied from the log of a real run
    (SIM_LOG, written by make test-docs-pictures or make docs-pictures): the run's
    line, the fault rate, the modes' verdict, the table's head and its first four
    rows (each with its line of ages not judged, if any), the slow channels'
    lines (their worst age against the bound), and the verdict; "..."
    where lines are left out.  make test-docs-pictures checks each line against a
    fresh run (tools/doc_facts.py --sim-log)."""
    try:
        with open(SIM_LOG) as f:
            lines = [ln.rstrip("\n") for ln in f if ln.strip()]
    except OSError:
        raise Absent(f"_Not measured yet: `make test-docs-pictures` writes `{SIM_LOG}`._")
    start = next((k for k, ln in enumerate(lines) if ln.startswith("sim: ") and " cycles (" in ln), None)
    head = next((k for k, ln in enumerate(lines) if ln.split()[:3] == ["channel", "consumer", "New"]), None)
    if start is None or head is None or head < start:
        raise Absent(f"_{SIM_LOG} holds no make sim report: `make test-docs-pictures` writes it._")
    out, rows, k = lines[start:start + 2], 0, head + 1
    between = [ln for ln in lines[start + 2:head] if ln.startswith("  modes: worst")]
    if len(between) < len(lines[start + 2:head]):
        out.append("  ...")
    out += between + [lines[head]]
    while k < len(lines) and rows < 4:
        out.append(lines[k])
        if lines[k].startswith("  ") and not lines[k].startswith("   "):
            rows += 1
        k += 1
    while k < len(lines) and lines[k].startswith("   "):   # the last row's own line of ages not judged
        out.append(lines[k])
        k += 1
    slow = [ln for ln in lines[k:] if ln.startswith("  slow channel ")]   # each slow channel's worst age and bound
    out += (["  ..."] + slow if slow else []) + ["  ...", lines[-1]]
    return "\n".join(["```"] + out + ["```"])


SECTIONS["sim-excerpt"] = sim_excerpt


def mode_switches():
    """Switch latency against the compiler's bounds in the tests with schedule
    modes (make test: the robot's and the system test's runs)."""
    runs = [("pico_boards_modes", "robot, fault-free"), ("pico_boards_modes_faults", "robot, 5 % faults"),
            ("system_modes", "system test, fault-free"),
            ("system_modes-faults-20-planned", "system test, 20 % faults (image planned for 20 %)")]
    rows = []
    for name, what in runs:
        r = load(name + ".json")
        if not r:
            rows.append([what, f"_not measured yet: `make test` writes `{name}.json`_"] + [""] * 5)
            continue
        m = r.get("modes") or {}
        sw = m.get("switches") or r.get("mode_switches") or []
        worst = max(sw, key=lambda s: s["latency"] / max(1, s["bound"]), default=None)
        at_target = max((s.get("bound_at_target", 0) for s in sw), default=0)
        verdict = r.get("verdict") or ("pass" if not r.get("violations_total") and not r.get("scenario_failures")
                                       else "fail")
        rows.append([what, len(sw), n(worst["latency"]) if worst else "-", n(worst["bound"]) if worst else "-",
                     n(at_target) if at_target else "-", n(m["judged_across_a_switch"]) if "judged_across_a_switch"
                     in m else "-", verdict])
    return table(["run", "switches", "worst latency (clocks)", "its bound", "largest bound at the target",
                  "values judged across a switch", "verdict"], rows)


SECTIONS["mode-switches"] = mode_switches


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
    """Each fence site of albatross.c dropped alone: what the store-buffer model
    requires and shows (make test-host-threads-model), and how often the
    fence-less builds tore on silicon, per CPU (make test-host-threads-silicon)."""
    r = load("host_threads.json")
    if not r or "model" not in r:
        missing("host_threads.json", "make test-host-threads-model")
    seen = r.get("observed", {})
    cpus = sorted(seen)

    def shown(m):
        if not m:
            return "-"
        return f"{'must fail' if m['must_fail'] else 'must pass'}: {m['shows']} ({n(m['run']['imports'])} Imports)"

    def silicon(row):
        out = []
        for cpu in cpus:
            for name, v in seen[cpu].items():
                if name.startswith(f"line {row['line']} (") or name.startswith(f"lines {row['line']} ("):
                    out.append(f"{v['tore']} of {v['runs']}")
        return "; ".join(out) or "-"
    rows = []
    for s in r["model"]["sites"]:
        m = s.get("model", {})
        rows.append([s["line"], f"`{s['function']}`", s["comment"] or "-", s["order"],
                     shown(m.get("tso")), shown(m.get("pso")), silicon(s)])
    m = r["model"]
    return (f"Model: seed {m['seed']}; a run that must fail stops at its {m['stop_after']}th violation; "
            f"the latest first violation of those came at Import {n(m['latest_first_violation'])}. "
            f"Silicon: runs that tore, of those made"
            + (f", on {', '.join(cpus)}" if cpus else "") + ".\n\n"
            + table(["line", "function", "the fence orders", "order", "model, tso", "model, pso",
                     "silicon: tore"], rows))


SECTIONS["host-threads-sites"] = host_threads_sites


def host_threads_observed():
    """Silicon, observed: how often each fence-less build tore, per CPU model
    (make test-host-threads-silicon; counts add up over the runs kept in the report)."""
    r = load("host_threads.json")
    if not r or "observed" not in r:
        missing("host_threads.json", "make test-host-threads-silicon")
    rows = []
    for cpu in sorted(r["observed"]):
        for name, v in r["observed"][cpu].items():
            rows.append([cpu, name.rsplit(", ", 1)[0], v["kind"], f"{v['tore']} of {v['runs']}", n(v["imports"]), n(v["violations"])])
    return table(["CPU", "fence left out", "kind", "runs that tore", "Imports in all", "violations in all"], rows)


SECTIONS["host-threads-observed"] = host_threads_observed


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


def current_test_count(suite):
    """How many tests the suite has now (make list-tests / list-slow-tests), or None."""
    target = {"test": "list-tests", "slow": "list-slow-tests"}.get(suite)
    if not target:
        return None
    try:
        out = subprocess.run(["make", "-s", "--no-print-directory", target], capture_output=True, text=True,
                             timeout=120, env={k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS")})
    except (OSError, subprocess.SubprocessError):
        return None
    return len(out.stdout.split()) if out.returncode == 0 else None


def suite_rows(names):
    """The rows of suite_NAME.json for each name; a row whose report is absent is
    kept from the old table (by its suite and its note), a suite that has more
    or fewer tests now than the run had says so (and make figures warns)."""
    rows, cpu = [], None
    for name in names:
        r = load(f"suite_{name}.json")
        label = f"`make {TARGET.get(name.split('_')[0], name.split('_')[0])}`"
        if not r:
            busy = name.endswith("_hogs")
            for c in old_rows(label):
                if ("(" in c[5]) != busy:
                    continue
                now = current_test_count(name.split("_")[0])
                if c[1].isdigit() and now is not None and now != int(c[1]):
                    c[1] += f" (the suite has {now} now)"
                rows.append(c)
            continue
        cpu = cpu or r["cpu"]
        tests = str(r["tests"])
        now = current_test_count(r["suite"])
        if now is not None and now != r["tests"]:
            tests += f" (the suite has {now} now)"
            print(f"figures: suite_{name}.json ran {r['tests']} tests, make {TARGET.get(r['suite'], r['suite'])} "
                  f"has {now} now: run it again for current figures", file=sys.stderr)
        rows.append([label, tests, f"{r['passed']} passed", f"{r['wall_s'] / 60:.1f} min",
                     f"{r['jobs']}", f"{r['loadavg_end'][0]:.1f}" + (f" ({r['busy']})" if r.get("busy") else ""),
                     f"{r['cpu_sum_s'] / 60:.1f} min", f"{r['idle_estimate_s'] / 60:.1f} min", r["date"]])
    return rows, cpu


SUITE_HEAD = ["suite", "tests", "verdicts", "wall time", "jobs", "load average", "CPU time", "CPU time / cores", "run"]


def suite_times():
    """How long make check, make test and make test-slow take on a machine with
    nothing else of ours running (build/reports/suite_*.json, tools/suite_report.py)."""
    rows, cpu = suite_rows(("check", "test", "slow"))
    if not rows:
        missing("suite_test.json", "make test")
    cpu = cpu or next(iter(re.findall(r"Measured on (.+?), \d+ cores", old_text())), None)
    return ((f"Measured on {cpu}, " if cpu else "") + f"{load_cores()} cores, shared with other jobs. The load "
            "average counts every job on the machine at the end of the run; the CPU time is what the tests and "
            "builds used, so CPU time / cores is what the suite needs on an idle machine.\n\n"
            + table(SUITE_HEAD, rows))


def suite_times_busy():
    """The same suites run beside busy loops (ALB_SUITE_TAG=hogs: suite_*_hogs.json):
    how much a loaded machine stretches them."""
    rows, cpu = suite_rows(("check_hogs", "test_hogs"))
    if not rows:
        missing("suite_test_hogs.json", "ALB_SUITE_TAG=hogs make test")
    cpu = cpu or next(iter(re.findall(r"Measured on (.+?)\. ", old_text())), None)
    return ((f"Measured on {cpu}. " if cpu else "") + "The load average counts every job on the machine at the end "
            "of the run, the busy loops included.\n\n" + table(SUITE_HEAD, rows))


SECTIONS["suite-times-busy"] = suite_times_busy


def load_cores():
    for name in ("test", "check", "slow"):
        r = load(f"suite_{name}.json")
        if r and r.get("cores"):
            return r["cores"]
    return os.cpu_count() or 2


SECTIONS["suite-times"] = suite_times
