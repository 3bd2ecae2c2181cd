// ctrl_scenarios_fragswitch.cpp -- test_controller scenario fragswitch: a mode
// switch while a value goes over several runs (docs/controller.md
// "Fragments").  A mode switch keeps a channel's state: the value goes on
// when the channel next runs, in whatever entry, at the first word not yet
// stored to the destination, with the source buffer it holds and the
// destination buffer it picked; nothing of it is published before its last
// word, and its taken_at is its first run's.
// Channel 0 is a three-buffer COPY of W = 5 (board 0 @SRC_BASE -> board 1
// @DST_BASE) in mode 0 (cycle 400: a REQUEST of channel 3 at 0, channel 0
// at 40 in a slot of L_FRAG0 = 30 clocks, too short for the whole value:
// as in scenario frag, a first run stores 1 word and a run that goes on 3,
// so the value takes 3 runs; the words each run carries are read from the
// stores the bench sees).  Two parts, each on its own image and model:
//   on    mode 1 (cycle 300) runs channel 0 too, in a slot of L_CP = 80
//         (room for the whole value): a request read in cycle 0 switches
//         after mode 0's first run; mode 1's first run of channel 0 goes on
//         with the value at the first word not stored, from the held buffer
//         with no access to the source's control word, stores the rest and
//         publishes the value once, whole (the one held since its first run,
//         not the producer's newer one), with the first run's taken_at; the
//         next value starts with a fresh Import.
//   away  mode 1 (cycle 300) does not run channel 0 (channel 4 instead): the
//         switch comes after mode 0's second run (the value not finished);
//         while mode 1 runs, nothing touches channel 0's places, the source's
//         ReadLocked stays the held buffer (the producer publishes around
//         it) and the consumer sees nothing New; back in mode 0, the first
//         run goes on at the first word not stored, from the held buffer,
//         stores the rest and publishes the value once, whole, with the
//         first run's taken_at (older than both switches: its age is
//         honest); the next run Imports afresh.
// Negative: controller-negative-fragswitch (the controller that forgets the
// channels' state in a mode's first 100 clocks, mutant forget_switch: the
// held buffer is lost and the run after the switch loads other words).
#include "ctrl_bench.h"

