#!/usr/bin/env python3
"""host_threads.py -- run the host thread test (tb/host_threads/host_threads.c)
and judge it; tools/mk/host_threads.mk calls it.  Each command writes its
section of build/reports/host_threads.json (the other sections are kept).

  check    DIR   the real driver with the unchanged mmio port (DIR/ht_mmio) on two
                 threads: both kinds, payloads of 2 and 8 words; every Import must
                 check out, and each run goes on until the producer overtook
                 --min-overtaken Imports, within --soft-seconds (a busy machine
                 that leaves less overlap is reported as LIMITED, not a failure)
  model    DIR   the store-buffer model (DIR/sb_model, deterministic): the fenced
                 driver must never fail, the fence-less one must fail, on both
                 kinds, in tso and pso; each fence site dropped alone must fail
                 exactly where MODEL_FAILS says (store-load: both modes;
                 store-store: pso only; load-load, load-store: outside the model,
                 must pass), except the store-load sites of the functions named by
                 --covered (a later full fence does their work: must pass), and
                 --pair F1,F2 (the first fences of F1 and F2 dropped together)
                 must fail
  observe  DIR   silicon, observed: each fence-less build (no fence; each
                 store-load site alone; the pair) once on this CPU, counted per
                 CPU model in the report; only a clean end is required, and that
                 the fence-less builds hold no fence instruction
  soak     DIR   check with --imports (long), then the fence-less builds --repeat
                 times each: how often each fails within its budget on this CPU

Options: --imports N (per run; --fail-imports for the sites that must fail,
which stop at their --stop-after-th violation), --min-overtaken M (each run goes on past N
Imports until the producer overtook M of them, up to --soft-seconds),
--words W,W, --repeat R, --seconds S (watchdog of each run), --covered
FUNCTION,FUNCTION, --seed S (the model's scheduler).  Exit status 0: the command's
expectation held.
"""
import argparse
import json
import os
import platform
import re
import subprocess
import sys

DRIVER = "c-driver/albatross.c"
REPORT = "build/reports/host_threads.json"
KINDS = ("three-buffer", "four-slot")


def fence_sites():
    """[(line, function, comment, kind, order)] for each alb_fence(); of the driver."""
    sites, func = [], None
    with open(DRIVER) as f:
        for no, line in enumerate(f, 1):
            m = re.match(r"^(?:static |ALB_NOINLINE |ALB_INLINE )*(?:int|void) \**(\w+)\(", line)
            if m:
                func = m.group(1)
            if "alb_fence();" in line:
                c = re.search(r"/\*\s*(.*?)\s*\*/", line)
                comment = c.group(1) if c else ""
                if func.endswith("_init"):
                    kind, order = "set-up", "set-up (before the threads start)"
                else:
                    kind = "four-slot" if func.startswith("fs_") else "three-buffer"
                    order = ("store-load" if "before loading" in comment else
                             "load-load" if "acquire" in comment else
                             "load-store" if "loads before" in comment else "store-store")
                sites.append((no, func, comment, kind, order))
    return sites


def run(a, binary, kind, imports, words, stop_after=None, label="run"):
    os.makedirs("build/host_threads/runs", exist_ok=True)
    out = f"build/host_threads/runs/{label}.json"
    if os.path.exists(out):
        os.remove(out)
    cmd = [binary, "--kind", kind, "--imports", str(imports), "--words", str(words),
           "--seconds", str(a.seconds), "--soft-seconds", str(a.soft_seconds),
           "--min-overtaken", str(a.min_overtaken), "--label", label, "--json", out]
    if stop_after:
        cmd += ["--stop-after", str(stop_after)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l]
    rep = {}
    if os.path.exists(out):
        with open(out) as f:
            rep = json.load(f)
    rep["exit"] = p.returncode
    rep["last_line"] = lines[-1] if lines else ""
    rep["first_lines"] = lines[:3]
    return rep


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            return next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "")
    except OSError:
        return platform.processor()


