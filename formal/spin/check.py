#!/usr/bin/env python3
"""check.py -- run the SPIN checks of formal/spin/albatross.pml (three-buffer
channel) or, with --model four_slot, of formal/spin/four_slot.pml (four-slot).

  check.py --out build/formal/spin --json build/reports/formal_spin.json
      every property of the protocol: the five safety checks hold, the LTL
      properties writer_wait_free and lock_free hold, and reader_wait_free
      FAILS with an acceptance cycle in which the writer keeps exporting and
      the reader keeps retrying its While (the reader is not wait-free).
      Each safety check runs twice: from the RAM image, and as cold_<name>
      from a zeroed RAM (-DCOLD_START).
  check.py --variant WHILE_AS_IF --out ... --json ...
      a broken variant (-DWHILE_AS_IF, -DIGNORE_READLOCKED; -DCOLD_READ_ZERO
      with --must-fail cold_mutex,cold_definite): the checks named by
      --must-fail must each find a violation.

  check.py --model four_slot --out build/formal/spin/four_slot \
           --json build/reports/formal_spin_four_slot.json
      the four-slot channel: the safety checks hold (also with one data word,
      with consumer_init L = 1, with consumer crashes at every access, and
      with the controller's Import rule -DOLD_BY_SLOT), and reader_wait_free,
      writer_wait_free and lock_free all HOLD.
  check.py --model four_slot --variant WRONG_ORDER --must-fail mutex,definite ...
      a broken four-slot variant; --must-fail may name LTL properties too
      (reader_wait_free: an acceptance cycle must be found).  Variant runs are
      breadth-first, so the counterexample is a shortest one; its protocol
      steps (the model's printf lines) go to <dir>/trail.txt and the report.

Each check is its own spin -a / gcc / pan run under --out/<name>/.  Exit 0
when every check gave the expected outcome; otherwise the last line says what
was expected and what came.
"""
import argparse, json, os, re, shutil, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
MODEL = os.path.join(HERE, "albatross.pml")     # set by --model

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
# the same properties from a zeroed RAM (-DCOLD_START): each side runs its
# init at any point of the other's run, Actual = 0 reads nothing
SAFETY.update({"cold_" + k: ("cold start on a zeroed RAM: " + p, [d, "COLD_START"])
               for k, (p, d) in list(SAFETY.items())})
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

