#!/usr/bin/env python3
"""synth_report.py -- Yosys synthesis figures of one RAM module on three FPGA families.

    tools/synth_report.py MODULE [--file FILE.v] [--addr-width 10]
                          [--families ice40,ecp5,xc7] [--require-bram]
                          [--expect-fail [FAMILY,...]] [--full] [--report JSON]

For each family (synth_ice40, synth_ecp5, synth_xilinx -family xc7 -flatten
-noiopad) the module is read with -DSYNTHESIS and `chparam -set ADDR_WIDTH N`,
then synthesised in two steps, both counted from `stat -json`:

  1. up to the memory mapping (`-run :map_ffram`): memory_libmap has chosen
     block RAM, distributed RAM, or nothing.  A $mem_v2 cell still present at
     this point is turned into flip-flops and multiplexers by the next step
     (memory_map): the RAM is left as logic.
  2. the whole script, when step 1 left no memory as logic (or with --full):
     LUTs, flip-flops, carries, block and distributed RAM cells.  A RAM left as
     logic is not synthesised to the end by default: a 4 KiB RAM becomes 32768
     flip-flops and ABC runs for tens of minutes; its figures are then null.

bram_inferred is true only if block RAM cells were used, no memory was left as
logic, and the flip-flop count is small (< --max-ffs, default 200).

Prints a table and writes build/reports/synth_<module>.json.  Yosys logs go to
build/synth/<module>/<family>*.log.  Exit status: 0; 1 with --require-bram
unless every family inferred block RAM ("expected block RAM on <family>, got
..."); with --expect-fail the verdict is inverted: 0 only if the check fails on
each named family (default ice40), for the reason of no block RAM (a Yosys
error is never an expected failure); 2 on a usage or tool error.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

# Family: Yosys script, and how its cells are counted.
FAMILIES = {
    "ice40": {
        "synth": "synth_ice40 -top {top}",
        "luts": lambda t: t == "SB_LUT4",
        "ffs": lambda t: t.startswith("SB_DFF"),
        "carries": lambda t: t == "SB_CARRY",
        "brams": lambda t: t.startswith("SB_RAM40_4K"),
        "lutrams": lambda t: False,
        "bram_names": "SB_RAM40_4K",
    },
    "ecp5": {
        "synth": "synth_ecp5 -top {top}",
        "luts": lambda t: t == "LUT4",
        "ffs": lambda t: t == "TRELLIS_FF",
        "carries": lambda t: t == "CCU2C",
        "brams": lambda t: t in ("DP16KD", "PDPW16KD"),
        "lutrams": lambda t: t.startswith("TRELLIS_DPR16X4"),
        "bram_names": "DP16KD",
    },
    "xc7": {
        "synth": "synth_xilinx -family xc7 -flatten -noiopad -top {top}",
        "luts": lambda t: re.fullmatch(r"LUT[1-6]", t) is not None,
        "ffs": lambda t: re.fullmatch(r"FD[RSCP]E(_1)?", t) is not None,
        "carries": lambda t: t == "CARRY4",
        "brams": lambda t: t in ("RAMB18E1", "RAMB36E1"),
        "lutrams": lambda t: t.startswith("RAM") and not t.startswith("RAMB"),
        "bram_names": "RAMB18E1/RAMB36E1",
    },
}
MEM_CELLS = ("$mem", "$mem_v2")


def find_source(module):
    for d in ("rtl", "soc", "tb/dpram"):
        path = os.path.join(d, module + ".v")
        if os.path.isfile(path):
            return path
    return None


def yosys_quote(path):
    if re.search(r'[\s;"]', path):
        sys.exit("synth_report: unsupported character in path %r" % path)
    return path


def run_yosys(script, log, timeout):
    """Run one Yosys script; return (ok, seconds, message)."""
    t0 = time.monotonic()
    try:
        proc = subprocess.run(["yosys", "-q", "-l", log, "-p", script],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, time.monotonic() - t0, "yosys timed out after %d s" % timeout
    secs = time.monotonic() - t0
    if proc.returncode != 0:
        tail = [l for l in proc.stdout.splitlines() if l.strip()][-3:]
        return False, secs, "yosys exit %d: %s" % (proc.returncode, " | ".join(tail))
    return True, secs, ""


def cell_types(stat_path, top):
    with open(stat_path) as f:
        stat = json.load(f)
    if "design" in stat and "num_cells_by_type" in stat["design"]:
        return stat["design"]["num_cells_by_type"]
    return stat["modules"]["\\" + top]["num_cells_by_type"]


def count(types, pred):
    return sum(n for t, n in types.items() if pred(t))


def mem_bits_left(dump_path):
    """Bits of the $mem_v2 cells in a `dump` of them."""
    bits = 0
    with open(dump_path) as f:
        text = f.read()
    for cell in re.split(r"\n\s*cell ", text)[1:]:
        size = re.search(r"parameter \\SIZE (\d+)", cell)
        width = re.search(r"parameter \\WIDTH (\d+)", cell)
        if size and width:
            bits += int(size.group(1)) * int(width.group(1))
    return bits


def warnings_of(log):
    seen = []
    with open(log, errors="replace") as f:
        for line in f:
            line = line.strip()
            if line.startswith("Warning:") and line not in seen:
                seen.append(line)
    return seen


def synth_family(fam, src, top, aw, outdir, args):
    spec = FAMILIES[fam]
    synth = spec["synth"].format(top=top)
    head = "read_verilog -DSYNTHESIS -Irtl %s; chparam -set ADDR_WIDTH %d %s; " % (
        " ".join(yosys_quote(f) for f in src.split(",")), aw, top)
    r = {"script": head + synth, "luts": None, "ffs": None, "carries": None,
         "brams": None, "lutrams": None, "logic_ram_bits": None,
         "mem_cells_left": None, "bram_inferred": False, "full_synthesis": False,
         "error": None, "warnings": [], "yosys_seconds": 0.0}

    # Step 1: up to the memory mapping.
    log1 = os.path.join(outdir, fam + "_memory.log")
    st1 = os.path.join(outdir, fam + "_memory_stat.json")
    dump1 = os.path.join(outdir, fam + "_memory_left.txt")
    il1 = os.path.join(outdir, fam + "_memory.il")
    ok, secs, msg = run_yosys(head + synth + " -run :map_ffram; "
                              "tee -q -o %s stat -json; tee -q -o %s dump t:$mem_v2; write_rtlil %s"
                              % (st1, dump1, yosys_quote(il1)), log1, args.timeout)
    r["yosys_seconds"] += secs
    if not ok:
        r["error"] = msg + " (log %s)" % log1
        return r
    types1 = cell_types(st1, top)
    r["logic_ram_bits"] = mem_bits_left(dump1)
    r["brams"] = count(types1, spec["brams"])
    r["lutrams"] = count(types1, spec["lutrams"])
    r["warnings"] = warnings_of(log1)

    # Step 2: the rest of the script, on the design step 1 left (the cell
    # library it read included), unless it would only grind a RAM into FFs.
    if r["logic_ram_bits"] and not args.full:
        r["note"] = ("memory left as logic (%d bits, no block/distributed RAM mapping): "
                     "full synthesis skipped, use --full" % r["logic_ram_bits"])
        return r
    log2 = os.path.join(outdir, fam + ".log")
    st2 = os.path.join(outdir, fam + "_stat.json")
    ok, secs, msg = run_yosys("read_rtlil %s; %s -run map_ffram:; tee -q -o %s stat -json"
                              % (yosys_quote(il1), synth, st2), log2, args.timeout)
    r["yosys_seconds"] += secs
    if not ok:
        r["error"] = msg + " (log %s)" % log2
        return r
    types = cell_types(st2, top)
    r["full_synthesis"] = True
    r["cells"] = dict(sorted(types.items()))
    for k in ("luts", "ffs", "carries", "brams", "lutrams"):
        r[k] = count(types, spec[k])
    r["mem_cells_left"] = count(types, lambda t: t in MEM_CELLS)
    r["warnings"] = warnings_of(log2)
    r["bram_inferred"] = (r["brams"] > 0 and r["logic_ram_bits"] == 0
                          and r["mem_cells_left"] == 0 and r["ffs"] < args.max_ffs)
    return r


def bram_failure(fam, r, max_ffs):
    """Why fam did not infer block RAM, or None if it did."""
    if r["bram_inferred"]:
        return None
    if r["error"]:
        return "expected block RAM on %s, got a Yosys error: %s" % (fam, r["error"])
    got = ["%d %s" % (r["brams"], FAMILIES[fam]["bram_names"])]
    if r["logic_ram_bits"]:
        got.append("%d RAM bits left as logic (flip-flops)" % r["logic_ram_bits"])
    if r["lutrams"]:
        got.append("%d distributed-RAM cells" % r["lutrams"])
    if r["mem_cells_left"]:
        got.append("%d unmapped $mem cells" % r["mem_cells_left"])
    if r["ffs"] is not None and r["ffs"] >= max_ffs:
        got.append("%d flip-flops (limit %d)" % (r["ffs"], max_ffs))
    return "expected block RAM on %s, got %s" % (fam, ", ".join(got))


def write_json(path, obj):
    """Write a report: its folder made, the file replaced whole (never left half
    written).  The temporary file is this process's own, so that tests running
    in parallel that rewrite one shared report (formal_sby.json) never rename
    each other's file away."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)