namespace {

// W; E7.frag of channel 0's entries (not 0: the value may go over several
// runs; the compiler's planned minimum of words per run, not used by the
// controller); mode 0's slot for channel 0 (30 clocks begin 7 accesses:
// scenario frag has the count).
const unsigned FW = 5, FRAG0 = 1, FRAG1 = 3;
const uint32_t L_FRAG0 = 30;
const unsigned REQ_BASE = 0x0C0, SRC1_BASE = 0x080, DST1_BASE = 0x100;
const unsigned REQ_CH = 3, CH1 = 4;
const uint32_t H1_0 = 400, H1_1 = 300, L_REQ = 40, S_CP = 40, L_CP = 80;
const unsigned NE = 4 + 2;                  // 4 entries, 2 mode descriptors

std::vector<uint32_t> fvalue(unsigned n) {
    std::vector<uint32_t> v = value(n);
    v.push_back(0xF5A90000u + n);
    v.push_back(0x0DDBA11u ^ (n << 8));
    return v;
}

// mode 0: REQUEST, channel 0 (a slot of L_FRAG0); mode 1: REQUEST, then
// channel 0 in a slot of L_CP (on) or channel 4 (away).
std::vector<uint32_t> fragswitch_rom(bool on) {
    const unsigned REQ = C::EFLAG_REQUEST;
    std::vector<Entry> es = {
        {COPY, REQ, REQ_CH, 1, 0, L_REQ, 0, REQ_BASE, {}},
        {COPY, 0, 0, FW, S_CP, L_FRAG0, 0, SRC_BASE, {{1, DST_BASE}}, FRAG0},
        {COPY, REQ, REQ_CH, 1, 0, L_REQ, 0, REQ_BASE, {}},
        on ? Entry{COPY, 0, 0, FW, S_CP, L_CP, 0, SRC_BASE, {{1, DST_BASE}}, FRAG1}
           : Entry{COPY, 0, CH1, W_COPY, S_CP, L_CP, 0, SRC1_BASE, {{1, DST1_BASE}}},
    };
    std::vector<uint32_t> r = build_rom(H1_0, 0, es, 2);
    const unsigned table = (unsigned)es.size();
    r[C::H0_NE.word] = (r[C::H0_NE.word] & ~C::H0_NE.put(C::H0_NE.max())) | C::H0_NE.put(NE);
    r[C::H1_NEXT.word] |= C::H1_NEXT.put(0x2);                   // mode 0 may switch to mode 1
    r[C::H2_TABLE.word] |= C::H2_TABLE.put(table);
    r[C::H2_MODES.word] |= C::H2_MODES.put(2);
    r[C::H2_START_END.word] |= C::H2_START_END.put(2);           // mode 0: entries 0..1
    const uint32_t d[2][4] = {{H1_0, 0, 2, 0x2}, {H1_1, 2, 4, 0x1}};  // cycle, first, end, next
    for (unsigned m = 0; m < 2; ++m) {
        uint32_t *w = &r[rom_addr(table + m, 0)];
        w[C::D0_CYCLE.word] |= C::D0_CYCLE.put(d[m][0]) | C::D0_FIRST.put(d[m][1]) | C::D0_END.put(d[m][2]);
        w[C::D1_DROP_RUN.word] |= C::D1_DROP_RUN.put(2) | C::D1_NEXT.put(d[m][3]);
    }
    reseal(r, NE);
    return r;
}

struct Bench {
    bool rom;
    Sim s;
    Producer prod{0, SRC_BASE, FW}, req{0, REQ_BASE, 1}, prod1{0, SRC1_BASE, W_COPY};
    Consumer cons{1, DST_BASE, FW + 1};
    const uint64_t T0 = t0_of((int)NE);
    ValueRuns v{s, 0, SRC_BASE, 1, DST_BASE, FW};   // channel 0's value: its words per run
    explicit Bench(bool on) : rom((write_rom(fragswitch_rom(on)), true)) {
        prod.init(s);
        s.wr(1, DST_BASE, 0x3, 0x0101);   // Actual = ReadLocked = Buffer1
        s.wr(0, SRC_BASE, 0x2, 1u << 8);  // source ReadLocked = Buffer1
        s.wr(0, REQ_BASE, 0x3, 0x0101);
        s.wr(0, SRC1_BASE, 0x3, 0x0101);
        s.wr(1, DST1_BASE, 0x3, 0x0101);
        cons.rl = 1;
    }
    // RAM operations of the controller in [from, to): Actual stores to channel 0's destination.
    unsigned dst_publishes(size_t from, size_t to) const { return s.actual_stores(1, DST_BASE, from, to); }
    // ... any access to channel 0's places (source or destination).
    unsigned ch0_ops(size_t from, size_t to) const {
        unsigned n = 0;
        for (size_t i = from; i < to && i < s.ram.size(); ++i) {
            const RamOp &r = s.ram[i];
            n += (r.board == 0 && r.adr >= SRC_BASE && r.adr < SRC_BASE + 1 + 3 * FW) ||
                 (r.board == 1 && r.adr >= DST_BASE && r.adr < DST_BASE + 1 + 3 * (FW + 1));
        }
        return n;
    }
    unsigned src_ctrl(size_t from, size_t to) const { return s.ops_at(0, SRC_BASE, from, to); }
    // The time of channel 0's choosing load in the cycle from c0 (the 3rd attempt from c0 + S_CP).
    uint64_t taken_at(uint64_t c0) const {
        std::vector<Attempt> a = s.attempts(c0 + S_CP, c0 + S_CP + L_CP);
        return a.size() >= 3 ? a[2].end : 0;
    }
    unsigned src_rl() { return s.rd(0, SRC_BASE) >> 8 & 0xFF; }
};

void check_value(const char *what, const std::vector<uint32_t> &got, const std::vector<uint32_t> &exp) {
    bool ok = got.size() >= FW;
    for (unsigned i = 0; ok && i < FW; ++i) ok = got[i] == exp[i];
    check(G_DATA, ok, "%s: expected %08x %08x %08x %08x %08x, got %08x %08x %08x %08x %08x", what, exp[0], exp[1],
          exp[2], exp[3], exp[4], got.size() > 0 ? got[0] : 0, got.size() > 1 ? got[1] : 0, got.size() > 2 ? got[2] : 0,
          got.size() > 3 ? got[3] : 0, got.size() > 4 ? got[4] : 0);
}

const char *const GOES_ON = "the first word not yet stored to the destination";

void part_on() {
    Bench f(true);
    std::vector<uint32_t> got;
    const uint64_t T0 = f.T0, B = T0 + H1_0;   // the switch: the end of cycle 0
    const unsigned b0 = f.prod.publish(f.s, fvalue(0));
    f.req.publish(f.s, {1});                    // read by cycle 0's REQUEST: mode 1 from B
    const size_t i0 = f.s.ram.size();
    f.s.run_until(T0 + TAIL);
    const size_t e0 = f.s.ram.size();
    CHECK_EQ(G_DATA, "fragswitch on: mode 0's first run publishes nothing (Actual stores)", 0, f.dst_publishes(i0, e0));
    f.v.check_run("fragswitch on: mode 0's first run starts", i0, e0, b0, 0, "word 0 (a run that Imports)");
    const unsigned p0 = f.v.first_unstored();
    check(G_DATA, p0 > 0 && p0 < FW, "fragswitch on: mode 0's first run stores a part of the value (its slot too "
          "short for the whole): expected the first word not stored in 1..%u, got %u", FW - 1, p0);
    const uint64_t taken = f.taken_at(T0);
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));   // the producer goes on around the held buffer
    check(G_DATA, b1 != b0, "fragswitch on: the producer's next value avoids the held buffer: expected a buffer "
          "other than %u, got %u", b0, b1);
    const size_t i1 = f.s.ram.size();
    f.s.run_until(B + TAIL - 100);
    const size_t e1 = f.s.ram.size();
    std::vector<Attempt> c1 = f.s.attempts(B, B + L_REQ);
    check(G_TIMING, !c1.empty() && c1[0].start == B + F, "fragswitch on: mode 1 (cycle %u) starts at the end of "
          "cycle 0: expected its REQUEST's first access at %" PRIu64 ", got %" PRIu64, H1_1, B + F,
          c1.empty() ? 0 : c1[0].start);
    CHECK_EQ(G_DATA, "fragswitch on: the run after the switch makes no access to the source's control word (its "
             "lock held over the switch)", 0, f.src_ctrl(i1, e1));
    f.v.check_run("fragswitch on: the run after the switch (mode 1) goes on", i1, e1, b0, p0, GOES_ON);
    CHECK_EQ(G_DATA, "fragswitch on: the run after the switch (mode 1, a slot with room for the rest) stores the "
             "rest (the first word not stored)", FW, f.v.first_unstored());
    CHECK_EQ(G_DATA, "fragswitch on: the value published once after the switch (Actual stores)", 1,
             f.dst_publishes(i1, e1));
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "fragswitch on: the consumer's Import returns New", 1, isnew);
    check_value("fragswitch on: the value delivered whole, the one held since its first run (v0)", got, fvalue(0));
    CHECK_EQ(G_DATA, "fragswitch on: taken_at = the time of the first run's Import, before the switch", taken,
             got.size() > FW ? got[FW] : 0);
    // The next value (v1): a fresh Import in mode 1, from word 0.
    f.v.fresh();
    const size_t i2 = f.s.ram.size();
    f.s.run_until(B + 2 * H1_1 + TAIL - 100);
    check(G_DATA, f.src_ctrl(i2, f.s.ram.size()) > 0, "fragswitch on: the next value starts with a fresh Import: "
          "expected source control accesses, got %u", f.src_ctrl(i2, f.s.ram.size()));
    f.v.check_run("fragswitch on: the next value's run (mode 1) starts", i2, f.s.ram.size(), b1, 0,
                  "word 0 (a run that Imports)");
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "fragswitch on: the next value is New after its run in mode 1", 1, isnew);
    check_value("fragswitch on: the next value delivered whole (v1)", got, fvalue(1));
    CHECK_EQ(G_ROM, "fragswitch on: rom_errors_o", 0, f.s.top->rom_errors_o);
}

