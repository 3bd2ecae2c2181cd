#!/usr/bin/env python3
"""controller_ladder.py -- what each function of the controller's core configuration costs:
the core configuration synthesised again with one function more taken out at each rung.

    tools/controller_ladder.py [--families ice40,xc7] [--rtl DIR] [--out DIR]
                               [--report JSON] [--area JSON] [--jobs N] [--check]

Rung 0 is the core configuration of `make area` (HAS_STATUS, HAS_SYNC,
HAS_ROM_RECHECK, HAS_ENTRY_CHECK and HAS_MODES 0; NB 4, ADDR_WIDTH 10, N_CHAN 16, the
robot's ROM image).  Each later rung takes one more function out of a copy
of rtl/ by a literal edit of one line (LADDER below: each edit must match
exactly once, or the tool stops naming the rung), so rung k has none of the
functions of rungs 1..k.  What a rung saves is the difference to the rung
before, in LUTs of the same run; the functions are taken out in the order
listed, and a saving depends a little on that order (logic two functions
share goes with the first one out).  The last rung is the sequencer with the
three-buffer COPY to one destination, its retries and the global time: the
functions a controller cannot do without.

The edits measure; they are not designs.  A rung's copy is not a working
controller (a ROM check that always passes, a TIME entry treated as a COPY):
it shows where the logic of the working one goes, by function rather than
by module (the parts table of `make area` is by module).

--check applies every rung's edits to a copy and elaborates each rung with
Yosys (`hierarchy -check`), without synthesis: a change to rtl/ that
breaks an edit fails there, in seconds, naming the rung (make test).

Prints a table; writes build/reports/controller_ladder.json (with each
rung's LUTs over one PicoRV32 when --area names a controller_area.json of
the same run that has PicoRV32's LUTs).  Exit status 0; 1 if an edit no
longer matches or a synthesis fails, with the reason; 2 on a usage error.
"""

import argparse
import concurrent.futures
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from controller_area import BASE, FEATURES, GOALS, TOP, chparam  # noqa: E402
from fpga_report import CTRL_FILES, ROBOT_ROM, run, synth_files, tail  # noqa: E402
from synth_report import FAMILIES, write_json  # noqa: E402

CORE = dict(BASE, **{p: 0 for p, _ in FEATURES})
ELAB_TIMEOUT = 300   # seconds for one rung's elaboration (it takes about 2)

# (name, what is taken out, [(rtl file, the line's text, its replacement)]).
LADDER = [
    ("start-up CRC", "the ROM's CRC: its step (4 bits a clock), its register and its test for zero (the pass still runs)",
     [("albatross_rom_check.v", "assign crc_ok_o = crc_q == 32'd0;", "assign crc_ok_o = 1'b1;")]),
    ("four-slot kind", "the four-slot channels: Simpson's picks and the Import's match, the Slot store, the whole-word source loads",
     [("albatross_controller.v", ".four_i(four)", ".four_i(1'b0)")]),
    ("TIME and STATUS kinds", "the entries that publish the slot time and the (zero) STATUS words: every entry a COPY",
     [("albatross_controller.v", ".copy_i(k_copy), .time_kind_i(k_time)", ".copy_i(1'b1), .time_kind_i(1'b0)")]),
    ("taken_at", "the value's taken_at: its state RAM field and its store data (the store itself stays)",
     [("albatross_controller.v", ".st_taken_i(st_taken)", ".st_taken_i(32'd0)")]),
    ("drop run", "the drop of a destination after K failed attempts in a row (retries until the deadline stay)",
     [("albatross_transfer_fsm.v", "drop_q  <= dst && run_inc == k_run;", "drop_q  <= 1'b0;")]),
    ("destinations 2 to 4", "every entry has one destination: no order among destinations, one set of their registers",
     [("albatross_controller.v",
       "wire [3:0]         active = {nd[2], nd >= 3'd3, nd >= 3'd2, nd != 3'd0};",
       "wire [3:0]         active = 4'b0001;")]),
]


def say(msg):
    print(f"controller_ladder: {msg}", flush=True)


def make_rungs(rtl, out):
    """Copies of rtl/ for rungs 1..N, each with its own edits and all earlier ones; errors as strings."""
    rungs, errors = [], []
    prev = rtl
    for i, (name, _, edits) in enumerate(LADDER, 1):
        d = os.path.join(out, f"rung{i}", "rtl")
        shutil.rmtree(os.path.dirname(d), ignore_errors=True)
        shutil.copytree(prev, d)
        for fname, old, new in edits:
            path = os.path.join(d, fname)
            try:
                with open(path) as f:
                    text = f.read()
            except OSError as e:
                errors.append(f"rung {i} ({name}): {fname}: {e.strerror}")
                continue
            hits = text.count(old)
            if hits != 1:
                errors.append(f"rung {i} ({name}): expected the text `{old}` once in {fname}, found it {hits} times: "
                              f"update LADDER in tools/controller_ladder.py to the RTL")
                continue
            with open(path, "w") as f:
                f.write(text.replace(old, new))
        rungs.append(d)
        prev = d
    return rungs, errors


def files_of(d):
    return [os.path.join(d, os.path.relpath(f, "rtl")) for f in CTRL_FILES]


