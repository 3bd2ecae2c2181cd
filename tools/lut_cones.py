#!/usr/bin/env python3
"""lut_cones.py -- where the LUTs of a flattened iCE40 netlist go: each SB_LUT4 is
counted toward the registers, block RAMs and output ports its output reaches
through LUTs and carry cells (its cone's ends), split evenly among them.

    tools/lut_cones.py NETLIST.json [--top MODULE] [--rows N]
    tools/lut_cones.py --self-test

NETLIST.json is Yosys's write_json of a design synthesised with
synth_ice40 -flatten.  A register is named by the net its Q drives: of the
net's names, one whose last part ends in _q (the project's register names),
else the shortest; a block RAM by its cell name without Yosys's ".row.col"
suffix (all its 4-kbit blocks together); an output port as "port NAME".  Bit
indices are dropped, so a register's bits count together.  A LUT that reaches
no end (Yosys keeps none) is counted as "(no end)".

The shares add up to the netlist's SB_LUT4 count; a LUT shared by two
registers counts half to each, so a register's figure is what its logic costs
where the design shares nothing with it, not what taking it out would save
(the ablations of tools/controller_ladder.py measure that).

Prints the N largest (default 20) and the rest as one row; exit status 0,
2 on a usage error or an unreadable netlist.  --self-test synthesises a small
design with Yosys (two registers that share no logic, one output port) and
checks the attribution: the shares add up to its SB_LUT4 count, and each
register and the port gets the LUTs of its own logic; exit status 1 with what
was expected and what came if not.
"""

import argparse
import collections
import json
import os
import re
import subprocess
import sys
import tempfile

COMB = ("SB_LUT4", "SB_CARRY")


def _reg_name(names):
    """The most telling of a net's names (see the head comment)."""
    clean = [n for n in names if not n.startswith("$")]
    if not clean:
        return None
    regs = [n for n in clean if n.split(".")[-1].endswith("_q")]
    return min(regs or clean, key=len)


def cones(netlist, top=None):
    """[(end, LUTs)] of one module of a write_json netlist, largest first; the shares
    add up to its SB_LUT4 count."""
    mods = netlist["modules"]
    if top is None:
        tops = [m for m, v in mods.items() if v.get("attributes", {}).get("top")]
        top = tops[0] if len(tops) == 1 else None
    if top not in mods:
        raise ValueError(f"no module {top!r} in the netlist (give --top)")
    m = mods[top]
    names = collections.defaultdict(list)
    for n, v in m["netnames"].items():
        for b in v["bits"]:
            if isinstance(b, int):
                names[b].append(re.sub(r"\[\d+\]$", "", n))
    readers = collections.defaultdict(list)
    cells = m["cells"]
    for cn, c in cells.items():
        for p, bits in c["connections"].items():
            if c["port_directions"].get(p) == "input":
                for b in bits:
                    if isinstance(b, int):
                        readers[b].append(cn)
    port_of = {}
    for pn, pv in m["ports"].items():
        if pv["direction"] == "output":
            for b in pv["bits"]:
                if isinstance(b, int):
                    port_of[b] = "port " + pn

    def end_name(cn):
        c = cells[cn]
        if c["type"].startswith("SB_DFF"):
            q = c["connections"]["Q"][0]
            return _reg_name(names.get(q, [])) or cn
        return re.sub(r"(\.\d+)+$", "", cn)

    memo = {}

    def ends(cn):
        if cn in memo:
            return memo[cn]
        memo[cn] = set()        # a combinational loop ends here
        res = set()
        c = cells[cn]
        for p, bits in c["connections"].items():
            if c["port_directions"].get(p) != "output":
                continue
            for b in bits:
                if b in port_of:
                    res.add(port_of[b])
                for r in readers.get(b, []):
                    res |= ends(r) if cells[r]["type"] in COMB else {end_name(r)}
        memo[cn] = res
        return res

    sys.setrecursionlimit(max(10000, 4 * len(cells)))
    share = collections.Counter()
    for cn, c in cells.items():
        if c["type"] == "SB_LUT4":
            e = ends(cn)
            for x in e or {"(no end)"}:
                share[x] += 1.0 / max(1, len(e))
    return sorted(share.items(), key=lambda kv: -kv[1])


