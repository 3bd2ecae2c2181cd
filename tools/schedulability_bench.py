#!/usr/bin/env python3
"""schedulability_bench.py -- which generated systems each planner accepts,
per bus demand (docs/compiler.md "Schedulability").

    schedulability_bench.py run [--systems N] [--levels 5,10,...] [--planners single-rate,exact-grid]
                                [--time-limit S] [--jobs J] [--out FILE.json] [--svg FILE.svg]
    schedulability_bench.py --case SEED [-o FILE.toml]    the description of one system
    schedulability_bench.py --smoke                        the cheap self-test (make test)

The systems.  Each is a real system description (the dict that the
compiler's parse_description takes, and the TOML file --case writes), made
from its seed alone: seed = demand target in percent * 10000 + a counter.
50 MHz, 2 .. 16 boards with 16 KB of RAM each (the most the ROM's base
fields address), 4 .. 64 copy channels (log-uniform), each with a producer
and 1 .. 4 consumers, a period log-uniform over three decades (50 us to
50 ms) and a value log-uniform from 4 bytes to 2 KB.  The demand of a system
is the sum over its channels of the compiler's own slot length (one
transfer, as plan.slot_length computes it: fetch, the fault-free accesses,
the [bus] retry budget, guard) divided by its period.  The sizes are scaled
together (each kept within 4 bytes .. 2 KB) to reach the target to within
half a percentage point.  When even 4-byte values exceed it, the periods are
stretched together (the span stays three decades, beyond 50 ms); when 2 KB
values fall short, they are shrunk together, down to a shortest period of
50 us.  When even that is not enough, or the sizes miss the target, the
system is drawn again with the next seed, and so is a system whose channels
overflow a board's RAM.  The report counts each kind of redraw and keeps
their seeds.

The planners (PLANNERS: a new one plugs in by name):
  single-rate   today's compiler, compile_system with one slot per channel
                (albatross-schedule --no-redundancy), in process; a rejection
                is its ScheduleError
  exact-grid    compiler/albatross_schedule/exact.py: CP-SAT on the plain
                power-of-two grid, within --time-limit seconds per system:
                accepted (a placement), rejected (a proof) or unknown
  multi-rate    the compiler as it is (--no-redundancy): the single-rate plan
                when it fits, else compiler/albatross_schedule/multirate.py;
                a rejection's reason: demand or exact (proofs) or gave-up
Each system's outcome, reason and time (process CPU seconds) per planner go
to the JSON report with its seed; per demand level the counts and the time
statistics; the console table and an SVG picture of the acceptance ratio.
The run fails if the single-rate compiler accepts a system that the exact
search proves impossible (its plan is a placement on the grid), or if a
planner has an internal error."""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

from albatross_schedule import ScheduleError, compile_system, load_description, parse_description
from albatross_schedule.description import MAX_RAM_BYTES
from schedulability_gen import (BOARDS, CHANNELS, CLOCK_HZ, PERIOD_US, SEED_STRIDE, SIZE_BYTES, TOLERANCE, Redraw,
                                draw_level, generate, system_demand, toml_text)

LEVELS = (5, 10, 20, 30, 40, 50, 60, 70, 80, 90)
DEFAULT_SYSTEMS = 100
DEFAULT_TIME_LIMIT = 5.0        # CP-SAT's deterministic time (about seconds) per system


# ---------------------------------------------------------------------------
# The planners: each takes the description dict and the options and returns
# {"outcome": accepted | rejected | unknown | error, "seconds": CPU s, "reason": ...}.

def _first_line(msg: str) -> str:
    return msg.split("\n")[0][:400]


