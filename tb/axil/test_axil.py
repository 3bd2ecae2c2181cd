"""test_axil -- cocotb test of albatross_dpram_axil (tools/mk/axil.mk, docs/rtl.md
"albatross_dpram_axil"), run by tb/axil/run_axil.py under Icarus.

An independent AXI4-Lite master (cocotbext-axi's AxiLiteMaster, several
concurrent issuers, so AW/W/AR come back to back and pipelined) drives port A
while a Wishbone B4 classic driver written here hammers port B, both mostly on
the same four words.  Phase 1 runs with no stalls (back-to-back handshakes,
throughput figure); phase 2 with random VALID gaps on AW, W, AR and random
BREADY / RREADY stalls (cocotbext-axi pause generators) and random gaps on B.

Checks (every failure names what it expected and what it got):
  * every byte: a reference model (bytes) applies each write whole, in the order
    the RAM performs the accesses; every read of either port must return exactly
    the model's bytes at that moment (byte atomicity and write-data correctness
    under concurrent writes to the same word).  The model takes port A's data,
    address and strobes from the master's own requests (issue order = AXI
    order), never from the RTL; the only internal signal observed is the time
    of port A's accesses (the core's native ack, dut.n_ack), which orders them
    against port B's.
  * BRESP / RRESP are OKAY.
  * the access bounds: BVALID low at most 5 clocks while a write is owed,
    RVALID at most 4 while a read is (clocks in which an earlier response waits for the
    master's READY not counted, as formal/axil/faxil_slave.v s_b_wait); port B
    acked in the 1st to 3rd clock of its request.
Figures (printed, and written as JSON to $AXIL_REPORT if set): operations and
bytes checked, same-word collisions, worst and best latencies, phase-1 cycles per
AXI access.
"""
import json
import os
import random

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, RisingEdge, Timer
from cocotbext.axi import AxiLiteBus, AxiLiteMaster, AxiResp

ADDR_WIDTH = 4
WORDS = 1 << ADDR_WIDTH
HOT = 4                      # most accesses go to words 0..HOT-1 (collisions)
MAX_WAIT_B = 5               # BVALID low at most 5 clocks while a write is owed
MAX_WAIT_R = 4               # RVALID: 4 (reads go first)
B_MAX_WAIT = 2
OPS = int(os.environ.get("AXIL_OPS", "1500"))          # AXI accesses per phase
SEED = int(os.environ.get("AXIL_SEED", "1"))
WATCHDOG_CYCLES = 200 * OPS + 20000


