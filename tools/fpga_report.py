#!/usr/bin/env python3
"""fpga_report.py -- synthesis (and iCE40 place-and-route) figures of the designs on three families.

    tools/fpga_report.py --picorv32 FILE --serv DIR [--designs dpram,controller,picorv32,top]
                         [--families ice40,ecp5,xc7] [--pnr] [--out DIR] [--report JSON]

Designs (files are read with -DSYNTHESIS; parameters as the systems use them):
  dpram       rtl/albatross_dpram.v, ADDR_WIDTH 10 (4 KiB)
  controller  rtl/albatross_controller.v, NB 4, ADDR_WIDTH 10, N_CHAN 16, ROM_WORDS 1024
              (the four-board robot's configuration)
  picorv32    one PicoRV32 as tb/rtl/pico_core.v configures it (rv32i, counters),
              behind fpga/picorv32_ooc.v (only its memory port on pins)
  top         the board top of the family: fpga/icebreaker_top.v (ice40: a
              SERV and a PicoRV32 board), fpga/ulx3s_top.v (ecp5) and
              fpga/arty_top.v (xc7): two PicoRV32 boards; with their DPRAMs,
              the bus and the controller
For each design and family: Yosys synth_ice40 / synth_ecp5 / synth_xilinx
-family xc7 -flatten, counted from `stat -json` (LUTs, flip-flops, carries,
block RAMs, distributed RAMs).  With --pnr, the iCE40 netlists are placed and
routed with nextpnr-ice40: the top on the iCEBreaker's part (UP5K, SG48,
constraints/icebreaker.pcf, the 12 MHz clock), the others out of context on
an HX8K CT256 (enough pins for their ports), each with its Fmax; Debian 12
has no place-and-route for ECP5 or 7-series, so those Fmax are null.  The
top's .asc is kept for icepack (make bitstream).

Prints a table and writes JSON.  Exit status 0; 1 if a run failed (Yosys or
nextpnr error, or the top misses its clock constraint), with the reason;
2 on a usage error.
"""

import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synth_report import FAMILIES, cell_types, count  # noqa: E402

SOC_FILES = ["rtl/albatross_dpram.v", "rtl/albatross_bus.v", "rtl/albatross_controller.v",
             "tb/rtl/board_core.v", "tb/rtl/pico_core.v", "tb/rtl/serv_core.v", "tb/rtl/serv_bridge.v", "tb/rtl/board_memmap.v",
             "tb/rtl/pico_wb_adapter.v", "fpga/albatross_soc.v", "fpga/board_reset.v", "fpga/beat_divider.v"]
TOPS = {"ice40": "icebreaker_top", "ecp5": "ulx3s_top", "xc7": "arty_top"}
TOP_CLOCK_MHZ = {"ice40": 12, "ecp5": 25, "xc7": 100}


def design(name, fam, picorv32, serv):
    """(files, top, chparam) of a design on a family."""
    if name == "dpram":
        return ["rtl/albatross_dpram.v"], "albatross_dpram", "chparam -set ADDR_WIDTH 10 albatross_dpram"
    if name == "controller":
        return (["rtl/albatross_controller.v"], "albatross_controller",
                "chparam -set NB 4 -set ADDR_WIDTH 10 -set N_CHAN 16 -set ROM_WORDS 1024 albatross_controller")
    if name == "picorv32":
        return [picorv32, "fpga/picorv32_ooc.v"], "picorv32_ooc", ""
    top = TOPS[fam]
    return [picorv32] + serv + SOC_FILES + [f"fpga/{top}.v"], top, ""


def run(cmd, log, timeout=1800):
    t0 = time.monotonic()
    with open(log, "w") as f:
        try:
            p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout)
        except subprocess.TimeoutExpired:
            return False, time.monotonic() - t0
        except FileNotFoundError:
            sys.exit(f"fpga_report: {cmd[0]} not found: run `make deps`")
    return p.returncode == 0, time.monotonic() - t0


def tail(log, n=3):
    with open(log, errors="replace") as f:
        lines = [l.strip() for l in f if l.strip()]
    return " | ".join(lines[-n:])


def synth(name, fam, picorv32, serv, out):
    files, top, chparam = design(name, fam, picorv32, serv)
    r = synth_files(files, top, chparam, fam, os.path.join(out, f"{name}_{fam}"))
    return dict({"design": name}, **r)


def synth_files(files, top, chparam, fam, stem):
    """Yosys on one family; the cell counts (or "error"), logs at stem*."""
    spec = FAMILIES[fam]
    script = (f"read_verilog -DSYNTHESIS {' '.join(files)}; {chparam + '; ' if chparam else ''}"
              f"{spec['synth'].format(top=top)}; tee -q -o {stem}_stat.json stat -json"
              + (f"; write_json {stem}.json" if fam == "ice40" else ""))
    ok, secs = run(["yosys", "-q", "-p", script], stem + "_yosys.log")
    r = {"family": fam, "top": top, "yosys_seconds": round(secs, 1)}
    if not ok:
        r["error"] = f"yosys failed: {tail(stem + '_yosys.log')} (log {stem}_yosys.log)"
        return r
    types = cell_types(stem + "_stat.json", top)
    for k in ("luts", "ffs", "carries", "brams", "lutrams"):
        r[k] = count(types, spec[k])
    return r