def save(section, data):
    rep = {}
    if os.path.exists(REPORT):
        try:
            with open(REPORT) as f:
                rep = json.load(f)
        except ValueError:
            rep = {}
    rep["machine"] = {"cpu": cpu_model() or platform.processor(), "arch": platform.machine(), "cores": os.cpu_count()}
    rep[section] = data
    os.makedirs(os.path.dirname(REPORT), exist_ok=True)
    with open(REPORT, "w") as f:
        json.dump(rep, f, indent=1)
        f.write("\n")


def counts(r):
    return (f"{r.get('imports', 0):,} Imports (New {r.get('new', 0):,}, Old {r.get('old', 0):,}), "
            f"{r.get('violations', 0)} violations: {r.get('torn', 0)} torn, {r.get('back_in_time', 0)} back in time, "
            f"{r.get('stale', 0)} stale, {r.get('wrong_new', 0)} wrong New, {r.get('wrong_old', 0)} wrong Old")


def check(a):
    runs, ok = [], True
    for kind in KINDS:
        for w in a.words:
            r = run(a, f"{a.dir}/ht_mmio", kind, a.imports, w, label=f"mmio-{kind}-{w}w")
            runs.append(r)
            # exit 4: no violation, but the threads overlapped less than wanted
            # within the time bound (a busy machine): not a failure of the driver,
            # and shown as a limit of this run.
            good = r["exit"] in (0, 4)
            ok &= good
            print(f"  {'ok  ' if good else 'FAIL'} mmio port, {kind}, {w} words: {counts(r)}; "
                  f"producer overtook {r.get('overtaken', 0):,} Imports, {r.get('starvation_events', 0)} "
                  f"starvation events, {r.get('seconds', 0):.1f} s")
            if r["exit"] == 4:
                print(f"       LIMITED: the machine was busy; the producer overtook only {r.get('overtaken', 0):,} "
                      f"of the {a.min_overtaken:,} Imports wanted within {a.soft_seconds:.0f} s")
            if not good:
                print("       expected exit 0 and 0 violations, got exit %d: %s" % (r["exit"], r["last_line"]))
                for l in r["first_lines"]:
                    print("       " + l)
    total = sum(r.get("imports", 0) for r in runs)
    save("checked", {"runs": runs, "imports_total": total, "min_overtaken": a.min_overtaken})
    limited = sum(1 for r in runs if r["exit"] == 4)
    print(f"host-threads: {total:,} Imports checked on {len(runs)} runs, "
          f"{sum(r.get('violations', 0) for r in runs)} violations, "
          f"{sum(r.get('overtaken', 0) for r in runs):,} overtaken"
          + (f" ({limited} runs LIMITED by a busy machine)" if limited else ""))
    return ok


FENCE = re.compile(r"\b(mfence|lock )")


def fence_count(binary):
    """The fence instructions (mfence, lock-prefixed) in the driver's functions of BINARY."""
    text = subprocess.run(["objdump", "-d", "--no-show-raw-insn", binary], capture_output=True,
                          text=True).stdout
    cur, fences = False, 0
    for line in text.splitlines():
        m = re.match(r"^[0-9a-f]+ <(\w+)>:$", line)
        if m:
            cur = m.group(1).startswith(("alb_", "fs_"))
        elif cur and "\t" in line and FENCE.search(line.split("\t", 1)[1]):
            fences += 1
    return fences


# What the store-buffer model (tb/host_threads/sb_model.c) must show for a
# fence of each order dropped alone, per mode: True = the checker must catch
# a violation, False = none may appear.  tso keeps every order but
# store-load; pso also reorders stores to different addresses.  Loads are
# performed in order in both: the load-load and load-store fences (the
# consumer's acquire and release) are outside the model, and must pass.
MODEL_FAILS = {"store-load": {"tso": True, "pso": True}, "store-store": {"tso": False, "pso": True},
               "load-load": {"tso": False, "pso": False}, "load-store": {"tso": False, "pso": False}}
