#!/usr/bin/env python3
"""albatross_soc.py -- the LiteX test SoC of the ALBATROSS integration
(tools/mk/litex.mk): LiteX's VexRiscv (the "standard" variant: instruction
and data caches), an integrated ROM (the program) and SRAM (data, stack),
an AlbatrossDPRAM (tools/litex/albatross_litex.py) as an uncached Wishbone
slave at --origin, its port B brought out to the top as pads, and a TOHOST
CSR whose first store ends the run (its value, the exit code, and a done
flag are pads too).  Generates, with LiteX from PyPI and no toolchain:

  OUT/gateware/sim.v                    the SoC (top module `sim`)
  OUT/gateware/sources.txt              the Verilog files it needs (VexRiscv.v
                                        from pythondata-cpu-vexriscv, rtl/albatross_dpram.v)
  OUT/software/include/generated/mem.h  LiteX's memory map (ALBATROSS_BASE)
  OUT/software/include/generated/albatross_channels.h  the channels in the window
  OUT/software/include/generated/albatross_board.h     the addresses crt0.S and
                                        soc/firmware/board.h need (plain numbers)

usage: albatross_soc.py --output-dir OUT [--origin ADDR]
An --origin outside the CPU's I/O region (VexRiscv: below 0x8000_0000) is
refused by LiteX (exit status 1): a cached window is never built.
"""
import argparse
import os
import sys

from migen import Module, Signal, If
from migen.genlib.io import CRG
from litex.build.generic_platform import Pins, Subsignal
from litex.build.sim import SimPlatform
from litex.gen import LiteXModule
from litex.soc.interconnect.csr import CSRStorage
from litex.soc.integration.soc import SoCError
from litex.soc.integration.soc_core import SoCCore
from litex.soc.integration.builder import Builder

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from albatross_litex import add_albatross, write_channel_header  # noqa: E402

DP_ADDR_BITS = 10  # word-address pads of port B (a 4 KiB window)
# The channels of the test program (tb/litex/firmware/litex_pair.c): name, payload bytes, kind.
CHANNELS = [("pair", 16, "three_buffer"), ("pair4", 16, "four_slot")]

_io = [
    ("sys_clk", 0, Pins(1)),
    ("albatross_b", 0,
        Subsignal("cyc", Pins(1)), Subsignal("stb", Pins(1)), Subsignal("we", Pins(1)),
        Subsignal("adr", Pins(DP_ADDR_BITS)), Subsignal("sel", Pins(4)), Subsignal("dat_w", Pins(32)),
        Subsignal("dat_r", Pins(32)), Subsignal("ack", Pins(1))),
    ("tohost", 0, Subsignal("done", Pins(1)), Subsignal("code", Pins(32))),
]


class Tohost(LiteXModule):
    """One CSR: a store sets done (sticky) and code (the stored value)."""

    def __init__(self, pads):
        self.code = CSRStorage(32, description="exit code; a store ends the run")
        done = Signal()
        self.sync += If(self.code.re, done.eq(1))
        self.comb += [pads.done.eq(done), pads.code.eq(self.code.storage)]


class AlbatrossSoC(SoCCore):
    def __init__(self, origin):
        platform = SimPlatform("SIM", _io)
        self.crg = CRG(platform.request("sys_clk"))
        SoCCore.__init__(self, platform, int(1e6), cpu_type="vexriscv", cpu_variant="standard",
                         integrated_rom_size=0x4000, integrated_rom_init=[0],
                         integrated_sram_size=0x2000, with_uart=False,
                         ident="ALBATROSS LiteX test SoC")
        dp = add_albatross(self, origin=origin, size=4 << DP_ADDR_BITS)
        pb = platform.request("albatross_b")
        self.comb += [dp.port_b.cyc.eq(pb.cyc), dp.port_b.stb.eq(pb.stb), dp.port_b.we.eq(pb.we),
                      dp.port_b.adr.eq(pb.adr), dp.port_b.sel.eq(pb.sel), dp.port_b.dat_w.eq(pb.dat_w),
                      pb.dat_r.eq(dp.port_b.dat_r), pb.ack.eq(dp.port_b.ack)]
        self.tohost = Tohost(platform.request("tohost"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--output-dir", required=True)
    ap.add_argument("--origin", default="0x90000000", help="the window's address (default 0x9000_0000)")
    a = ap.parse_args()
    origin = int(a.origin, 0)
    a.output_dir = os.path.abspath(a.output_dir)  # LiteX changes the working directory while building
    try:
        soc = AlbatrossSoC(origin)
    except SoCError:
        print("albatross_soc: LiteX refused the window at 0x%08x (see above)" % origin)
        return 1
    builder = Builder(soc, output_dir=a.output_dir, compile_software=False, compile_gateware=False)
    try:
        builder.build(run=False)
    except ImportError as e:
        # The SimPlatform's own simulator files need more pythondata packages
        # (tapcfg); the Verilog and the headers are written before that.
        print("albatross_soc: LiteX's own simulator files not written (%s); not needed here" % str(e).split("\n")[0])
    gw = os.path.join(a.output_dir, "gateware")
    if not os.path.exists(os.path.join(gw, "sim.v")):
        print("albatross_soc: LiteX wrote no gateware/sim.v")
        return 1
    with open(os.path.join(gw, "sources.txt"), "w") as f:
        f.write("\n".join(os.path.abspath(p) for p, _, _ in soc.platform.sources) + "\n")
    inc = os.path.join(a.output_dir, "software", "include", "generated")
    end = write_channel_header(os.path.join(inc, "albatross_channels.h"), CHANNELS)
    tohost = soc.mem_map["csr"] + soc.csr.paging * soc.csr.locs["tohost"]  # its one register, code
    with open(os.path.join(inc, "albatross_board.h"), "w") as f:
        f.write("/* Generated by tools/litex/albatross_soc.py: the addresses of the LiteX test SoC that\n"
                " * crt0.S and soc/firmware/board.h need, as plain numbers.  Do not edit. */\n"
                "#define BOARD_DPRAM_BASE 0x%08x\n#define BOARD_REGS_BASE 0x%08x\n"
                "#define LITEX_SRAM_END 0x%08x\n" % (origin, tohost,
                                                    soc.mem_map["sram"] + 0x2000))
    print("albatross_soc: %s/sim.v, window 0x%08x (uncached), %u bytes of channels, TOHOST CSR at 0x%08x"
          % (gw, origin, end, tohost))
    return 0


if __name__ == "__main__":
    sys.exit(main())
