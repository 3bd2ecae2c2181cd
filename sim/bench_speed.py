#!/usr/bin/env python3
"""bench_speed.py --report FILE --verilator-cycles N --verilator CMD --icarus-cycles M --icarus CMD

Simulated cycles per second of wall time for the whole four-board system
(make bench-sim-speed): CMD under Verilator (sim/mobot_sim.cpp, all checks
on) and under Icarus Verilog (sim/pico_boards_tb.v), each run once in
this process, one after the other, so the ratio compares like with like on
one machine.  Each run must succeed (exit 0; the Icarus run must report no
trap, no bus error, no controller error), else the bench fails.  Prints the
figures and writes them to FILE.  Standard library only.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time


def run(name, cmd):
    t0 = time.perf_counter()
    p = subprocess.run(shlex.split(cmd), capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit(f"bench_speed: the {name} run failed (exit {p.returncode}):\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    return wall, p.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--report", required=True)
    ap.add_argument("--verilator", required=True)
    ap.add_argument("--verilator-cycles", type=int, required=True)
    ap.add_argument("--icarus", required=True)
    ap.add_argument("--icarus-cycles", type=int, required=True)
    a = ap.parse_args()
    vw, _ = run("Verilator", a.verilator)
    iw, out = run("Icarus", a.icarus)
    m = re.search(r"pico_boards_tb: (\d+) cycles.*trap (\d+), bus error (\d+), error (\d)", out)
    if not m or int(m[1]) != a.icarus_cycles or set(m[2] + m[3] + m[4]) != {"0"}:
        sys.exit(f"bench_speed: expected the Icarus run to end healthy after {a.icarus_cycles} cycles, got:\n{out[-1000:]}")
    v_rate, i_rate = a.verilator_cycles / vw, a.icarus_cycles / iw
    rep = {"verilator_cycles": a.verilator_cycles, "verilator_wall_s": round(vw, 3),
           "verilator_cycles_per_s": round(v_rate), "icarus_cycles": a.icarus_cycles,
           "icarus_wall_s": round(iw, 3), "icarus_cycles_per_s": round(i_rate),
           "verilator_over_icarus": round(v_rate / i_rate, 1)}
    os.makedirs(os.path.dirname(a.report) or ".", exist_ok=True)
    with open(a.report, "w") as f:
        json.dump(rep, f, indent=2)
        f.write("\n")
    print(f"whole system (4 PicoRV32 boards, controller, 4 DPRAMs): Verilator {v_rate:,.0f} cycles/s "
          f"({a.verilator_cycles} cycles, checks on), Icarus {i_rate:,.0f} cycles/s ({a.icarus_cycles} cycles); "
          f"Verilator / Icarus = {v_rate / i_rate:.1f}")
    print(f"bench_speed: {a.report}")


if __name__ == "__main__":
    main()