def fmt(v):
    return "-" if v is None else str(v)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("module")
    ap.add_argument("--file", help="Verilog source (default rtl/, soc/ or tb/dpram/MODULE.v); "
                    "several as a comma-separated list (a wrapper and its core)")
    ap.add_argument("--addr-width", type=int, default=10)
    ap.add_argument("--families", default="ice40,ecp5,xc7")
    ap.add_argument("--require-bram", action="store_true",
                    help="exit 1 unless every family inferred block RAM")
    ap.add_argument("--expect-fail", nargs="?", const="ice40", metavar="FAMILIES",
                    help="negative test: pass only if --require-bram fails on these "
                         "families (default ice40)")
    ap.add_argument("--full", action="store_true",
                    help="synthesise to the end even a RAM left as logic (slow)")
    ap.add_argument("--max-ffs", type=int, default=200)
    ap.add_argument("--timeout", type=int, default=600, help="seconds per Yosys run")
    ap.add_argument("--build", default="build")
    ap.add_argument("--report", help="JSON output (default build/reports/synth_MODULE.json)")
    args = ap.parse_args()

    if shutil.which("yosys") is None:
        print("synth_report: yosys not found: run `make deps` (installs Debian's yosys)")
        return 2
    families = [f for f in args.families.split(",") if f]
    expect = [f for f in (args.expect_fail or "").split(",") if f]
    for f in families + expect:
        if f not in FAMILIES:
            print("synth_report: unknown family %r (known: %s)" % (f, ", ".join(FAMILIES)))
            return 2
    for f in expect:
        if f not in families:
            families.append(f)
    src = args.file or find_source(args.module)
    if not src or not all(os.path.isfile(f) for f in src.split(",")):
        print("synth_report: no source for module %s (give --file)" % args.module)
        return 2

    outdir = os.path.join(args.build, "synth", args.module)
    os.makedirs(outdir, exist_ok=True)
    report = args.report or os.path.join(args.build, "reports", "synth_%s.json" % args.module)

    try:
        version = subprocess.run(["yosys", "-V"], stdout=subprocess.PIPE,
                                 text=True).stdout.strip()
    except OSError as e:
        print("synth_report: cannot run yosys (%s): run `make deps`" % e)
        return 2

    results = {}
    for fam in families:
        results[fam] = synth_family(fam, src, args.module, args.addr_width, outdir, args)

    print("%s (%s, ADDR_WIDTH=%d, %d bytes), %s" % (
        args.module, src, args.addr_width, 4 << args.addr_width, version))
    print("%-6s %6s %6s %6s %7s %7s %11s %6s %5s" % (
        "family", "LUTs", "FFs", "carry", "BRAMs", "LUTRAM", "logic RAM", "BRAM?", "s"))
    for fam, r in results.items():
        print("%-6s %6s %6s %6s %7s %7s %11s %6s %5.1f" % (
            fam, fmt(r["luts"]), fmt(r["ffs"]), fmt(r["carries"]), fmt(r["brams"]),
            fmt(r["lutrams"]), fmt(r["logic_ram_bits"]),
            "yes" if r["bram_inferred"] else "NO", r["yosys_seconds"]))
    for fam, r in results.items():
        for w in r["warnings"]:
            print("  %s: %s" % (fam, w))
        if r.get("note"):
            print("  %s: %s" % (fam, r["note"]))
        if r["error"]:
            print("  %s: ERROR %s" % (fam, r["error"]))

    out = {"module": args.module, "source": src, "addr_width": args.addr_width,
           "bytes": 4 << args.addr_width, "yosys": version, "max_ffs": args.max_ffs,
           "families": results}
    write_json(report, out)
    print("report: %s" % report)

    failures = {fam: bram_failure(fam, r, args.max_ffs) for fam, r in results.items()}
    if args.expect_fail is not None:
        ok = True
        for fam in expect:
            r = results[fam]
            if r["error"]:
                print("FAIL: %s: Yosys error, not an expected block-RAM failure: %s"
                      % (fam, r["error"]))
                ok = False
            elif failures[fam] is None:
                print("FAIL: the checker did not catch %s: block RAM inferred on %s"
                      % (args.module, fam))
                ok = False
            else:
                print("caught on %s: %s" % (fam, failures[fam]))
        for fam in families:
            if fam not in expect:
                print("(%s: %s)" % (fam, failures[fam] or "block RAM inferred"))
        if ok:
            print("OK: --require-bram fails for %s on %s, as expected"
                  % (args.module, ", ".join(expect)))
        return 0 if ok else 1
    errors = [r["error"] for r in results.values() if r["error"]]
    if args.require_bram:
        bad = [m for m in failures.values() if m]
        for m in bad:
            print(m)
        if bad:
            return 1
        print("OK: block RAM inferred on %s" % ", ".join(families))
    return 2 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
