#!/usr/bin/env python3
"""host_threads.py -- run the host thread test (tb/host_threads/host_threads.c)
and judge it; tools/mk/host_threads.mk calls it.  Each command writes its
section of build/reports/host_threads.json (the other sections are kept).

  check    DIR   the real driver with the unchanged mmio port (DIR/ht_mmio):
                 both kinds, payloads of 2 and 8 words; every Import must check
                 out, and the producer must overtake some Imports
  negative DIR   the same with no fence at all (DIR/ht_nofence): each kind must
                 fail (exit 1, violations counted)
  sites    DIR   one build per fence site of c-driver/albatross.c with only that
                 fence dropped (DIR/ht_drop<LINE>), each run on the kind the
                 site belongs to: a store-load site (its comment says "... before
                 loading ...") must fail, except those in the functions named
                 by --not-observed (run and reported all the same); a release or acquire
                 site must pass (x86-64 is TSO: it keeps store-store and
                 load-load order, only the store-load one needs the fence);
                 --pair F1,F2: the first fences of functions F1 and F2 dropped
                 together (DIR/ht_pair_<L1>_<L2>) must fail
  soak     DIR   check with --imports-per-run (long), then the negative and the
                 store-load sites --repeat times each: how often each fails
                 within its budget, and after how many Imports

Options: --imports N (per run; --fail-imports for the sites that must fail,
which stop at their --stop-after-th violation), --min-overtaken M (each run goes on past N
Imports until the producer overtook M of them, up to --soft-seconds),
--words W,W, --repeat R, --seconds S (watchdog of each run), --not-observed
FUNCTION,FUNCTION.  Exit status 0: the command's
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
                             "acquire" if "acquire" in comment else "release")
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


def save(section, data):
    rep = {}
    if os.path.exists(REPORT):
        try:
            with open(REPORT) as f:
                rep = json.load(f)
        except ValueError:
            rep = {}
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "")
    except OSError:
        pass
    rep["machine"] = {"cpu": cpu or platform.processor(), "arch": platform.machine(), "cores": os.cpu_count()}
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
            good = r["exit"] == 0
            ok &= good
            print(f"  {'ok  ' if good else 'FAIL'} mmio port, {kind}, {w} words: {counts(r)}; "
                  f"producer overtook {r.get('overtaken', 0):,} Imports, {r.get('starvation_events', 0)} "
                  f"starvation events, {r.get('seconds', 0):.1f} s")
            if not good:
                print("       expected exit 0 and 0 violations, got exit %d: %s" % (r["exit"], r["last_line"]))
                for l in r["first_lines"]:
                    print("       " + l)
    total = sum(r.get("imports", 0) for r in runs)
    save("checked", {"runs": runs, "imports_total": total, "min_overtaken": a.min_overtaken})
    print(f"host-threads: {total:,} Imports checked on {len(runs)} runs, "
          f"{sum(r.get('violations', 0) for r in runs)} violations")
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


def negative(a):
    runs, ok = [], True
    n_real, n_broken = fence_count(f"{a.dir}/ht_mmio"), fence_count(f"{a.dir}/ht_nofence")
    good = n_real > 0 and n_broken == 0
    ok &= good
    print(f"  {'ok  ' if good else 'FAIL'} fence instructions in the driver's code: {n_real} with the mmio port, "
          f"{n_broken} without (expected some, and none)")
    for kind in KINDS:
        for w in a.words:
            r = run(a, f"{a.dir}/ht_nofence", kind, a.imports, w, a.stop_after, label=f"nofence-{kind}-{w}w")
            runs.append(r)
            good = r["exit"] == 1 and r.get("violations", 0) > 0
            ok &= good
            print(f"  {'caught    ' if good else 'NOT CAUGHT'} no fence, {kind}, {w} words: {counts(r)}"
                  + (f"; first at Import {r['first_violation_at']:,}" if r.get("first_violation_at") else ""))
            if not good:
                print(f"       expected exit 1 with violations, got exit {r['exit']}: {r['last_line']}")
    save("no_fence", {"runs": runs, "budget_imports": a.imports, "min_overtaken": a.min_overtaken,
                      "stop_after": a.stop_after,
                      "fence_instructions": {"mmio": n_real, "no_fence": n_broken}})
    print(f"host-threads-nofence-negative: {sum(1 for r in runs if r['exit'] == 1)} of {len(runs)} "
          f"runs without the fence failed, {sum(r.get('violations', 0) for r in runs):,} violations")
    return ok


def sites(a):
    rows, ok = [], True
    for line, func, comment, kind, order in fence_sites():
        row = {"line": line, "function": func, "comment": comment, "kind": kind, "order": order}
        if kind == "set-up":
            row["verdict"] = "not run: set-up, before the threads start (pthread_create orders it)"
            rows.append(row)
            print(f"  -          line {line} {func}: {row['verdict']}")
            continue
        expect_fail = order == "store-load" and func not in a.not_observed
        r = run(a, f"{a.dir}/ht_drop{line}", kind, a.fail_imports if expect_fail else a.imports, a.words[0],
                a.stop_after if expect_fail else None, label=f"drop{line}-{kind}")
        row["run"] = r
        failed = r["exit"] == 1 and r.get("violations", 0) > 0
        if expect_fail:
            good = failed
            row["verdict"] = "fails without it" if failed else "NOT CAUGHT"
        elif order == "store-load":
            good = r["exit"] in (0, 1)
            row["verdict"] = ("fails without it" if failed else
                              "not observed on this machine (listed as such)")
        else:
            good = r["exit"] == 0
            row["verdict"] = "not needed on x86-64 (TSO)" if good else "UNEXPECTED failure"
        ok &= good
        rows.append(row)
        what = comment if comment.startswith(order) else f"{order}: {comment}"
        print(f"  {'ok  ' if good else 'FAIL'} line {line} {func} ({what}) on {kind}: "
              f"{row['verdict']}; {counts(r)}")
        if not good:
            print(f"       expected {'exit 1 with violations' if expect_fail else 'exit 0'}, got exit "
                  f"{r['exit']}: {r['last_line']}")
    if a.pair:
        first = {}
        for line, func, _c, kind, _o in fence_sites():
            first.setdefault(func, (line, kind))
        (l1, kind), (l2, _k) = first[a.pair[0]], first[a.pair[1]]
        r = run(a, f"{a.dir}/ht_pair_{l1}_{l2}", kind, a.fail_imports, a.words[0], a.stop_after,
                label=f"drop{l1}+{l2}-{kind}")
        failed = r["exit"] == 1 and r.get("violations", 0) > 0
        ok &= failed
        rows.append({"line": f"{l1} + {l2}", "function": " + ".join(a.pair), "comment": "the two together",
                     "kind": kind, "order": "store-load, and the full fence after it", "run": r,
                     "verdict": "fails without both" if failed else "NOT CAUGHT"})
        print(f"  {'ok  ' if failed else 'FAIL'} lines {l1} + {l2} ({' + '.join(a.pair)}) dropped together on {kind}: "
              f"{rows[-1]['verdict']}; {counts(r)}")
        if not failed:
            print(f"       expected exit 1 with violations, got exit {r['exit']}: {r['last_line']}")
    save("sites", {"sites": rows, "budget_imports": a.imports, "budget_imports_must_fail": a.fail_imports, "min_overtaken": a.min_overtaken, "words": a.words[0],
                   "stop_after": a.stop_after})
    n = sum(1 for r in rows if r.get("verdict") == "fails without it")
    single = sum(1 for r in rows if "run" in r and isinstance(r["line"], int))
    print(f"host-threads-sites: {n} of {single} fence sites fail when dropped alone "
          f"(the store-load ones{'; not observed alone: ' + ','.join(a.not_observed) if a.not_observed else ''})"
          + (f"; {' + '.join(a.pair)} together: {rows[-1]['verdict']}" if a.pair else ""))
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
    p.add_argument("command", choices=("check", "negative", "sites", "soak"))
    p.add_argument("dir")
    p.add_argument("--imports", type=int, default=15000000)
    p.add_argument("--negative-imports", type=int, default=30000000)
    p.add_argument("--fail-imports", type=int, default=100000000)
    p.add_argument("--words", default="2,8")
    p.add_argument("--stop-after", type=int, default=1000)
    p.add_argument("--repeat", type=int, default=10)
    p.add_argument("--seconds", type=float, default=60)
    p.add_argument("--soft-seconds", type=float, default=40)
    p.add_argument("--min-overtaken", type=int, default=50000)
    p.add_argument("--not-observed", default="")
    p.add_argument("--pair", default="")
    a = p.parse_args()
    a.words = [int(w) for w in a.words.split(",")]
    a.not_observed = [f for f in a.not_observed.split(",") if f]
    a.pair = [f for f in a.pair.split(",") if f]
    ok = {"check": check, "negative": negative, "sites": sites, "soak": soak}[a.command](a)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
