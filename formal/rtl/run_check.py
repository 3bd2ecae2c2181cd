#!/usr/bin/env python3
"""run_check.py -- one bounded proof of an RTL property wrapper (tools/mk/formal_rtl.mk).

    run_check.py NAME --engine smtbmc|abc --top TOP --src FILE... [--define D]
                 --depth N --props P1,P2 [--reach R1,R2] --expect pass|LABEL

Engines:
  smtbmc  yosys -> write_smt2 -> yosys-smtbmc -s z3 --unroll --logic QF_BV (the
          albatross_dpram wrapper): one BMC run over all assertions, the failed
          ones reported by label, a VCD of the counterexample (--dump-vcd), and
          a cover run (-c) that must reach every cover.
  abc     yosys -> write_aiger -> yosys-abc bmc3 (the controller harness: z3
          could not unroll it to the depth of two slots in minutes).  One AIG
          per assertion, so a failure is named; the REACH assertions (built with
          -DREACH) must each fail, showing the proof is not vacuous.
--expect pass: every property holds to the depth.  --expect LABEL: the proof must
fail, and LABEL (or one of L1|L2) must be among the failed properties.  Each run writes
build/formal/rtl/NAME/result.json and merges all of them into
build/reports/formal_rtl.json (property, result, depth, seconds per check).
"""
import argparse, glob, json, os, re, subprocess, sys, time

OUT = "build/formal/rtl"
REPORT = "build/reports/formal_rtl.json"


def sh(cmd, log):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        f.write(p.stdout)
    return p.returncode, p.stdout


def reads(a, extra_define=None):
    ds = " ".join("-D" + d for d in (a.define + ([extra_define] if extra_define else [])))
    # Yosys 0.23 gives a memory's for-loop zero fill a higher priority than a
    # later $readmemh of the same words (the controller's ROM would read as all
    # zero): drop the one-word $meminit cells, the $readmemh image stays.
    # -Irtl: rtl/albatross_contract.vh, also for a mutant copied outside rtl/.
    return "; ".join(f"read_verilog {ds} -DSYNTHESIS -formal -Irtl {s}" for s in a.src) + \
        f"; hierarchy -top {a.top}; proc; delete t:$meminit_v2 r:WORDS=1 %i"


def run_smtbmc(a, d, log):
    smt = os.path.join(d, "model.smt2")
    rc, out = sh(["yosys", "-q", "-p", reads(a) + f"; prep -top {a.top}; memory_map; opt; "
                  f"async2sync; dffunmap; write_smt2 -wires {smt}"], log)
    if rc:
        return None, "yosys failed (see " + log + ")", {}
    rc, out = sh(["yosys-smtbmc", "--noprogress", "-s", "z3", "--unroll", "--logic", "QF_BV",
                  "-t", str(a.depth), "--dump-vcd", os.path.join(d, "cex.vcd"), smt], log)
    failed = set(re.findall(r"Assert failed in \S+: (\w+)", out))
    fail_step = re.findall(r"Checking assertions in step (\d+)", out)
    res = {p: ("fail" if p in failed else "pass") for p in a.props}
    status = "FAILED" if "Status: FAILED" in out else ("PASSED" if "Status: PASSED" in out else "ERROR")
    if status == "ERROR":
        return None, "yosys-smtbmc gave no status (see " + log + ")", res
    info = {"failed": sorted(failed), "step": int(fail_step[-1]) if (failed and fail_step) else None}
    if status == "PASSED" and a.expect == "pass":
        rc, out = sh(["yosys-smtbmc", "--noprogress", "-s", "z3", "--unroll", "--logic", "QF_BV",
                      "-c", "-t", str(a.depth), smt], log)
        unreached = re.findall(r"Unreached cover statement at (\S+)", out)
        info["covers"] = "reached" if "Status: PASSED" in out else "unreached: " + " ".join(unreached)
    return status, info, res