def plan_single_rate(data, opts) -> dict:
    system = parse_description(json.loads(json.dumps(data)), f"<seed {data['system']['name']}>")
    system.planner = "single-rate"      # the single-rate plan alone (the compiler turns multi-rate when it fails)
    for ch in system.channels:          # albatross-schedule --no-redundancy
        ch.max_slots = 1
    t0 = time.process_time()
    try:
        system, plan, rom, rep = compile_system(system)
    except ScheduleError as e:
        msg = e.messages[0]
        kind = ("cycle over the time field" if "does not fit time_bits" in msg else
                "slots exceed the cycle" if "infeasible plan" in msg else "other")
        return {"outcome": "rejected", "seconds": round(time.process_time() - t0, 4), "reason": kind,
                "detail": _first_line(msg.split(": ", 1)[-1])}
    except AssertionError as e:
        return {"outcome": "error", "seconds": round(time.process_time() - t0, 4), "reason": "internal error",
                "detail": _first_line(str(e))}
    return {"outcome": "accepted", "seconds": round(time.process_time() - t0, 4), "reason": "plan",
            "detail": f"cycle {plan.cycle} clocks, {len(plan.slots)} entries, slots fill "
                      f"{sum(s.length for s in plan.slots) / plan.cycle:.3f}"}


def plan_exact_grid(data, opts) -> dict:
    from albatross_schedule.exact import FEASIBLE, INFEASIBLE, exact_grid
    system = parse_description(json.loads(json.dumps(data)), f"<seed {data['system']['name']}>")
    t0 = time.process_time()
    try:
        r = exact_grid(system, time_limit=opts.time_limit, workers=1)
    except AssertionError as e:
        return {"outcome": "error", "seconds": round(time.process_time() - t0, 4), "reason": "internal error",
                "detail": _first_line(str(e))}
    outcome = {FEASIBLE: "accepted", INFEASIBLE: "rejected"}.get(r.status, "unknown")
    last = r.placement or (r.tries[-1] if r.tries else None)
    reason = ("placement" if outcome == "accepted" else
              "/".join(sorted({t.reason for t in r.tries})) if r.tries else "no minor cycle")
    out = {"outcome": outcome, "seconds": round(time.process_time() - t0, 4), "wall_s": round(r.seconds, 3),
           "work": round(sum(t.work for t in r.tries), 3), "reason": reason, "detail": _first_line(r.reason()),
           "proof": r.tries[0].reason if r.tries and outcome == "rejected" else None}
    if last is not None:
        out["minor_clocks"] = last.minor
        out["cluster"] = max(last.reps)
    return out


def plan_multi_rate(data, opts) -> dict:
    """The compiler as it is, --no-redundancy: the single-rate plan when it
    fits, else the multi-rate planner (albatross_schedule/multirate.py); a
    rejection's reason is its kind: demand (a proof), exact (a proof on the
    grid at the best minor cycles) or gave-up (no proof)."""
    system = parse_description(json.loads(json.dumps(data)), f"<seed {data['system']['name']}>")
    for ch in system.channels:
        ch.max_slots = 1
    t0 = time.process_time()
    try:
        system, plan, rom, rep = compile_system(system)
    except ScheduleError as e:
        return {"outcome": "rejected", "seconds": round(time.process_time() - t0, 4),
                "reason": getattr(e, "kind", None) or "other", "detail": _first_line(e.messages[-1])}
    except AssertionError as e:         # the self-check or verify_rom refused the plan
        return {"outcome": "error", "seconds": round(time.process_time() - t0, 4), "reason": "internal error",
                "detail": _first_line(str(e))}
    frag = sum(1 for ch in system.channels if ch.fragments > 1)
    return {"outcome": "accepted", "seconds": round(time.process_time() - t0, 4),
            "reason": "multi-rate" if plan.multirate else "single-rate",
            "detail": f"minor cycle {plan.cycle} clocks, cluster {plan.cluster}, {len(plan.slots)} entries, "
                      f"{frag} channels in fragments"}


PLANNERS = {"single-rate": plan_single_rate, "exact-grid": plan_exact_grid, "multi-rate": plan_multi_rate}
# The planners' names in the table and the picture; a planner yet to come
# keeps its place in the picture's legend.
TITLES = {"single-rate": "single-rate (today's compiler)", "exact-grid": "exact search, plain grid (CP-SAT)",
          "multi-rate": "multi-rate planner"}
COLOURS = {"single-rate": "#c0392b", "exact-grid": "#2c3e50", "multi-rate": "#27ae60"}