MODES = ("tso", "pso")


def model_run(a, kind, mode, drop, words, must_fail, label):
    os.makedirs("build/host_threads/runs", exist_ok=True)
    out = f"build/host_threads/runs/{label}.json"
    if os.path.exists(out):
        os.remove(out)
    cmd = [f"{a.dir}/sb_model", "--kind", kind, "--mode", mode, "--drop", drop, "--words", str(words),
           "--seed", str(a.seed), "--imports", str(a.fail_imports if must_fail else a.imports),
           "--json", out, "--label", label]
    if must_fail:
        cmd += ["--stop-after", str(a.stop_after)]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=a.seconds)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l]
    rep = {}
    if os.path.exists(out):
        with open(out) as f:
            rep = json.load(f)
    rep["exit"] = p.returncode
    rep["last_line"] = lines[-1] if lines else ""
    return rep


def model_judge(r, must_fail):
    """(good, what it showed)."""
    failed = r["exit"] == 1 and r.get("violations", 0) > 0
    if must_fail:
        return failed, ("caught" if failed else "NOT CAUGHT")
    return r["exit"] == 0, ("no violation" if r["exit"] == 0 else "UNEXPECTED violation")


def model(a):
    """The deterministic proof: the fenced driver never fails in the model,
    the fence-less one always does, and each fence site dropped alone (and
    the pair) fails exactly where the memory model says it must."""
    ok, runs, rows = True, [], []
    for kind in KINDS:
        for mode in MODES:
            for w in a.words:
                for drop, must_fail in (("none", False), ("all", True)):
                    r = model_run(a, kind, mode, drop, w, must_fail, f"model-{mode}-{kind}-{w}w-drop-{drop}")
                    good, what = model_judge(r, must_fail)
                    ok &= good
                    runs.append(r)
                    print(f"  {'ok  ' if good else 'FAIL'} model {mode}, {kind}, {w} words, "
                          f"{'every fence kept' if drop == 'none' else 'no fence'}: {what}; {counts(r)}"
                          + (f"; first at Import {r['first_violation_at']:,}" if r.get("first_violation_at") else ""))
                    if not good:
                        print(f"       expected {'exit 1 with violations' if must_fail else 'exit 0'}, "
                              f"got exit {r['exit']}: {r['last_line']}")
    # The same seed gives the same run: the proof does not depend on the machine.
    again = model_run(a, KINDS[0], "tso", "all", a.words[0], True, "model-repeat")
    same = all(again.get(k) == runs[1].get(k) for k in ("imports", "violations", "first_violation_at", "steps"))
    ok &= same
    print(f"  {'ok  ' if same else 'FAIL'} the same seed again gives the same run (first violation at Import "
          f"{again.get('first_violation_at', 0):,} both times)" if same else
          f"  FAIL expected the same run for the same seed, got {again} and {runs[1]}")
    first = {}
    for line, func, comment, kind, order in fence_sites():
        first.setdefault(func, line)
        if kind == "set-up":
            rows.append({"line": line, "function": func, "comment": comment, "kind": kind, "order": order,
                         "verdict": "not run: set-up, before the CPUs start"})
            continue
        row = {"line": line, "function": func, "comment": comment, "kind": kind, "order": order, "model": {}}
        for mode in MODES:
            must_fail = MODEL_FAILS[order][mode] and func not in a.covered
            r = model_run(a, kind, mode, str(line), a.words[-1], must_fail, f"model-{mode}-drop{line}")
            good, what = model_judge(r, must_fail)
            ok &= good
            row["model"][mode] = {"must_fail": must_fail, "shows": what, "run": r}
            note = (" (covered by the next function's full fence)" if func in a.covered and MODEL_FAILS[order][mode]
                    else " (outside the model: loads in order)" if order.startswith("load") else "")
            print(f"  {'ok  ' if good else 'FAIL'} model {mode}, line {line} {func} ({order}: {comment}) dropped: "
                  f"{what}{note}; {counts(r)}")
            if not good:
                print(f"       expected {'exit 1 with violations' if must_fail else 'exit 0'}, got exit "
                      f"{r['exit']}: {r['last_line']}")
        rows.append(row)
    if a.pair:
        l1, l2 = first[a.pair[0]], first[a.pair[1]]
        row = {"line": f"{l1} + {l2}", "function": " + ".join(a.pair), "comment": "the two together",
               "kind": "four-slot", "order": "store-load, and the full fence after it", "model": {}}
        for mode in MODES:
            r = model_run(a, "four-slot", mode, f"{l1},{l2}", a.words[-1], True, f"model-{mode}-drop{l1}+{l2}")
            good, what = model_judge(r, True)
            ok &= good
            row["model"][mode] = {"must_fail": True, "shows": what, "run": r}
            print(f"  {'ok  ' if good else 'FAIL'} model {mode}, lines {l1} + {l2} ({' + '.join(a.pair)}) dropped "
                  f"together: {what}; {counts(r)}")
        rows.append(row)
    # A pass means something only if the budget of the runs that must pass is
    # well above the Import at which the slowest caught fault first showed.
    latest = max([r.get("first_violation_at", 0) for r in runs] +
                 [m["run"].get("first_violation_at", 0) for row in rows for m in row.get("model", {}).values()
                  if m["must_fail"]])
    enough = a.imports >= 2 * latest
    ok &= enough
    print(f"  {'ok  ' if enough else 'FAIL'} the runs that must pass make {a.imports:,} Imports, at least twice the "
          f"Import ({latest:,}) of the latest first violation of the runs that must fail"
          + ("" if enough else ": raise --imports"))
    save("model", {"runs": runs, "sites": rows, "latest_first_violation": latest, "seed": a.seed, "budget_imports": a.imports,
                   "budget_imports_must_fail": a.fail_imports, "stop_after": a.stop_after,
                   "covered": a.covered, "pair": a.pair})
    print(f"host-threads-model: {'every' if ok else 'NOT every'} expectation of the store-buffer model held "
          f"(seed {a.seed}; tso and pso; {len(runs) + 1} whole-driver runs, "
          f"{sum(len(r.get('model', {})) for r in rows)} fence-site runs)")
    return ok