# The four-slot channel (four_slot.pml).  name: (property, -D switches, pan -m)
SAFETY_FS = {
    "mutex": ("mutual exclusion: the producer never stores into the buffer the "
              "consumer has chosen to read, until its last data load, and the "
              "consumer never loads a word of the buffer being written",
              ["CHECK_MUTEX"], 3000000),
    "definite": ("definite results: an Import returns both words of one "
                 "completely written Export, from a valid buffer index; the "
                 "producer's buffer and the ReadLocked it loads are valid",
                 ["CHECK_DEFINITE"], 3000000),
    "actuality": ("actuality: an Import returns the value in Actual's buffer when "
                  "it began, or a newer one", ["CHECK_ACTUALITY"], 3000000),
    "actuality_w1": ("actuality with one data word (W = 1: which value, not how "
                     "many words; torn values are definite's)", ["CHECK_ACTUALITY", "W=1"], 3000000),
    "newold": ("New/Old: the value is never older than the previous Import's "
               "(never back in time), and the Import returns New exactly when it "
               "is newer (the first Import, L = 0: New)", ["CHECK_NEWOLD"], 3000000),
    "bound": ("bound: an Import makes exactly 1 + W shared accesses on the Old "
              "path and 3 + W otherwise (W = 2), an Export W + 3",
              ["CHECK_BOUND"], 3000000),
    "bound_w1": ("bound with one data word (W = 1): 2 or 4 accesses per Import, "
                 "4 per Export", ["CHECK_BOUND", "W=1"], 3000000),
    "newold_init1": ("New/Old with consumer_init L = 1 (the initial value counts "
                     "as read: the first Import returns Old)",
                     ["CHECK_NEWOLD", "L_INIT=1"], 3000000),
    "crash_mutex": ("mutual exclusion when the consumer may crash instead of any "
                    "access, any number of times, and restart with L = 0",
                    ["CHECK_MUTEX", "CRASH"], 3000000),
    "crash_definite": ("definite results with consumer crashes at every access",
                       ["CHECK_DEFINITE", "CRASH"], 3000000),
    "crash_bound": ("bound with consumer crashes at every access",
                    ["CHECK_BOUND", "CRASH"], 3000000),
    "crash_newold": ("New/Old with consumer crashes at every access (the first "
                     "Import after a restart returns New)",
                     ["CHECK_NEWOLD", "CRASH"], 10000000),
    # a zeroed RAM: each side's init at any point of the other's run
    # (-DCOLD_START, consumer_init with L = 1 as the driver's)
    "cold_mutex": ("cold start on a zeroed RAM: mutual exclusion",
                   ["CHECK_MUTEX", "COLD_START", "L_INIT=1"], 3000000),
    "cold_definite": ("cold start on a zeroed RAM: definite results (nothing read "
                      "while Actual is 0)", ["CHECK_DEFINITE", "COLD_START", "L_INIT=1"], 3000000),
    "cold_actuality": ("cold start on a zeroed RAM: actuality",
                       ["CHECK_ACTUALITY", "COLD_START", "L_INIT=1"], 3000000),
    "cold_actuality_w1": ("cold start on a zeroed RAM: actuality with one data word (W = 1)",
                          ["CHECK_ACTUALITY", "COLD_START", "L_INIT=1", "W=1"], 3000000),
    "cold_newold": ("cold start on a zeroed RAM: New/Old (the producer keeps out of "
                    "pair 0 until the consumer starts, so Buffer1 read as Old is "
                    "the initial value)", ["CHECK_NEWOLD", "COLD_START", "L_INIT=1"], 3000000),
    "cold_bound": ("cold start on a zeroed RAM: the access bound",
                   ["CHECK_BOUND", "COLD_START", "L_INIT=1"], 3000000),
    # the controller's Import rule (rtl/albatross_import.v): Old when
    # buf(pair(A), Slot[pair(A)]) of the first word load is L, that word load
    # being three byte loads in any order
    "ctrl_mutex": ("mutual exclusion, the controller's Import rule (-DOLD_BY_SLOT)",
                   ["CHECK_MUTEX", "OLD_BY_SLOT"], 3000000),
    "ctrl_definite": ("definite results, the controller's Import rule",
                      ["CHECK_DEFINITE", "OLD_BY_SLOT"], 3000000),
    "ctrl_newold": ("New/Old, the controller's Import rule",
                    ["CHECK_NEWOLD", "OLD_BY_SLOT"], 3000000),
    "ctrl_bound": ("bound, the controller's Import rule",
                   ["CHECK_BOUND", "OLD_BY_SLOT"], 3000000),
}
LTL_FS = {
    "reader_wait_free": ("[]<> !importing: the consumer's Import always finishes "
                         "(weak fairness) -- holds: the consumer is wait-free",
                         "-f", "holds"),
    "writer_wait_free": ("[]<> !exporting: the producer's Export always finishes "
                         "(weak fairness)", "-f", "holds"),
    "lock_free": ("[]<> (!importing || !exporting): some operation always "
                  "completes (no fairness assumption)", "", "holds"),
    "ctrl_reader_wait_free": ("reader_wait_free with the controller's Import rule "
                              "(-DOLD_BY_SLOT)", "-f", "holds"),
}
# LTL row -> (claim, extra -D switches of its build)
LTL_BUILD = {"ctrl_reader_wait_free": ("reader_wait_free", ["OLD_BY_SLOT"])}


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


# Most searches end within half a second (every check of albatross.pml, the
# LTL rows, and the four-slot checks of mutual exclusion and of the bound, which
# track no data values): pan is compiled with -O0 for them (0.4 s for
# four_slot.pml instead of 1.8 s at -O2).  The other four-slot checks store
# millions of states: -O2, and a hash table of 2^24 slots (pan -w24) instead of
# the default 2^19, whose chains of conflicts made their searches about a
# quarter slower.
LARGE_MODELS = ("four_slot.pml",)