class Bench:
    def __init__(self, dut):
        self.dut = dut
        self.model = [None] * (4 * WORDS)   # bytes; None until first written
        self.a_writes = []                  # (word, {lane: byte}) in AXI issue order
        self.a_reads = []                   # [word, expected bytes or None] in AXI issue order
        self.a_wr_i = 0
        self.a_rd_i = 0
        self.b_req = None                   # port B's request in this clock
        self.b_result = None
        self.errors = []
        self.stats = {"a_writes": 0, "a_reads": 0, "b_writes": 0, "b_reads": 0,
                      "bytes_checked": 0, "collisions": 0, "b_wait_max": 0, "r_wait_max": 0,
                      "b_ack_wait_max": 0, "b_wait_min": 99, "r_wait_min": 99}
        self.cycle = 0
        self.last_word_access = {}          # word -> (cycle, port)

    def fail(self, msg):
        self.errors.append(msg)
        raise AssertionError(msg)

    def touch(self, word, port):
        prev = self.last_word_access.get(word)
        if prev and prev[1] != port and self.cycle - prev[0] <= 3:
            self.stats["collisions"] += 1
        self.last_word_access[word] = (self.cycle, port)

    def apply_write(self, word, lanes):
        for lane, val in lanes.items():
            self.model[4 * word + lane] = val

    def expect(self, word):
        return [self.model[4 * word + l] for l in range(4)]

    def check_bytes(self, who, word, expected, got_word):
        for lane in range(4):
            if expected[lane] is None:
                continue
            got = (got_word >> (8 * lane)) & 0xFF
            self.stats["bytes_checked"] += 1
            if got != expected[lane]:
                self.fail(f"byte mismatch: {who} read of word {word} lane {lane}: "
                          f"expected 0x{expected[lane]:02x}, got 0x{got:02x}")

    async def monitor(self):
        """Once per clock, mid-cycle: the access order, the model, the bounds."""
        dut = self.dut
        aw_out = w_out = ar_out = 0
        b_wait = r_wait = 0
        b_req_wait = 0
        while True:
            await FallingEdge(dut.clk)
            self.cycle += 1
            if self.cycle > WATCHDOG_CYCLES:
                self.fail(f"watchdog: test still running after {WATCHDOG_CYCLES} cycles")
            if int(dut.rst.value):
                continue
            # port A's access, performed at the last rising edge (ack now)
            if int(dut.dut.n_ack.value):
                if int(dut.dut.n_we.value):
                    if self.a_wr_i >= len(self.a_writes):
                        self.fail("port A performed a write no AXI write asked for")
                    word, lanes = self.a_writes[self.a_wr_i]
                    self.a_wr_i += 1
                    self.apply_write(word, lanes)
                else:
                    if self.a_rd_i >= len(self.a_reads):
                        self.fail("port A performed a read no AXI read asked for")
                    rec = self.a_reads[self.a_rd_i]
                    self.a_rd_i += 1
                    rec[1] = self.expect(rec[0])
                self.touch(int(dut.dut.n_adr.value), "A")
            # port B's access
            req = self.b_req
            if req is not None:
                if int(dut.b_ack.value):
                    word, we, sel, data = req
                    if we:
                        self.apply_write(word, {l: (data >> (8 * l)) & 0xFF for l in range(4) if sel >> l & 1})
                        self.stats["b_writes"] += 1
                    else:
                        self.check_bytes("port B", word, self.expect(word), int(dut.b_dat_r.value))
                        self.stats["b_reads"] += 1
                    self.touch(word, "B")
                    self.stats["b_ack_wait_max"] = max(self.stats["b_ack_wait_max"], b_req_wait)
                    self.b_result = True
                    b_req_wait = 0
                else:
                    b_req_wait += 1
                    if b_req_wait > B_MAX_WAIT:
                        self.fail(f"port B bound: expected ack within {B_MAX_WAIT + 1} clocks of stb, "
                                  f"still waiting after {b_req_wait}")
            # AXI response bounds (owed = handshakes at earlier edges, as faxil_slave)
            bvalid, rvalid = int(dut.s_axi_bvalid.value), int(dut.s_axi_rvalid.value)
            if bvalid and int(dut.s_axi_bresp.value) != 0:
                self.fail(f"BRESP: expected OKAY (0), got {int(dut.s_axi_bresp.value)}")
            if rvalid and int(dut.s_axi_rresp.value) != 0:
                self.fail(f"RRESP: expected OKAY (0), got {int(dut.s_axi_rresp.value)}")
            if aw_out and w_out and not bvalid:
                b_wait += 1
                if b_wait > MAX_WAIT_B:
                    self.fail(f"write response bound: expected BVALID within {MAX_WAIT_B} clocks, "
                              f"low for {b_wait}")
            else:
                if bvalid and b_wait:
                    self.stats["b_wait_min"] = min(self.stats["b_wait_min"], b_wait)
                self.stats["b_wait_max"] = max(self.stats["b_wait_max"], b_wait)
                b_wait = 0
            if ar_out and not rvalid:
                r_wait += 1
                if r_wait > MAX_WAIT_R:
                    self.fail(f"read response bound: expected RVALID within {MAX_WAIT_R} clocks, "
                              f"low for {r_wait}")
            else:
                if rvalid and r_wait:
                    self.stats["r_wait_min"] = min(self.stats["r_wait_min"], r_wait)
                self.stats["r_wait_max"] = max(self.stats["r_wait_max"], r_wait)
                r_wait = 0
            b_hs = bvalid and int(dut.s_axi_bready.value)
            r_hs = rvalid and int(dut.s_axi_rready.value)
            aw_out += int(dut.s_axi_awvalid.value) & int(dut.s_axi_awready.value)
            w_out += int(dut.s_axi_wvalid.value) & int(dut.s_axi_wready.value)
            ar_out += int(dut.s_axi_arvalid.value) & int(dut.s_axi_arready.value)
            aw_out -= b_hs
            w_out -= b_hs
            ar_out -= r_hs

    async def b_access(self, word, we, sel, data):
        """One Wishbone classic access on port B (driven after a rising edge)."""
        dut = self.dut
        dut.b_adr.value = word
        dut.b_we.value = we
        dut.b_sel.value = sel
        dut.b_dat_w.value = data
        dut.b_cyc.value = 1
        dut.b_stb.value = 1
        self.b_result = None
        self.b_req = (word, we, sel, data)
        while True:
            await RisingEdge(dut.clk)
            if self.b_result:
                break
        self.b_req = None
        dut.b_cyc.value = 0
        dut.b_stb.value = 0

    async def port_b(self, rng, stop, max_gap):
        while not stop():
            word = rng.randrange(HOT) if rng.random() < 0.9 else rng.randrange(WORDS)
            if rng.random() < 0.6:
                await self.b_access(word, 1, rng.randrange(1, 16), rng.getrandbits(32))
            else:
                await self.b_access(word, 0, 0xF, 0)
            for _ in range(rng.randrange(max_gap + 1)):
                await RisingEdge(self.dut.clk)

    async def a_issuer(self, master, rng, n):
        for _ in range(n):
            word = rng.randrange(HOT) if rng.random() < 0.9 else rng.randrange(WORDS)
            if rng.random() < 0.55:
                first = rng.randrange(4)
                length = rng.randrange(1, 5 - first)
                data = bytes(rng.getrandbits(8) for _ in range(length))
                self.a_writes.append((word, {first + i: data[i] for i in range(length)}))
                ev = master.init_write(4 * word + first, data)
                await ev.wait()
                if ev.data.resp != AxiResp.OKAY:
                    self.fail(f"write to word {word}: expected OKAY, got {ev.data.resp}")
                self.stats["a_writes"] += 1
            else:
                rec = [word, None]
                self.a_reads.append(rec)
                ev = master.init_read(4 * word, 4)
                await ev.wait()
                if ev.data.resp != AxiResp.OKAY:
                    self.fail(f"read of word {word}: expected OKAY, got {ev.data.resp}")
                if rec[1] is None:
                    self.fail(f"read of word {word} answered before port A read the RAM")
                self.check_bytes("port A (AXI)", word, rec[1], int.from_bytes(ev.data.data, "little"))
                self.stats["a_reads"] += 1