def run_system(job):
    data, facts, names, opts = job
    outcomes = {}
    for name in names:
        outcomes[name] = PLANNERS[name](data, opts)
    return dict(facts, outcomes=outcomes)


def consistency(systems) -> list:
    """Contradictions between the planners (each a bug of one of them): the
    single-rate plan is a placement on the grid of the shortest period, so
    the exact search cannot prove a system impossible that it accepts; and no
    system above 100 % demand fits."""
    problems = []
    for s in systems:
        o = s["outcomes"]
        sr, ex = o.get("single-rate"), o.get("exact-grid")
        if sr and ex and sr["outcome"] == "accepted" and ex["outcome"] == "rejected":
            problems.append(f"seed {s['seed']}: single-rate accepts it but the exact search proves it "
                            f"impossible ({ex['detail']})")
        mr = o.get("multi-rate")
        if mr and mr["outcome"] == "rejected" and s["demand"] < 1.0 and mr["reason"] not in ("demand", "exact",
                                                                                             "gave-up"):
            problems.append(f"seed {s['seed']}: multi-rate rejects it without a stated reason ({mr['detail']})")
        if mr and sr and sr["outcome"] == "accepted" and mr["outcome"] != "accepted":
            problems.append(f"seed {s['seed']}: the single-rate plan fits but the compiler rejects it")
        for name, r in o.items():
            if r["outcome"] == "error":
                problems.append(f"seed {s['seed']}: {name}: {r['detail']}")
            if s["demand"] > 1.0 and r["outcome"] == "accepted":
                problems.append(f"seed {s['seed']}: {name} accepts a demand of {s['demand']:.3f}")
    return problems


def stats(values) -> dict:
    if not values:
        return {}
    return {"median": round(statistics.median(values), 4), "mean": round(statistics.fmean(values), 4),
            "max": round(max(values), 4)}


def summarise(systems, levels, names, redraws) -> list:
    rows = []
    for lv in levels:
        ss = [s for s in systems if s["target_pct"] == lv]
        row = {"demand_pct": lv, "systems": len(ss),
               "demand_range": [min(s["demand"] for s in ss), max(s["demand"] for s in ss)] if ss else [],
               "redraws": {k: len(v) for k, v in redraws[lv].items()},
               "redraw_seeds": redraws[lv]}
        for name in names:
            outs = [s["outcomes"][name] for s in ss]
            row[name] = {k: sum(1 for o in outs if o["outcome"] == k)
                         for k in ("accepted", "rejected", "unknown", "error")}
            row[name]["ratio"] = round(row[name]["accepted"] / len(ss), 4) if ss else None
            # why the rejected ones were: the compiler's error, or the exact
            # search's proof on its first minor cycle
            why = {}
            for o in outs:
                if o["outcome"] == "rejected":
                    k = o.get("proof") or o["reason"]
                    why[k] = why.get(k, 0) + 1
            row[name]["rejected_why"] = why
            row[name]["seconds"] = stats([o["seconds"] for o in outs])
            big = [o["seconds"] for s, o in zip(ss, outs) if s["channels"] >= 48]
            row[name]["seconds_48_channels_up"] = stats(big)
        rows.append(row)
    return rows


def console_table(rows, names) -> str:
    head = ["demand %", "systems"] + [f"{n} acc" for n in names]
    if "exact-grid" in names:
        head.append("exact unknown")
    head += [f"{n} s med/max" for n in names] + ["redrawn (RAM)"]
    out = ["  ".join(f"{h:>14}" for h in head)]
    for r in rows:
        cells = [str(r["demand_pct"]), str(r["systems"])]
        cells += [f"{r[n]['accepted']}/{r['systems']}" for n in names]
        if "exact-grid" in names:
            cells.append(str(r["exact-grid"]["unknown"]))
        cells += [f"{r[n]['seconds'].get('median', 0):.2f}/{r[n]['seconds'].get('max', 0):.2f}" for n in names]
        cells.append(f"{sum(r['redraws'].values())} ({r['redraws']['ram-overflow']})")
        out.append("  ".join(f"{c:>14}" for c in cells))
    return "\n".join(out)


