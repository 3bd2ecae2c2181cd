#!/usr/bin/env python3
"""suite_report.py --order NAME TEST... -- the tests, the costliest first
(by the last report), for make test to start them in that order.

suite_report.py NAME T0_NS JOBS TEST... -- the times of a suite run (make
test, make check, make formal) into build/reports/suite_NAME.json: its wall
time, the jobs, each test's run (build/results/TEST.ms, by tools/run_test.sh)
and builds (build/results/recipes.tsv, by tools/recipe_shell.sh: every
recipe line's time), the builds attributed to the tests that need them (from
make's database: a build shared by several tests counts for each, and is
marked shared).  The console gets the wall time, the sum of the times and
the slowest tests, builds included."""
import json
import os
import platform
import re
import subprocess
import sys
import time

RESULTS = "build/results"

# The make target of each suite name (tools/mk: suite_run NAME).
TARGET = {"slow": "test-slow", "all": "test-all"}


def prerequisites():
    """{target: [prerequisites]} from make's database (make -pq, no rule runs)."""
    out = subprocess.run(["make", "-pq", "--no-print-directory", "help"], capture_output=True, text=True,
                         env={k: v for k, v in os.environ.items() if k not in ("ALB_SUITE", "MAKEFLAGS", "MFLAGS")}).stdout
    deps, in_files = {}, False
    for line in out.splitlines():
        if line.startswith("# Files"):
            in_files = True
        if not in_files or line.startswith(("#", "\t")) or ":" not in line or line.startswith(" "):
            continue
        m = re.match(r"^([^:=\s][^:=]*?):{1,2}(?!=)\s*(.*)$", line)
        if m:
            t = m.group(1).strip()
            ds = m.group(2).split("|")[0].split()
            deps.setdefault(t, []).extend(ds)
    return deps