def pauses(rng, p):
    while True:
        yield rng.random() < p


@cocotb.test()
async def axil_against_cocotbext(dut):
    rng = random.Random(SEED)
    for name in ("b_cyc", "b_stb", "b_we", "b_adr", "b_sel", "b_dat_w"):
        getattr(dut, name).value = 0
    dut.rst.value = 1
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    master = AxiLiteMaster(AxiLiteBus.from_prefix(dut, "s_axi"), dut.clk, dut.rst)
    for lg in ("cocotb.tb_axil", "cocotbext.axi"):
        import logging
        logging.getLogger(lg).setLevel(logging.WARNING)
    master.write_if.log.setLevel(30)
    master.read_if.log.setLevel(30)
    bench = Bench(dut)
    for _ in range(3):
        await RisingEdge(dut.clk)
    dut.rst.value = 0
    await RisingEdge(dut.clk)
    mon = cocotb.start_soon(bench.monitor())

    # Every word defined once through port B (the array is never reset).
    for w in range(WORDS):
        await bench.b_access(w, 1, 0xF, rng.getrandbits(32))

    # Phase 1: back to back, no stalls; port B busy every other access.
    done = [False]
    b_task = cocotb.start_soon(bench.port_b(random.Random(SEED + 1), lambda: done[0], 0))
    c0 = bench.cycle
    issuers = [cocotb.start_soon(bench.a_issuer(master, random.Random(SEED + 10 + i), OPS // 4))
               for i in range(4)]
    for t in issuers:
        await t
    cycles_p1 = bench.cycle - c0
    ops_p1 = 4 * (OPS // 4)
    done[0] = True
    await b_task

    # Phase 2: random stalls on every AXI channel and gaps on port B.
    prng = random.Random(SEED + 2)
    master.write_if.aw_channel.set_pause_generator(pauses(prng, 0.3))
    master.write_if.w_channel.set_pause_generator(pauses(prng, 0.4))
    master.write_if.b_channel.set_pause_generator(pauses(prng, 0.5))
    master.read_if.ar_channel.set_pause_generator(pauses(prng, 0.3))
    master.read_if.r_channel.set_pause_generator(pauses(prng, 0.5))
    done[0] = False
    b_task = cocotb.start_soon(bench.port_b(random.Random(SEED + 3), lambda: done[0], 3))
    issuers = [cocotb.start_soon(bench.a_issuer(master, random.Random(SEED + 20 + i), OPS // 4))
               for i in range(4)]
    for t in issuers:
        await t
    done[0] = True
    await b_task

    # Final sweep: every word read through both ports.
    for w in range(WORDS):
        rec = [w, None]
        bench.a_reads.append(rec)
        ev = master.init_read(4 * w, 4)
        await ev.wait()
        bench.check_bytes("port A (AXI, final)", w, rec[1], int.from_bytes(ev.data.data, "little"))
        await bench.b_access(w, 0, 0xF, 0)
    await Timer(100, unit="ns")
    mon.cancel()

    if bench.a_wr_i != len(bench.a_writes) or bench.a_rd_i != len(bench.a_reads):
        bench.fail(f"port A accesses: expected {len(bench.a_writes)} writes and {len(bench.a_reads)} reads "
                   f"performed, got {bench.a_wr_i} and {bench.a_rd_i}")
    st = dict(bench.stats)
    st["phase1_cycles_per_axi_access"] = round(cycles_p1 / ops_p1, 3)
    st["bound_b"] = MAX_WAIT_B
    st["bound_r"] = MAX_WAIT_R
    st["seed"] = SEED
    dut._log.warning("axil figures: %s", json.dumps(st))
    if st["collisions"] < 50:
        bench.fail(f"too few same-word collisions between the ports: expected >= 50, got {st['collisions']}")
    rep = os.environ.get("AXIL_REPORT")
    if rep:
        with open(rep, "w") as f:
            json.dump(st, f, indent=1)