void part_away() {
    Bench f(false);
    std::vector<uint32_t> got;
    const uint64_t T0 = f.T0, B = T0 + 2 * H1_0;   // the switch to mode 1: the end of cycle 1
    const unsigned b0 = f.prod.publish(f.s, fvalue(0));
    f.prod1.publish(f.s, value(7));
    const size_t i0 = f.s.ram.size();
    f.s.run_until(T0 + TAIL);
    const size_t e0 = f.s.ram.size();
    const uint64_t taken = f.taken_at(T0);
    f.v.check_run("fragswitch away: mode 0's first run starts", i0, e0, b0, 0, "word 0 (a run that Imports)");
    f.req.publish(f.s, {1});                       // read by cycle 1's REQUEST: mode 1 from B
    const size_t i1 = f.s.ram.size();
    f.s.run_until(T0 + H1_0 + TAIL);
    CHECK_EQ(G_DATA, "fragswitch away: mode 0's runs 0 and 1 publish nothing (Actual stores)", 0,
             f.dst_publishes(i0, f.s.ram.size()));
    CHECK_EQ(G_DATA, "fragswitch away: mode 0's run 1 makes no access to the source's control word", 0,
             f.src_ctrl(i1, f.s.ram.size()));
    f.v.check_run("fragswitch away: mode 0's run 1 goes on", i1, f.s.ram.size(), b0, f.v.first_unstored(), GOES_ON);
    const unsigned p1 = f.v.first_unstored();
    check(G_DATA, p1 > 0 && p1 < FW, "fragswitch away: the value is not finished at the switch (2 runs of mode 0): "
          "expected the first word not stored in 1..%u, got %u", FW - 1, p1);
    // Mode 1: channel 0 is not run; the producer publishes twice.
    const size_t m0 = f.s.ram.size();
    f.s.run_until(B + 200);
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));
    check(G_DATA, b1 != b0 && f.src_rl() == b0, "fragswitch away: in mode 1 the source's ReadLocked stays the held "
          "buffer %u and the producer publishes around it: got ReadLocked %u, the producer's buffer %u", b0, f.src_rl(), b1);
    f.req.publish(f.s, {0});                       // read by mode 1's next cycle: mode 0 again from C
    const uint64_t C = B + 2 * H1_1;
    f.s.run_until(C - 50);
    const unsigned b2 = f.prod.publish(f.s, fvalue(2));
    check(G_DATA, b2 != b0 && f.src_rl() == b0, "fragswitch away: late in mode 1 the source's ReadLocked is still the "
          "held buffer %u and the producer's next value avoids it: got ReadLocked %u, the producer's buffer %u", b0,
          f.src_rl(), b2);
    const size_t m1 = f.s.ram.size();
    CHECK_EQ(G_DATA, "fragswitch away: mode 1 makes no access to channel 0's places", 0, f.ch0_ops(m0, m1));
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "fragswitch away: the consumer's Import returns Old while the value waits in mode 1", 0, isnew);
    // Back in mode 0: the value goes on at the first word not stored, held buffer, and ends.
    f.s.run_until(C + TAIL);
    const size_t e2 = f.s.ram.size();
    std::vector<Attempt> c2 = f.s.attempts(C, C + L_REQ);
    check(G_TIMING, !c2.empty() && c2[0].start == C + F, "fragswitch away: mode 0 again from %" PRIu64 ": expected "
          "its REQUEST's first access at %" PRIu64 ", got %" PRIu64, C, C + F, c2.empty() ? 0 : c2[0].start);
    CHECK_EQ(G_DATA, "fragswitch away: back in mode 0 the run makes no access to the source's control word (its "
             "lock held over both switches)", 0, f.src_ctrl(m1, e2));
    f.v.check_run("fragswitch away: back in mode 0 the value goes on", m1, e2, b0, p1, GOES_ON);
    CHECK_EQ(G_DATA, "fragswitch away: back in mode 0 the run stores the rest (the first word not stored)", FW,
             f.v.first_unstored());
    CHECK_EQ(G_DATA, "fragswitch away: the value published once back in mode 0 (Actual stores)", 1,
             f.dst_publishes(m1, e2));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "fragswitch away: the consumer's Import returns New", 1, isnew);
    check_value("fragswitch away: the value delivered whole, the one held since its first run (v0)", got, fvalue(0));
    CHECK_EQ(G_DATA, "fragswitch away: taken_at = the time of the first run's Import, before both switches", taken,
             got.size() > FW ? got[FW] : 0);
    // The next run: a fresh Import of the producer's latest value (v2), which takes 3 runs.
    f.v.fresh();
    f.s.run_until(C + H1_0 + TAIL);
    check(G_DATA, f.src_ctrl(e2, f.s.ram.size()) > 0, "fragswitch away: the next run Imports afresh: expected source "
          "control accesses, got %u", f.src_ctrl(e2, f.s.ram.size()));
    f.v.check_run("fragswitch away: the next value's first run starts", e2, f.s.ram.size(), b2, 0,
                  "word 0 (a run that Imports)");
    f.s.run_until(C + 3 * H1_0 + TAIL);
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "fragswitch away: the next value is New", 1, isnew);
    check_value("fragswitch away: the next value delivered whole (v2)", got, fvalue(2));
    CHECK_EQ(G_ROM, "fragswitch away: rom_errors_o", 0, f.s.top->rom_errors_o);
}

}  // namespace

void scenario_fragswitch() {
    std::printf("== fragswitch: a mode switch while a value goes over several runs (W 5): it goes on whole\n");
    part_on();
    part_away();
}