def pnr(r, out):
    """nextpnr-ice40 on a design synthesised for ice40; adds fmax / utilisation."""
    name, stem = r["design"], os.path.join(out, f"{r['design']}_ice40")
    if name == "top":
        part = ["--up5k", "--package", "sg48", "--pcf", "constraints/icebreaker.pcf",
                "--freq", str(TOP_CLOCK_MHZ["ice40"]), "--asc", stem + ".asc"]
        r["pnr_part"] = "iCE40UP5K-SG48 (iCEBreaker)"
    else:
        part = ["--hx8k", "--package", "ct256", "--pcf-allow-unconstrained", "--freq", "12"]
        r["pnr_part"] = "iCE40HX8K-CT256 (out of context)"
    ok, secs = run(["nextpnr-ice40", "--json", stem + ".json", "--report", stem + "_pnr.json",
                    "--seed", "1"] + part, stem + "_pnr.log")
    r["pnr_seconds"] = round(secs, 1)
    if not ok:
        r["error"] = f"nextpnr-ice40 failed: {tail(stem + '_pnr.log')} (log {stem}_pnr.log)"
        return
    with open(stem + "_pnr.json") as f:
        rep = json.load(f)
    fmax = rep.get("fmax", {})
    r["fmax_mhz"] = round(min(v["achieved"] for v in fmax.values()), 1) if fmax else None
    util = rep.get("utilization", {})
    r["logic_cells"] = util.get("ICESTORM_LC", {}).get("used")
    r["logic_cells_available"] = util.get("ICESTORM_LC", {}).get("available")
    r["brams_available"] = util.get("ICESTORM_RAM", {}).get("available")
    if name == "top":
        r["clock_constraint_mhz"] = TOP_CLOCK_MHZ["ice40"]
        if r["fmax_mhz"] is None or r["fmax_mhz"] < TOP_CLOCK_MHZ["ice40"]:
            r["error"] = (f"expected the iCEBreaker top to meet its {TOP_CLOCK_MHZ['ice40']} MHz clock, "
                          f"got Fmax {r['fmax_mhz']} MHz")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--picorv32", required=True, help="picorv32.v of the PyPI package")
    ap.add_argument("--serv", required=True, help="the rtl/ folder of the PyPI package pythondata-cpu-serv")
    ap.add_argument("--designs", default="dpram,controller,picorv32,top")
    ap.add_argument("--families", default="ice40,ecp5,xc7")
    ap.add_argument("--pnr", action="store_true")
    ap.add_argument("--out", default="build/fpga/synth")
    ap.add_argument("--report", default="build/reports/fpga.json")
    a = ap.parse_args()
    designs = [d for d in a.designs.split(",") if d]
    fams = [f for f in a.families.split(",") if f]
    bad = [d for d in designs if d not in ("dpram", "controller", "picorv32", "top")] + \
          [f for f in fams if f not in FAMILIES]
    if bad:
        ap.error(f"unknown design or family: {', '.join(bad)}")
    if not os.path.isfile(a.picorv32):
        ap.error(f"--picorv32 {a.picorv32}: no such file (run make deps)")
    serv = sorted(os.path.join(a.serv, f) for f in os.listdir(a.serv)
                  if f.startswith("serv_") and f.endswith(".v") and f != "serv_synth_wrapper.v") \
        if os.path.isdir(a.serv) else []
    if not serv:
        ap.error(f"--serv {a.serv}: no serv_*.v there (run make deps)")
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for fam in fams:
        for d in designs:
            print(f"fpga_report: {d} on {fam} ...", flush=True)
            r = synth(d, fam, a.picorv32, serv, a.out)
            if a.pnr and fam == "ice40" and "error" not in r:
                pnr(r, a.out)
            rows.append(r)
    # The goal of the issue: the controller against one PicoRV32, per family.
    ratios = {}
    for fam in fams:
        c = next((r for r in rows if r["design"] == "controller" and r["family"] == fam and "luts" in r), None)
        p = next((r for r in rows if r["design"] == "picorv32" and r["family"] == fam and "luts" in r), None)
        if c and p and p["luts"]:
            ratios[fam] = round(c["luts"] / p["luts"], 3)
    print(f"\n{'design':<11} {'family':<6} {'LUTs':>6} {'FFs':>6} {'carry':>6} {'BRAM':>5} {'LUTRAM':>6} "
          f"{'Fmax MHz':>9}  part")
    for r in rows:
        if "error" in r and "luts" not in r:
            print(f"{r['design']:<11} {r['family']:<6} ERROR {r['error']}")
            continue
        fm = r.get("fmax_mhz")
        print(f"{r['design']:<11} {r['family']:<6} {r['luts']:>6} {r['ffs']:>6} {r['carries']:>6} "
              f"{r['brams']:>5} {r['lutrams']:>6} {fm if fm is not None else '-':>9}  {r.get('pnr_part', '')}")
    for fam, x in ratios.items():
        print(f"controller / PicoRV32 LUTs on {fam}: {x:.3f}")
    os.makedirs(os.path.dirname(a.report) or ".", exist_ok=True)
    with open(a.report, "w") as f:
        json.dump({"rows": rows, "controller_over_picorv32_luts": ratios,
                   "note": "LUTs: SB_LUT4 / LUT4 / LUT1-6; Fmax from nextpnr-ice40 only"}, f, indent=2)
        f.write("\n")
    print(f"fpga_report: {a.report}")
    errors = [f"{r['design']} on {r['family']}: {r['error']}" for r in rows if "error" in r]
    if errors:
        print("fpga_report: FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
