#!/usr/bin/env python3
"""check.py -- run the SPIN checks of formal/spin/albatross.pml.

  check.py --out build/formal/spin --json build/reports/formal_spin.json
      every property of the protocol: the five safety checks hold, the LTL
      properties writer_wait_free and lock_free hold, and reader_wait_free
      FAILS with an acceptance cycle in which the writer keeps exporting and
      the reader keeps retrying its While (the reader is not wait-free).
  check.py --variant WHILE_AS_IF --out ... --json ...
      a broken variant (-DWHILE_AS_IF, -DIGNORE_READLOCKED): the checks named
      by --must-fail must each find a violation.

Each check is its own spin -a / gcc / pan run under --out/<name>/.  Exit 0
when every check gave the expected outcome; otherwise the last line says what
was expected and what came.
"""
import argparse, json, os, re, shutil, subprocess, sys, time

MODEL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "albatross.pml")

# name: (property text, -D switch)  -- safety checks, expected to hold
SAFETY = {
    "mutex": ("mutual exclusion: the writer never stores into the buffer the "
              "reader has locked and confirmed, until its ReadFrom ends",
              "CHECK_MUTEX"),
    "definite": ("definite results: an Import returns both halves of one "
                 "completely written Export, from a valid buffer index",
                 "CHECK_DEFINITE"),
    "actuality": ("actuality: an Import returns a value at least as new as the "
                  "last Export completed before the Import began",
                  "CHECK_ACTUALITY"),
    "newold": ("New/Old: an Import returns New exactly when its value is newer "
               "than the previous Import's, and never an older one",
               "CHECK_NEWOLD"),
    "retry": ("every further pass of the reader's While follows an Export "
              "completed since the reader's previous load of Actual",
              "CHECK_RETRY"),
}
# name: (property text, pan fairness flag, expected outcome)
LTL = {
    "reader_wait_free": ("[]<> !importing: the reader's Import always finishes "
                         "(weak fairness) -- expected to FAIL: a fast writer "
                         "starves it", "-f", "cycle"),
    "writer_wait_free": ("[]<> !exporting: the writer's Export always finishes "
                         "(weak fairness)", "-f", "holds"),
    "lock_free": ("[]<> (!importing || !exporting): some operation always "
                  "completes (no fairness assumption)", "", "holds"),
}


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def build(out, name, defines, safety):
    d = os.path.join(out, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    shutil.copy(MODEL, d)
    rc, log = run(["spin"] + ["-D" + x for x in defines] + ["-a", "albatross.pml"], d)
    if rc != 0 or not os.path.exists(os.path.join(d, "pan.c")):
        raise SystemExit(f"spin -a failed for {name}:\n{log}")
    cc = ["gcc", "-O1", "-w", "-o", "pan", "pan.c"]
    if safety:
        cc[1:1] = ["-DSAFETY", "-DNOCLAIM"]
    rc, log = run(cc, d)
    if rc != 0:
        raise SystemExit(f"gcc pan.c failed for {name}:\n{log}")
    return d


def pan(d, args):
    t0 = time.monotonic()
    rc, log = run(["./pan", "-m1000000"] + args, d)
    secs = time.monotonic() - t0
    errors = int(re.search(r"errors: (\d+)", log).group(1))
    states = int(re.search(r"(\d+) states, stored", log).group(1))
    depth = int(re.search(r"depth reached (\d+)", log).group(1))
    if re.search(r"max search depth too small", log):
        raise SystemExit(f"pan in {d}: search depth limit reached, raise -m")
    viol = re.search(r"pan:1: (.*)", log)
    return dict(errors=errors, states=states, depth=depth,
                seconds=round(secs, 3), violation=viol.group(1) if viol else None,
                log=log)


def replay(d, ltl=None):
    """spin -t -p: the counterexample's steps as text."""
    rc, log = run(["spin", "-t", "-p"] +
                  ["albatross.pml"], d)
    return log


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--json", required=True)
    ap.add_argument("--variant", default=None)
    ap.add_argument("--must-fail", default="mutex,definite")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(os.path.dirname(a.json) or ".", exist_ok=True)
    results, bad = [], []

    def record(name, prop, expected, r, ok, note):
        row = dict(check=name, property=prop, expected=expected,
                   result=("violated" if r["errors"] else "holds"),
                   states=r["states"], depth=r["depth"], seconds=r["seconds"],
                   ok=ok)
        if r["violation"]:
            row["violation"] = r["violation"]
        results.append(row)
        print(f"{'ok  ' if ok else 'BAD '} {name:18s} {row['result']:8s} "
              f"(expected {expected}) states {r['states']:>8d} depth {r['depth']:>6d} "
              f"{r['seconds']:.2f} s{('  ' + note) if note else ''}")
        if not ok:
            bad.append(f"{name}: expected {expected}, got {row['result']}"
                       + (f" ({r['violation']})" if r["violation"] else ""))

    if a.variant:
        for name in a.must_fail.split(","):
            prop, define = SAFETY[name]
            d = build(a.out, f"{a.variant.lower()}_{name}", [a.variant, define], True)
            r = pan(d, [])
            v = r["violation"] or ""
            # the property's own assertion, not the model's stamp bound
            ok = r["errors"] > 0 and "assertion violated" in v and "s!=" not in v
            record(name, prop, "violated", r, ok,
                   f"-D{a.variant}: {r['violation']}" if ok else "")
    else:
        for name, (prop, define) in SAFETY.items():
            d = build(a.out, name, [define], True)
            r = pan(d, [])
            record(name, prop, "holds", r, r["errors"] == 0, "")
        d = build(a.out, "ltl", [], False)
        for name, (prop, fair, expected) in LTL.items():
            r = pan(d, ["-a"] + ([fair] if fair else []) + ["-N", name])
            note = ""
            if expected == "holds":
                ok = r["errors"] == 0
            else:
                # the counterexample must be a cycle in which the writer keeps
                # storing Actual and the reader keeps storing ReadLocked
                ok = r["errors"] > 0 and "acceptance cycle" in (r["violation"] or "")
                if ok:
                    trail = replay(d, name)
                    shutil.copy(os.path.join(d, "albatross.pml.trail"),
                                os.path.join(d, f"{name}.trail"))
                    with open(os.path.join(d, f"{name}.txt"), "w") as f:
                        f.write(trail)
                    cyc = trail.split("<<<<<START OF CYCLE>>>>>")
                    cyc = cyc[1] if len(cyc) > 1 else ""
                    exports = len(re.findall(r"\(writer:\d\).*\[Actual = w\]", cyc))
                    retries = len(re.findall(r"\(reader:\d\).*\[ReadLocked = actual\]", cyc))
                    ends = len(re.findall(r"\(reader:\d\).*\[importing = 0\]", cyc))
                    ok = exports > 0 and retries > 0 and ends == 0
                    note = (f"cycle: {exports} Exports, {retries} ReadLocked "
                            f"stores, {ends} Imports finished; "
                            f"replay: {os.path.join(d, name + '.txt')}")
                    r["violation"] = r["violation"] + " (writer starves reader)" \
                        if ok else r["violation"]
            record(name, prop, "violated (acceptance cycle)" if expected == "cycle"
                   else "holds", r, ok, note)

    with open(a.json, "w") as f:
        json.dump(dict(model="formal/spin/albatross.pml", variant=a.variant,
                       checks=results), f, indent=2)
        f.write("\n")
    total = sum(x["seconds"] for x in results)
    if bad:
        print("FAIL: " + "; ".join(bad))
        return 1
    print(f"all {len(results)} SPIN checks gave the expected outcome"
          f"{' for -D' + a.variant if a.variant else ''} "
          f"({sum(x['states'] for x in results)} states, {total:.2f} s in pan)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