def small_check(defines, safety=True):
    return (not safety or os.path.basename(MODEL) not in LARGE_MODELS
            or any(d in ("CHECK_MUTEX", "CHECK_BOUND") for d in defines))


def opt_level(defines, safety=True):
    return "-O0" if small_check(defines, safety) else "-O2"


def hash_args(defines):
    return [] if small_check(defines) else ["-w24"]


def build(out, name, defines, safety, cflags=()):
    d = os.path.join(out, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    shutil.copy(MODEL, d)
    rc, log = run(["spin"] + ["-D" + x for x in defines] +
                  ["-a", os.path.basename(MODEL)], d)
    if rc != 0 or not os.path.exists(os.path.join(d, "pan.c")):
        raise SystemExit(f"spin -a failed for {name}:\n{log}")
    cc = ["gcc", opt_level(defines, safety), "-w", "-o", "pan", "pan.c"]
    if safety:
        cc[1:1] = ["-DSAFETY", "-DNOCLAIM"]
    cc[1:1] = list(cflags)
    rc, log = run(cc, d)
    if rc != 0:
        raise SystemExit(f"gcc pan.c failed for {name}:\n{log}")
    return d


def pan(d, args, depth=1000000):
    t0 = time.monotonic()
    rc, log = run(["./pan", f"-m{depth}"] + args, d)
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


def replay(d, ltl=None, defines=()):
    """spin -t -p: the counterexample's steps as text."""
    rc, log = run(["spin"] + ["-D" + x for x in defines] + ["-t", "-p"] +
                  [os.path.basename(MODEL)], d)
    return log


def protocol_steps(d, defines):
    """The shared accesses of a trail (four_slot.pml's printf lines)."""
    rc, log = run(["spin"] + ["-D" + x for x in defines] + ["-t"] +
                  [os.path.basename(MODEL)], d)
    steps = [l.strip() for l in log.splitlines()
             if re.match(r"\s+[PC]: ", l) or "assertion violated" in l
             or "START OF CYCLE" in l]
    with open(os.path.join(d, "trail.txt"), "w") as f:
        f.write("\n".join(steps) + "\n")
    return steps


def starvation(d, name, defines=()):
    """The reader_wait_free cycle: Exports, consumer ReadLocked stores and no
    finished Import in the repeated part.  Returns (ok, note, path)."""
    trail = replay(d, name, defines)
    shutil.copy(os.path.join(d, os.path.basename(MODEL) + ".trail"),
                os.path.join(d, f"{name}.trail"))
    with open(os.path.join(d, f"{name}.txt"), "w") as f:
        f.write(trail)
    cyc = trail.split("<<<<<START OF CYCLE>>>>>")
    cyc = cyc[1] if len(cyc) > 1 else ""
    exports = len(re.findall(r"\((?:writer|producer):\d\).*\[Actual = w\]", cyc))
    retries = len(re.findall(r"\((?:reader|consumer):\d\).*\[ReadLocked = a(?:ctual)?\]", cyc))
    ends = len(re.findall(r"\((?:reader|consumer):\d\).*\[importing = 0\]", cyc))
    ok = exports > 0 and retries > 0 and ends == 0
    return ok, (f"cycle: {exports} Exports, {retries} ReadLocked stores, "
                f"{ends} Imports finished; replay: {os.path.join(d, name + '.txt')}")


def main():
    global MODEL
    ap = argparse.ArgumentParser()
    ap.add_argument("--model", default="albatross", choices=["albatross", "four_slot"])
    ap.add_argument("--out", required=True)
    ap.add_argument("--json", required=True)
    ap.add_argument("--variant", default=None)
    ap.add_argument("--must-fail", default="mutex,definite")
    ap.add_argument("--only", default="", help="comma-separated checks: run just these")
    ap.add_argument("--skip", default="", help="comma-separated checks: run all but these")
    a = ap.parse_args()
    MODEL = os.path.join(HERE, a.model + ".pml")
    if a.model == "four_slot":
        safety, ltl, cflags = SAFETY_FS, LTL_FS, []
    else:
        safety = {k: (p, [d] if isinstance(d, str) else d, 1000000)
                  for k, (p, d) in SAFETY.items()}
        ltl, cflags = LTL, []
    only = [x for x in a.only.split(",") if x]
    skip = [x for x in a.skip.split(",") if x]
    unknown = [x for x in only + skip if x not in safety and x not in ltl]
    if unknown:
        raise SystemExit(f"check.py: no check named {', '.join(unknown)} in {a.model} "
                         f"(there are: {', '.join(list(safety) + list(ltl))})")
    if only or skip:
        keep = (lambda n: n in only) if only else (lambda n: n not in skip)
        safety = {k: v for k, v in safety.items() if keep(k)}
        ltl = {k: v for k, v in ltl.items() if keep(k)}
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(os.path.dirname(a.json) or ".", exist_ok=True)
    results, bad = [], []

    def record(name, prop, expected, r, ok, note, extra=None):
        row = dict(check=name, property=prop, expected=expected,
                   result=("violated" if r["errors"] else "holds"),
                   states=r["states"], depth=r["depth"], seconds=r["seconds"],
                   ok=ok)
        if r["violation"]:
            row["violation"] = r["violation"]
        row.update(extra or {})
        results.append(row)
        print(f"{'ok  ' if ok else 'BAD '} {name:18s} {row['result']:8s} "
              f"(expected {expected}) states {r['states']:>8d} depth {r['depth']:>6d} "
              f"{r['seconds']:.2f} s{('  ' + note) if note else ''}")
        if not ok:
            bad.append(f"{name}: expected {expected}, got {row['result']}"
                       + (f" ({r['violation']})" if r["violation"] else ""))

    def ltl_run(d, name, prop, fair, expected, defines, claim=None):
        r = pan(d, ["-a"] + ([fair] if fair else []) + ["-N", claim or name],
                3000000 if a.model == "four_slot" else 1000000)
        note = ""
        if expected == "holds":
            ok = r["errors"] == 0
        else:
            # the counterexample must be a cycle in which the writer keeps
            # storing Actual and the reader keeps storing ReadLocked
            ok = r["errors"] > 0 and "acceptance cycle" in (r["violation"] or "")
            if ok:
                ok, note = starvation(d, name, defines)
                r["violation"] = r["violation"] + " (writer starves reader)" \
                    if ok else r["violation"]
        record(name, prop, "violated (acceptance cycle)" if expected == "cycle"
               else "holds", r, ok, note)

    if a.variant:
        for name in a.must_fail.split(","):
            if name in ltl:
                prop, fair, _ = ltl[name]
                d = build(a.out, f"{a.variant.lower()}_{name}", [a.variant], False,
                          cflags)
                ltl_run(d, name, prop, fair, "cycle", [a.variant])
                continue
            prop, defines, depth = safety[name]
            defines = [a.variant] + defines
            # four-slot variants breadth-first: a shortest counterexample
            bfs = ["-DBFS"] if a.model == "four_slot" else []
            d = build(a.out, f"{a.variant.lower()}_{name}", defines, True,
                      cflags + bfs)
            r = pan(d, hash_args(defines), depth)
            v = r["violation"] or ""
            # the property's own assertion, not the model's stamp bound
            ok = r["errors"] > 0 and "assertion violated" in v and "s!=" not in v
            extra = {}
            if ok and a.model == "four_slot":
                extra["trail"] = protocol_steps(d, defines)
            record(name, prop, "violated", r, ok,
                   f"-D{a.variant}: {r['violation']}" if ok else "", extra)
    else:
        for name, (prop, defines, depth) in safety.items():
            d = build(a.out, name, defines, True, cflags)
            r = pan(d, hash_args(defines), depth)
            record(name, prop, "holds", r, r["errors"] == 0, "")
        d = build(a.out, "ltl", [], False, cflags) if ltl else None
        for name, (prop, fair, expected) in ltl.items():
            if name in LTL_BUILD:
                claim, defines = LTL_BUILD[name]
                ltl_run(build(a.out, "ltl_" + name, defines, False, cflags),
                        name, prop, fair, expected, defines, claim)
            else:
                ltl_run(d, name, prop, fair, expected, [])

    with open(a.json, "w") as f:
        json.dump(dict(model=f"formal/spin/{a.model}.pml", variant=a.variant,
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