SELF_TEST_TIMEOUT = 300   # seconds for Yosys on the test design (it takes about 1)
SELF_TEST_V = """
module cones_t (input wire clk, input wire [7:0] x, input wire [7:0] y, input wire [7:0] w,
                output reg [7:0] sum_q, output reg [7:0] par_q, output wire [7:0] mix_o);
    always @(posedge clk) sum_q <= x + y;             // an adder: a LUT and a carry a bit
    always @(posedge clk) par_q <= w ^ {w[6:0], w[7]}; // a LUT a bit, on inputs the adder does not read
    assign mix_o = w & {w[0], w[7:1]};                  // a LUT a bit, to a port
endmodule
"""


def self_test():
    with tempfile.TemporaryDirectory() as d:
        src, net = os.path.join(d, "t.v"), os.path.join(d, "t.json")
        with open(src, "w") as f:
            f.write(SELF_TEST_V)
        try:
            p = subprocess.run(["yosys", "-q", "-p", f"read_verilog {src}; synth_ice40 -top cones_t -flatten; "
                                f"write_json {net}"], capture_output=True, text=True, timeout=SELF_TEST_TIMEOUT)
        except subprocess.TimeoutExpired:
            print(f"lut_cones self-test: expected Yosys to synthesise the test design within {SELF_TEST_TIMEOUT} s, "
                  "it did not finish")
            return 1
        if p.returncode:
            print(f"lut_cones self-test: yosys failed: {p.stderr.strip()[-300:]}")
            return 1
        with open(net) as f:
            nl = json.load(f)
    bad = _check("the synthesised design", nl, "cones_t", {"sum_q": 8, "par_q": 8, "port mix_o": 8})
    # A shared LUT, written by hand (Yosys may duplicate one): L1 feeds a_q
    # and b_q, L2 feeds a_q through L3; so a_q 1/2 + 1 + 1, b_q 1/2.
    def cell(t, ins, outs):
        conns = dict({p: [b] for p, b in ins.items()}, **{p: [b] for p, b in outs.items()})
        return {"type": t, "port_directions": dict({p: "input" for p in ins}, **{p: "output" for p in outs}),
                "connections": conns}
    hand = {"modules": {"h": {"ports": {}, "netnames": {"a_q": {"bits": [10]}, "b_q": {"bits": [11]}}, "cells": {
        "L1": cell("SB_LUT4", {"I0": 2}, {"O": 3}), "L2": cell("SB_LUT4", {"I0": 2}, {"O": 4}),
        "L3": cell("SB_LUT4", {"I0": 4}, {"O": 5}),
        "FA": cell("SB_DFF", {"D": 3}, {"Q": 10}), "FA2": cell("SB_DFF", {"D": 5}, {"Q": 10}),
        "FB": cell("SB_DFF", {"D": 3}, {"Q": 11})}}}}
    bad += _check("the hand-written netlist", hand, "h", {"a_q": 2.5, "b_q": 0.5})
    if bad:
        print("lut_cones self-test: FAIL: " + "; ".join(bad))
        return 1
    print("lut_cones self-test: pass (a synthesised design of 24 LUTs, and a shared LUT split in halves)")
    return 0


def _check(what, nl, top, want):
    """Failures (text) of one netlist's attribution against the expected shares."""
    luts = sum(1 for c in nl["modules"][top]["cells"].values() if c["type"] == "SB_LUT4")
    got = dict(cones(nl, top))
    bad = [f"{what}: {k}: expected {v} LUTs, came {got.get(k, 0):.2f}" for k, v in want.items()
           if abs(got.get(k, 0) - v) > 0.01]
    if abs(sum(got.values()) - luts) > 0.01:
        bad.append(f"{what}: expected the shares to add up to its {luts} SB_LUT4, came {sum(got.values()):.2f}")
    return [b + f" (all: {got})" for b in bad]


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("netlist")
    ap.add_argument("--top")
    ap.add_argument("--rows", type=int, default=20)
    a = ap.parse_args()
    try:
        with open(a.netlist) as f:
            rows = cones(json.load(f), a.top)
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"lut_cones: {a.netlist}: {e}")
    total = sum(v for _, v in rows)
    for k, v in rows[:a.rows]:
        print(f"{v:8.1f}  {k}")
    if len(rows) > a.rows:
        print(f"{sum(v for _, v in rows[a.rows:]):8.1f}  ({len(rows) - a.rows} others)")
    print(f"{total:8.1f}  total SB_LUT4")
    return 0


if __name__ == "__main__":
    sys.exit(main())