def order(name, tests):
    """The tests, the costliest first by the last run's report (build/reports/
    suite_NAME.json, or suite_test.json): with make -j, a long test started
    last would run alone at the end.  Tests without a figure keep their place
    among those of median cost; with no report at all, the order is kept."""
    rep = None
    for n in (name, "test"):
        try:
            with open(f"build/reports/suite_{n}.json") as f:
                rep = json.load(f)
            break
        except (OSError, ValueError):
            pass
    cost = {r["test"]: (r.get("run_s") or 0) + (r.get("own_build_s") or 0) for r in (rep or {}).get("rows", [])}
    if not cost:
        return tests
    mid = sorted(cost.values())[len(cost) // 2]
    return sorted(tests, key=lambda t: -cost.get(t, mid))


def idle_slots(spans, start, end, jobs):
    """From the recipes' (start ms, end ms, target): the slot-seconds left
    empty between start and end with `jobs` slots, and the longest stretches
    with fewer recipes running than slots (what ran then, how long)."""
    ev = sorted([(a, 1, n) for a, b, n in spans] + [(b, -1, n) for a, b, n in spans])
    running, idle, stretches, t, cur = set(), 0.0, [], start, None
    for when, kind, n in ev + [(end, 0, None)]:
        when = min(max(when, start), end)
        if when > t and len(running) < jobs:
            idle += (jobs - len(running)) * (when - t) / 1e3
            key = " + ".join(sorted(running)) or "nothing"
            if cur and cur[0] == key and cur[2] == t:
                cur[1] += (when - t) / 1e3
                cur[2] = when
            else:
                cur = [key, (when - t) / 1e3, when]
                stretches.append(cur)
        t = max(t, when)
        if kind == 1:
            running.add(n)
        elif kind == -1:
            running.discard(n)
    stretches.sort(key=lambda c: -c[1])
    return idle, [{"recipes": k, "s": round(s, 1)} for k, s, _ in stretches[:10] if s >= 1]


def main():
    if sys.argv[1] == "--order":
        print(" ".join(order(sys.argv[2], sys.argv[3:])))
        return
    name, t0, jobs, tests = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
    wall = (time.time_ns() - t0) / 1e9
    recipes, rcpu, spans = {}, {}, []
    try:
        with open(f"{RESULTS}/recipes.tsv") as f:
            for line in f:
                p = line.rstrip("\n").split("\t")
                if len(p) == 5:
                    spans.append((int(p[4]), int(p[4]) + int(p[1]), p[0]))
                if len(p) == 5 and not p[0].startswith("test-"):
                    recipes[p[0]] = recipes.get(p[0], 0) + int(p[1])
                    rcpu[p[0]] = rcpu.get(p[0], 0) + int(p[3])
    except OSError:
        pass
    deps = prerequisites() if recipes else {}
    users = {}
    need = {}
    for t in tests:
        seen, todo = set(), list(deps.get(f"test-{t}", []))
        while todo:
            d = todo.pop()
            if d in seen:
                continue
            seen.add(d)
            todo.extend(deps.get(d, []))
        need[t] = sorted(d for d in seen if d in recipes)
        for d in need[t]:
            users.setdefault(d, []).append(t)
    rows = []
    for t in tests:
        try:
            run_ms = int(open(f"{RESULTS}/{t}.ms").read())
        except (OSError, ValueError):
            run_ms = None
        try:
            status = open(f"{RESULTS}/{t}.status").read().strip()
        except OSError:
            status = "NOT RUN"
        try:
            run_cpu = int(open(f"{RESULTS}/{t}.cpu_ms").read())
        except (OSError, ValueError):
            run_cpu = 0
        build_ms = sum(recipes[d] for d in need[t])
        own_cpu = sum(rcpu[d] for d in need[t] if len(users[d]) == 1)
        own_ms = sum(recipes[d] for d in need[t] if len(users[d]) == 1)
        rows.append({"test": t, "status": status, "run_s": None if run_ms is None else run_ms / 1e3,
                     "build_s": build_ms / 1e3, "own_build_s": own_ms / 1e3,
                     "run_cpu_s": run_cpu / 1e3, "own_build_cpu_s": own_cpu / 1e3,
                     "cpu_s": (run_cpu + own_cpu) / 1e3,
                     "builds": [{"target": d, "s": recipes[d] / 1e3, "cpu_s": rcpu[d] / 1e3, "shared_by": len(users[d])}
                                for d in need[t]]})
    idle_s, alone = idle_slots(spans, t0 // 1000000, time.time_ns() // 1000000, jobs)
    run_sum = sum(r["run_s"] or 0 for r in rows)
    build_sum = sum(recipes.values()) / 1e3
    cpu_sum = (sum(r["run_cpu_s"] for r in rows) * 1e3 + sum(rcpu.values())) / 1e3
    try:
        load = os.getloadavg()
    except OSError:
        load = (0, 0, 0)
    rep = {"suite": name, "wall_s": round(wall, 1), "jobs": jobs, "tests": len(tests),
           "passed": sum(1 for r in rows if r["status"] == "PASS"),
           "run_sum_s": round(run_sum, 1), "build_sum_s": round(build_sum, 1), "cpu_sum_s": round(cpu_sum, 1),
           # On an idle machine the suite takes at least its CPU time shared by the cores.
           "idle_estimate_s": round(cpu_sum / min(jobs, os.cpu_count() or 1), 1),
           # job slots left empty (slot-seconds): what packing cost, and what ran alone then
           "idle_slot_s": round(idle_s, 1), "ran_alone": alone,
           "cores": os.cpu_count(), "loadavg_end": [round(x, 2) for x in load],
           "cpu": next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")),
                       platform.processor()),
           "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
           "busy": os.environ.get("ALB_SUITE_NOTE", ""),
           "rows": rows, "builds": {d: {"s": recipes[d] / 1e3, "cpu_s": rcpu[d] / 1e3}
                                    for d in sorted(recipes, key=lambda d: -rcpu[d])}}
    os.makedirs("build/reports", exist_ok=True)
    # ALB_SUITE_TAG (e.g. hogs) keeps a run made under other conditions
    # apart: build/reports/suite_NAME_TAG.json; ALB_SUITE_NOTE says what they were.
    tag = os.environ.get("ALB_SUITE_TAG", "")
    out = f"build/reports/suite_{name}{'_' + tag if tag else ''}.json"
    with open(out, "w") as f:
        json.dump(rep, f, indent=1)
        f.write("\n")
    slow = sorted(rows, key=lambda r: -r["cpu_s"])[:12]
    print(f"make {TARGET.get(name, name)}: {wall / 60:.1f} min wall on {jobs} jobs (load average {load[0]:.1f} at the end); "
          f"CPU time {cpu_sum / 60:.1f} min (runs and builds), so about {rep['idle_estimate_s'] / 60:.1f} min "
          f"on an idle machine with {min(jobs, os.cpu_count() or 1)} cores ({out})")
    print("the tests that cost most CPU time (run + builds of their own; builds shared with other tests not counted):")
    for r in slow:
        print(f"  {r['cpu_s']:7.1f} s CPU  {r['test']}  (run {r['run_cpu_s']:.1f} s CPU, {r['run_s'] or 0:.1f} s wall; "
              f"own builds {r['own_build_cpu_s']:.1f} s CPU)")
    print(f"job slots left empty: {idle_s:.0f} slot-seconds of {jobs * wall:.0f}"
          + ("; the longest stretches with fewer recipes than slots ran: "
             + ", ".join(f"{a['recipes']} ({a['s']:.0f} s)" for a in alone[:5]) if alone else ""))
    sb = sorted(rcpu, key=lambda d: -rcpu[d])[:8]
    if sb:
        print("the builds that cost most: " + ", ".join(f"{d} {rcpu[d] / 1e3:.1f} s ({len(users.get(d, []))} tests)"
                                                      for d in sb))

if __name__ == "__main__":
    main()