def elaborate(d, stem):
    script = (f"read_verilog -DSYNTHESIS -I{d} {' '.join(files_of(d))}; {chparam(CORE)}; "
              f"hierarchy -check -top {TOP}")
    ok, secs = run(["yosys", "-q", "-p", script], stem + "_elab.log", timeout=ELAB_TIMEOUT)
    if ok:
        return None
    return f"yosys stopped after {ELAB_TIMEOUT} s" if secs >= ELAB_TIMEOUT else tail(stem + "_elab.log")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--families", default="ice40,xc7")
    ap.add_argument("--rtl", default="rtl", help="the RTL folder the rungs are copies of")
    ap.add_argument("--out", default="build/fpga/ladder")
    ap.add_argument("--report", default="build/reports/controller_ladder.json")
    ap.add_argument("--area", default="build/reports/controller_area.json",
                    help="controller_area.json of the same run, for PicoRV32's LUTs")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--check", action="store_true", help="apply and elaborate only")
    a = ap.parse_args()
    fams = [f for f in a.families.split(",") if f]
    bad = [f for f in fams if f not in FAMILIES]
    if bad or not fams:
        ap.error(f"unknown family: {', '.join(bad) or '(none)'}; known: {', '.join(FAMILIES)}")
    if not os.path.isdir(a.rtl):
        ap.error(f"--rtl {a.rtl}: no such folder")
    if not a.check and not os.path.isfile(ROBOT_ROM):
        ap.error(f"{ROBOT_ROM}: no such file (make {ROBOT_ROM})")
    if not 1 <= a.jobs <= 2:
        ap.error("--jobs must be 1 or 2")
    os.makedirs(a.out, exist_ok=True)
    rungs, errors = make_rungs(a.rtl, a.out)
    if errors:
        for e in errors:
            say("FAIL: " + e)
        return 1
    dirs = [a.rtl] + rungs

    if a.check:
        fails = []
        for i, d in enumerate(dirs):
            why = elaborate(d, os.path.join(a.out, f"rung{i}"))
            name = "core" if i == 0 else LADDER[i - 1][0]
            say(f"rung {i} ({name}): " + ("elaborates" if why is None else f"does not elaborate: {why}"))
            if why is not None:
                fails.append(f"rung {i} ({name}) does not elaborate: {why}")
        if fails:
            say("FAIL: " + "; ".join(fails))
            return 1
        say(f"{len(LADDER)} rungs apply to {a.rtl} and elaborate")
        return 0

    say(f"{len(dirs) * len(fams)} syntheses of the core configuration ({len(dirs)} rungs x {', '.join(fams)}), "
        f"{a.jobs} at a time; each takes 5 to 30 s")
    res = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futs = {pool.submit(synth_files, files_of(d), TOP, chparam(CORE), fam,
                            os.path.join(a.out, f"rung{i}_{fam}")): (i, fam)
                for i, d in enumerate(dirs) for fam in fams}
        for k, fut in enumerate(concurrent.futures.as_completed(futs), 1):
            i, fam = futs[fut]
            res[(i, fam)] = r = fut.result()
            say(f"[{k}/{len(futs)}] rung {i} on {fam}: {r.get('luts', 'ERROR')} LUTs")

    pico = {}
    if os.path.isfile(a.area):
        with open(a.area) as f:
            pico = {k: v for k, v in json.load(f).get("picorv32_luts", {}).items() if v}
    rows = []
    for i in range(len(dirs)):
        name, what = ("core", "the core configuration of make area") if i == 0 else LADDER[i - 1][:2]
        row = {"rung": i, "name": name, "taken_out": what, "luts": {}, "saved": {}, "over_picorv32": {}}
        for fam in fams:
            r = res[(i, fam)]
            if "error" in r:
                row.setdefault("error", {})[fam] = r["error"]
                continue
            row["luts"][fam] = r["luts"]
            if i > 0 and "luts" in res[(i - 1, fam)]:
                row["saved"][fam] = res[(i - 1, fam)]["luts"] - r["luts"]
            if fam in pico:
                row["over_picorv32"][fam] = round(r["luts"] / pico[fam], 3)
        rows.append(row)

    print(f"\n{'rung':<4} {'taken out':<24}" + "".join(f"{fam:>8}{'saved':>7}{'/Pico':>7}" for fam in fams))
    for row in rows:
        line = f"{row['rung']:<4} {row['name']:<24}"
        for fam in fams:
            line += f"{row['luts'].get(fam, 'ERR'):>8}{row['saved'].get(fam, '-'):>7}" + \
                (f"{row['over_picorv32'][fam]:>7.2f}" if fam in row["over_picorv32"] else f"{'-':>7}")
        print(line)
    goals = {f: GOALS["core"][f] for f in fams if f in GOALS["core"]}
    if pico:
        print("core target, LUTs: " + ", ".join(f"{f} {round(goals[f] * pico[f])} ({goals[f]:.2f} of one PicoRV32)"
                                                  for f in goals if f in pico))
    errors = [f"rung {i} on {fam}: {r['error']}" for (i, fam), r in sorted(res.items()) if "error" in r]
    write_json(a.report, {"base": dict(CORE, ROM_FILE=ROBOT_ROM), "families": fams, "rows": rows,
                          "picorv32_luts": pico, "core_goals_over_picorv32": goals,
                          "note": "each rung: the core configuration with its function and every earlier rung's "
                                  "taken out by a literal edit of a copy of rtl/ (tools/controller_ladder.py)"})
    say(a.report)
    if errors:
        say("FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