def observe(a):
    """Silicon, observed: how often each fence-less build tears on this CPU.
    Nothing is required of them (whether a missing fence shows depends on
    the CPU and its timing); required: the fence-less builds hold no fence
    instruction while the mmio build does, and every run ends cleanly."""
    n_real, n_broken = fence_count(f"{a.dir}/ht_mmio"), fence_count(f"{a.dir}/ht_nofence")
    ok = n_real > 0 and n_broken == 0
    print(f"  {'ok  ' if ok else 'FAIL'} fence instructions in the driver's code: {n_real} with the mmio port, "
          f"{n_broken} without (expected some, and none)")
    variants = [("ht_nofence", "no fence", k) for k in KINDS]
    first = {}
    for l, f, _c, k, o in fence_sites():
        first.setdefault(f, l)
        if o == "store-load":
            variants.append((f"ht_drop{l}", f"line {l} ({f})", k))
    if a.pair:
        l1, l2 = first[a.pair[0]], first[a.pair[1]]
        variants.append((f"ht_pair_{l1}_{l2}", f"lines {l1} + {l2} ({' + '.join(a.pair)})", "four-slot"))
    rep = {}
    if os.path.exists(REPORT):
        try:
            with open(REPORT) as f:
                rep = json.load(f)
        except ValueError:
            rep = {}
    cpu = cpu_model()
    seen = rep.get("observed", {})
    mine = seen.setdefault(cpu, {})
    runs = []
    for binary, name, kind in variants:
        r = run(a, f"{a.dir}/{binary}", kind, a.imports, a.words[-1], a.stop_after, label=f"observe-{binary}-{kind}")
        clean = r["exit"] in (0, 1, 4)
        ok &= clean
        tore = r["exit"] == 1 and r.get("violations", 0) > 0
        v = mine.setdefault(f"{name}, {kind}", {"kind": kind, "runs": 0, "tore": 0, "imports": 0, "violations": 0})
        v["runs"] += 1
        v["tore"] += int(tore)
        v["imports"] += r.get("imports", 0)
        v["violations"] += r.get("violations", 0)
        if binary == "ht_nofence":
            runs.append(r)
        print(f"  {'    ' if clean else 'FAIL'} observed: {name}, {kind}: {'tore' if tore else 'did not tear'} "
              f"in {r.get('imports', 0):,} Imports ({r.get('overtaken', 0):,} overtaken); on this CPU so far "
              f"{v['tore']} of {v['runs']} runs tore")
        if not clean:
            print(f"       expected the run to end cleanly (exit 0, 1 or 4), got exit {r['exit']}: {r['last_line']}")
    save("observed", seen)
    save("no_fence", {"runs": runs, "budget_imports": a.imports, "min_overtaken": a.min_overtaken,
                      "stop_after": a.stop_after, "fence_instructions": {"mmio": n_real, "no_fence": n_broken}})
    print(f"host-threads-silicon: on {cpu}: " + "; ".join(
        f"{name} tore in {v['tore']} of {v['runs']} runs" for name, v in mine.items()))
    return ok