def render_svg(rows, names) -> str:
    """Acceptance ratio against demand, one line per planner; the exact
    search's unknown systems as a band above its line (what it might still
    accept); a planner named in TITLES but not measured is listed in the
    legend as not measured yet."""
    W, H, L, R, T, B = 640, 400, 60, 230, 40, 50
    pw, ph = W - L - R, H - T - B

    def x(d):
        return L + pw * d / 100.0

    def y(v):
        return T + ph * (1 - v)
    e = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" '
         'font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{L}" y="22" font-size="14">Systems accepted per bus demand</text>']
    for v in (0, 0.25, 0.5, 0.75, 1.0):
        e.append(f'<line x1="{L}" y1="{y(v):.1f}" x2="{L + pw}" y2="{y(v):.1f}" stroke="#ddd"/>')
        e.append(f'<text x="{L - 6}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
    for d in range(0, 101, 10):
        e.append(f'<line x1="{x(d):.1f}" y1="{T + ph}" x2="{x(d):.1f}" y2="{T + ph + 4}" stroke="black"/>')
        e.append(f'<text x="{x(d):.1f}" y="{T + ph + 18}" text-anchor="middle">{d}</text>')
    e.append(f'<rect x="{L}" y="{T}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    e.append(f'<text x="{L + pw / 2}" y="{H - 10}" text-anchor="middle">demand (% of the bus: sum of slot '
             'length / period)</text>')
    e.append(f'<text x="16" y="{T + ph / 2}" text-anchor="middle" transform="rotate(-90 16 {T + ph / 2})">'
             'acceptance ratio</text>')
    rows = [r for r in rows if r["systems"]]
    if "exact-grid" in names and rows:
        up = [(r["demand_pct"], (r["exact-grid"]["accepted"] + r["exact-grid"]["unknown"]) / r["systems"])
              for r in rows]
        lo = [(r["demand_pct"], r["exact-grid"]["ratio"]) for r in rows]
        pts = " ".join(f"{x(d):.1f},{y(v):.1f}" for d, v in up + lo[::-1])
        e.append(f'<polygon points="{pts}" fill="{COLOURS["exact-grid"]}" fill-opacity="0.15" stroke="none"/>')
    for name in names:
        col = COLOURS.get(name, "#7f8c8d")
        pts = [(x(r["demand_pct"]), y(r[name]["ratio"])) for r in rows]
        e.append(f'<polyline points="{" ".join(f"{a:.1f},{b:.1f}" for a, b in pts)}" fill="none" '
                 f'stroke="{col}" stroke-width="2"/>')
        e += [f'<circle cx="{a:.1f}" cy="{b:.1f}" r="3" fill="{col}"/>' for a, b in pts]
    ly = T + 10
    legend = list(names) + [n for n in TITLES if n not in names]
    for name in legend:
        col = COLOURS.get(name, "#7f8c8d")
        measured = name in names
        dash = "" if measured else ' stroke-dasharray="4 3"'
        e.append(f'<line x1="{L + pw + 12}" y1="{ly}" x2="{L + pw + 36}" y2="{ly}" stroke="{col}" '
                 f'stroke-width="2"{dash}/>')
        words, line = TITLES.get(name, name).split(), ""
        parts = []
        for w in words:
            if len(line) + len(w) > 24 and line:
                parts.append(line)
                line = w
            else:
                line = f"{line} {w}".strip()
        parts.append(line)
        if not measured:
            parts.append("(not measured yet)")
        for k, p in enumerate(parts):
            e.append(f'<text x="{L + pw + 42}" y="{ly + 4 + 14 * k}">{p}</text>')
        ly += 14 * len(parts) + 10
    if "exact-grid" in names:
        e.append(f'<rect x="{L + pw + 12}" y="{ly - 6}" width="24" height="10" fill="{COLOURS["exact-grid"]}" '
                 'fill-opacity="0.15"/>')
        e.append(f'<text x="{L + pw + 42}" y="{ly + 4}">exact search: time limit</text>')
        e.append(f'<text x="{L + pw + 42}" y="{ly + 18}">(no answer)</text>')
    e.append("</svg>")
    return "\n".join(e) + "\n"


def run(opts) -> int:
    names = opts.planners
    for n in names:
        if n not in PLANNERS:
            raise SystemExit(f"schedulability: unknown planner '{n}' (known: {', '.join(PLANNERS)})")
    if "exact-grid" in names:
        from albatross_schedule.exact import SolverMissing, _cp_model
        try:
            _cp_model()
        except SolverMissing as e:
            raise SystemExit(f"schedulability: {e}")
    t0 = time.monotonic()
    load = os.getloadavg()[0]
    jobs, redraws = [], {}
    for lv in opts.levels:
        drawn, redraws[lv] = draw_level(lv, opts.systems)
        jobs += [(data, facts, names, opts) for data, facts in drawn]
    if opts.jobs > 1:
        import multiprocessing
        with multiprocessing.Pool(opts.jobs) as pool:
            systems = list(pool.imap(run_system, jobs))
    else:
        systems = [run_system(j) for j in jobs]
    rows = summarise(systems, opts.levels, names, redraws)
    problems = consistency(systems)
    report = {"generator": "tools/schedulability_bench.py", "clock_hz": CLOCK_HZ, "planners": names,
              "levels_pct": list(opts.levels), "systems_per_level": opts.systems,
              "time_limit_s": opts.time_limit, "jobs": opts.jobs, "cpus": os.cpu_count(),
              "load_average_1min_at_start": round(load, 2), "wall_s": round(time.monotonic() - t0, 1),
              "generator_ranges": {"boards": BOARDS, "channels": CHANNELS, "period_us": PERIOD_US,
                                   "value_bytes": SIZE_BYTES, "ram_bytes": MAX_RAM_BYTES,
                                   "tolerance": TOLERANCE, "seed_stride": SEED_STRIDE},
              "levels": rows, "problems": problems, "systems": systems}
    print(console_table(rows, names))
    if opts.out:
        os.makedirs(os.path.dirname(opts.out) or ".", exist_ok=True)
        with open(opts.out, "w") as f:
            json.dump(report, f, indent=1)
        print(f"schedulability: {opts.out}")
    if opts.svg:
        with open(opts.svg, "w") as f:
            f.write(render_svg(rows, names))
        print(f"schedulability: {opts.svg}")
    print(f"schedulability: {len(systems)} systems in {report['wall_s']} s")
    for p in problems:
        print(f"schedulability: FAIL: {p}")
    return 1 if problems else 0


def write_case(seed: int, path) -> int:
    try:
        data, facts = generate(seed)
    except Redraw as r:
        print(f"schedulability: seed {seed} gives no system ({r.kind}: {r}); the benchmark drew the next seed")
        return 1
    path = path or f"sched_{seed}.toml"
    text = toml_text(data, f"tools/schedulability_bench.py --case {seed}: demand {facts['demand']:.4f} "
                           f"(target {facts['target_pct']} %), {facts['boards']} boards, "
                           f"{facts['channels']} channels\ntoday's compiler: albatross-schedule {path} -o DIR "
                           "--no-redundancy")
    with open(path, "w") as f:
        f.write(text)
    print(f"schedulability: seed {seed}: demand {facts['demand']:.4f}, {facts['boards']} boards, "
          f"{facts['channels']} channels -> {path}")
    return 0


# ---------------------------------------------------------------------------
# The self-test (make test-schedulability-smoke).

def hand_feasible() -> dict:
    """An 8-byte channel at 50 us beside ten 256-byte channels at 10 ms (3 %
    of the bus): the single-rate plan needs 52 + 10 * 304 clocks in a cycle
    of 2,500; on the grid each slow channel runs once in 128 minor cycles."""
    chans = [{"name": "fast", "size": 8, "producer": "a", "consumers": ["b"], "max_period_us": 50}]
    chans += [{"name": f"slow{i}", "size": 256, "producer": "a", "consumers": ["b"], "max_period_us": 10_000}
              for i in range(10)]
    return {"system": {"name": "hand_feasible", "clock_hz": CLOCK_HZ, "boards": ["a", "b"],
                       "ram_bytes": MAX_RAM_BYTES}, "bus": {}, "channel": chans}


def hand_infeasible() -> dict:
    """A 4-byte channel at 100 us and three 1,700-byte channels to two
    consumers at 200 us (79 % of the bus): the big ones run every second
    minor cycle, two of them in the same ones, and two of their 2,604-clock
    slots do not fit in 5,000 clocks.  The average load fits (no quick
    proof): the search must prove it."""
    chans = [{"name": "tick", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 100}]
    chans += [{"name": f"big{i}", "size": 1700, "producer": ["a", "b", "c"][i],
               "consumers": [x for x in "abcd" if x != "abc"[i]][:2], "max_period_us": 200} for i in range(3)]
    return {"system": {"name": "hand_infeasible", "clock_hz": CLOCK_HZ, "boards": ["a", "b", "c", "d"],
                       "ram_bytes": MAX_RAM_BYTES}, "bus": {}, "channel": chans}


def smoke() -> int:
    from albatross_schedule.exact import FEASIBLE, INFEASIBLE, exact_grid
    fails = []

    def check(ok, what):
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            fails.append(what)

    class Opts:
        time_limit = 20.0
    # 1. the hand-made feasible system: the exact search places it, today's compiler cannot.
    data = hand_feasible()
    sys_ = parse_description(json.loads(json.dumps(data)), "<hand_feasible>")
    r = exact_grid(sys_, time_limit=20.0)
    check(r.status == FEASIBLE and r.minor == 2500,
          f"hand-made feasible system (demand {system_demand(sys_):.3f}): exact search {r.status} at minor "
          f"cycle {r.minor} (expected feasible at 2500): {r.reason()}")
    sr = plan_single_rate(data, Opts)
    check(sr["outcome"] == "rejected" and sr["reason"] == "slots exceed the cycle",
          f"hand-made feasible system: single-rate {sr['outcome']} ({sr['reason']}), expected rejected "
          "(slots exceed the cycle)")
    mr = plan_multi_rate(data, Opts)
    check(mr["outcome"] == "accepted" and mr["reason"] == "multi-rate",
          f"hand-made feasible system: the compiler {mr['outcome']} ({mr['reason']}: {mr['detail']}), expected "
          "accepted by the multi-rate planner")
    # 2. the hand-made infeasible one: a proof by search, not by the load bound.
    data = hand_infeasible()
    sys_ = parse_description(json.loads(json.dumps(data)), "<hand_infeasible>")
    r = exact_grid(sys_, time_limit=20.0)
    first = r.tries[0] if r.tries else None
    d = system_demand(sys_)
    check(r.status == INFEASIBLE and first is not None and first.reason == "search" and d < 1,
          f"hand-made infeasible system (demand {d:.3f}): exact search {r.status}, first minor cycle's proof "
          f"'{first.reason if first else None}' (expected infeasible, proved by the search): {r.reason()}")
    # 3. the generator: its targets, ranges, reproducibility and the TOML file.
    with tempfile.TemporaryDirectory() as tmp:
        for lv in (5, 50, 90):
            drawn, redraws = draw_level(lv, 2)
            for data, facts in drawn:
                seed = facts["seed"]
                ch = data["channel"]
                path = os.path.join(tmp, f"{seed}.toml")
                with open(path, "w") as f:
                    f.write(toml_text(data, "smoke"))
                loaded = load_description(path)
                again = generate(seed)[0]
                in_range = (BOARDS[0] <= facts["boards"] <= BOARDS[1] and CHANNELS[0] <= len(ch) <= CHANNELS[1]
                            and all(SIZE_BYTES[0] <= c["size"] <= SIZE_BYTES[1] for c in ch)
                            and all(c["max_period_us"] >= PERIOD_US[0] for c in ch))
                check(abs(system_demand(loaded) - lv / 100) <= TOLERANCE and in_range and again == data,
                      f"seed {seed}: demand {system_demand(loaded):.4f} from its TOML file (target {lv / 100}, "
                      f"within {TOLERANCE}), {facts['boards']} boards, {len(ch)} channels, values "
                      f"{facts['value_bytes']} B, periods {facts['period_us']} us, the same system again: "
                      f"{again == data} (redrawn before it: {sum(len(v) for v in redraws.values())})")
        # 4. a run of both planners on one system per level, with its report and picture.
        class RunOpts:
            levels = [10, 70]
            systems = 1
            planners = ["single-rate", "exact-grid"]
            time_limit = 3.0
            jobs = 1
            out = os.path.join(tmp, "s.json")
            svg = os.path.join(tmp, "s.svg")
        rc = run(RunOpts)
        with open(RunOpts.out) as f:
            rep = json.load(f)
        with open(RunOpts.svg) as f:
            svg = f.read()
        check(rc == 0 and [r["demand_pct"] for r in rep["levels"]] == [10, 70] and len(rep["systems"]) == 2
              and all(set(s["outcomes"]) == {"single-rate", "exact-grid"} for s in rep["systems"])
              and svg.count("<polyline") == 2 and "not measured yet" in svg,
              f"a run of 2 systems: exit {rc}, levels {[r['demand_pct'] for r in rep['levels']]}, "
              f"{len(rep['systems'])} systems with both outcomes, the picture's lines {svg.count('<polyline')} "
              "and the multi-rate planner's place in its legend")
    # 5. negative: the consistency check catches a single-rate plan that the exact search calls impossible.
    fake = [{"seed": 1, "demand": 0.5, "outcomes": {"single-rate": {"outcome": "accepted"},
                                                      "exact-grid": {"outcome": "rejected", "detail": "x"}}}]
    check(len(consistency(fake)) == 1, "the consistency check catches a single-rate plan the exact search "
          f"proves impossible: {consistency(fake)}")
    print(f"schedulability smoke: {'FAIL' if fails else 'PASS'} ({len(fails)} failed)")
    return 1 if fails else 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="schedulability_bench.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("command", nargs="?", choices=["run"], help="run the benchmark")
    ap.add_argument("--case", type=int, metavar="SEED", help="write the description of this seed's system")
    ap.add_argument("-o", "--output", metavar="FILE.toml", help="with --case: the file (default sched_SEED.toml)")
    ap.add_argument("--smoke", action="store_true", help="the cheap self-test")
    ap.add_argument("--systems", type=int, default=int(os.environ.get("SCHED_SYSTEMS") or DEFAULT_SYSTEMS),
                    help=f"systems per demand level (default SCHED_SYSTEMS or {DEFAULT_SYSTEMS})")
    ap.add_argument("--levels", default=",".join(map(str, LEVELS)), help="demand targets in percent")
    ap.add_argument("--planners", default="single-rate,multi-rate,exact-grid", help=f"of {', '.join(PLANNERS)}")
    ap.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT,
                    help=f"the exact search's seconds per system (default {DEFAULT_TIME_LIMIT:g})")
    ap.add_argument("--jobs", type=int, default=2, help="systems planned side by side (default 2)")
    ap.add_argument("--out", default="build/reports/schedulability.json")
    ap.add_argument("--svg", default="build/reports/schedulability.svg")
    a = ap.parse_args(argv)
    if a.smoke:
        return smoke()
    if a.case is not None:
        return write_case(a.case, a.output)
    if a.command != "run":
        ap.error("name a command: run, --case SEED or --smoke")
    try:
        a.levels = [int(x) for x in a.levels.split(",") if x.strip()]
    except ValueError:
        ap.error(f"--levels {a.levels!r}: expected percentages, for example 5,10,20")
    if not a.levels or any(not 1 <= lv <= 999 for lv in a.levels):
        ap.error(f"--levels {a.levels}: each in 1..999")
    if a.systems < 1:
        ap.error("--systems: at least 1")
    a.planners = [p.strip() for p in a.planners.split(",") if p.strip()]
    return run(a)


if __name__ == "__main__":
    sys.exit(main())