def run_abc(a, d, log):
    res, steps, info = {}, {}, {}

    def one(prop, define):
        aig = os.path.join(d, prop + ".aig")
        rc, _ = sh(["yosys", "-q", "-p", reads(a, define) + f"; prep -top {a.top}; flatten; "
                    f"chformal -cover -remove; select -set keep {a.top}/{prop}; "
                    "chformal -assert -remove t:$assert @keep %d; memory_map; opt -full; async2sync; "
                    "techmap; opt -fast; dffunmap; abc -g AND; opt_clean; "
                    f"write_aiger -zinit {aig}"], log)
        if rc:
            return "error", None
        rc, out = sh(["yosys-abc", "-c", f"read_aiger {aig}; fold; bmc3 -F {a.depth}; "
                      f"write_cex {os.path.join(d, prop + '.cex')}"], log)
        m = re.search(r"was asserted in frame (\d+)", out)
        if m:
            return "fail", int(m.group(1))
        if re.search(r"No output asserted in (\d+) frames", out):
            return "pass", None
        return "error", None

    for p in a.props:
        res[p], steps[p] = one(p, None)
    info["failed"] = sorted(p for p in res if res[p] == "fail")
    info["frames"] = {p: steps[p] for p in steps if steps[p] is not None}
    if any(v == "error" for v in res.values()):
        return None, "yosys or abc failed (see " + log + ")", res
    if a.expect == "pass" and a.reach:
        reached = {}
        for r in a.reach:
            v, f = one(r, "REACH")
            reached[r] = f if v == "fail" else "unreached"
        info["reach"] = reached
    return ("FAILED" if info["failed"] else "PASSED"), info, res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("--engine", choices=["smtbmc", "abc"], required=True)
    ap.add_argument("--top", required=True)
    ap.add_argument("--src", nargs="+", required=True)
    ap.add_argument("--define", action="append", default=[])
    ap.add_argument("--depth", type=int, required=True)
    ap.add_argument("--props", required=True)
    ap.add_argument("--reach", default="")
    ap.add_argument("--expect", required=True)
    a = ap.parse_args()
    a.props = a.props.split(",")
    a.reach = [r for r in a.reach.split(",") if r]
    d = os.path.join(OUT, a.name)
    os.makedirs(d, exist_ok=True)
    log = os.path.join(d, "log.txt")
    open(log, "w").close()
    t0 = time.time()
    status, info, res = (run_smtbmc if a.engine == "smtbmc" else run_abc)(a, d, log)
    secs = round(time.time() - t0, 1)
    ok, msg = False, ""
    if status is None:
        msg = info
    elif a.expect == "pass":
        bad = [k for k, v in (info.get("reach") or {}).items() if v == "unreached"]
        if status != "PASSED":
            msg = f"expected every property to hold to depth {a.depth}, came failures: {', '.join(info['failed'])}"
        elif info.get("covers", "reached") != "reached" or bad:
            msg = f"properties hold, but the proof is vacuous: {info.get('covers', '')} {' '.join(bad)}"
        else:
            ok = True
            msg = f"{', '.join(a.props)} hold to depth {a.depth} ({a.engine}, {secs} s)"
    else:
        want = a.expect.split("|")
        hit = [w for w in want if w in info["failed"]]
        if status == "FAILED" and hit:
            ok = True
            msg = f"the proof caught the broken variant with {hit[0]}, as expected (failed: {', '.join(info['failed'])})"
        else:
            msg = f"expected the proof to fail on {a.expect}, came {status} (failed: {', '.join(info.get('failed', [])) or 'none'})"
    rec = {"check": a.name, "engine": a.engine, "top": a.top, "defines": a.define, "depth": a.depth,
           "expect": a.expect, "properties": res, "detail": info if isinstance(info, dict) else {},
           "seconds": secs, "ok": ok}
    with open(os.path.join(d, "result.json"), "w") as f:
        json.dump(rec, f, indent=1)
    allr = []
    for p in sorted(glob.glob(os.path.join(OUT, "*", "result.json"))):
        with open(p) as f:
            allr.append(json.load(f))
    os.makedirs(os.path.dirname(REPORT), exist_ok=True)
    with open(REPORT, "w") as f:
        json.dump({"checks": allr}, f, indent=1)
    print(msg)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