def soak(a):
    ok = check(a)
    stats = []
    variants = [("ht_nofence", "no fence", k) for k in KINDS]
    variants += [(f"ht_drop{l}", f"line {l} ({f})", k) for l, f, _c, k, o in fence_sites() if o == "store-load"]
    if a.pair:
        first = {}
        for l, f, _c, k, _o in fence_sites():
            first.setdefault(f, (l, k))
        (l1, k), (l2, _k) = first[a.pair[0]], first[a.pair[1]]
        variants.append((f"ht_pair_{l1}_{l2}", f"lines {l1} + {l2} ({' + '.join(a.pair)})", k))
    for binary, name, kind in variants:
        first, viol = [], []
        for i in range(a.repeat):
            r = run(a, f"{a.dir}/{binary}", kind, a.negative_imports, a.words[-1], a.stop_after,
                    label=f"soak-{binary}-{kind}-{i}")
            viol.append(r.get("violations", 0))
            first.append(r.get("first_violation_at", 0))
        caught = sum(1 for v in viol if v > 0)
        stats.append({"variant": name, "kind": kind, "runs": a.repeat, "failed": caught,
                      "budget_imports": a.negative_imports, "violations": viol, "first_violation_at": first})
        print(f"  {name}, {kind}: failed {caught} of {a.repeat} runs of at most {a.negative_imports:,} Imports; "
              f"first violation at Import {sorted(f for f in first if f) or '-'}")
    save("reliability", {"words": a.words[-1], "stop_after": a.stop_after, "min_overtaken": a.min_overtaken,
                         "variants": stats})
    return ok


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("command", choices=("check", "model", "observe", "soak"))
    p.add_argument("dir")
    p.add_argument("--imports", type=int, default=15000000)
    p.add_argument("--negative-imports", type=int, default=30000000)
    p.add_argument("--fail-imports", type=int, default=100000000)
    p.add_argument("--words", default="2,8")
    p.add_argument("--stop-after", type=int, default=1000)
    p.add_argument("--repeat", type=int, default=10)
    p.add_argument("--seconds", type=float, default=300)
    p.add_argument("--soft-seconds", type=float, default=40)
    p.add_argument("--min-overtaken", type=int, default=50000)
    p.add_argument("--covered", default="", help="store-load sites covered by a later full fence")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--pair", default="")
    a = p.parse_args()
    a.words = [int(w) for w in a.words.split(",")]
    a.covered = [f for f in a.covered.split(",") if f]
    a.pair = [f for f in a.pair.split(",") if f]
    ok = {"check": check, "model": model, "observe": observe, "soak": soak}[a.command](a)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
