// ctrl_scenarios_modes.cpp -- test_controller scenario modes: an image with two
// modes (docs/controller.md "Modes") and a mode request channel on board 0.
//   mode 0 (cycle 400): REQUEST of channel 3 at 0, COPY channel 0 (board 0 -> board 1 @DST_BASE) at 40
//   mode 1 (cycle 300): REQUEST at 0, COPY channel 4 (board 0 @SRC1_BASE -> board 1 @DST1_BASE) at 40,
//                       STATUS channel 2 -> board 1 at 130
//   both: MODE (a STATUS of W 2, channel 5) -> board 1 @MODE_BASE: {the running mode, since}
// A C++ producer on board 0 publishes requests with the three-buffer protocol.
// Checked: a request for mode 1 published mid-cycle is read by the next
// REQUEST slot and switches at the boundary after it, not before (the cycle in
// which it is read is a whole mode-0 cycle); the first entry of mode 1 runs at
// the new cycle's start (its first access at the boundary + FETCH_CYCLES); the
// cycles of mode 1 are 300 clocks and carry mode 1's COPY, not mode 0's; a
// request for a mode the image does not have is ignored (mode 1 runs on) and
// counted as a corrupt value of channel 3 in STATUS; the MODE channel shows
// {0, the first cycle's start} in mode 0 and {1, the switch's boundary} in
// mode 1; a value not published again is not New twice in the mode's later
// cycles (the channel keeps its state); a request back to mode 0 switches
// back, and channel 0's value, delivered before the first switch and not
// published since, is Old there with its taken_at (its state kept over both
// switches), until a new value arrives New; no ROM error.
#include "ctrl_bench.h"

namespace {
const unsigned REQ_BASE = 0x0C0, SRC1_BASE = 0x080, DST1_BASE = 0x100, MODE_BASE = 0x120;
const unsigned REQ_CH = 3, CH1 = 4;
const uint32_t H1_0 = 400, H1_1 = 300, L_REQ = 40, S_CP = 40, S_ST = 130;

std::vector<uint32_t> modes_rom() {
    const unsigned REQ = C::EFLAG_REQUEST, MODE = C::EFLAG_MODE;
    std::vector<Entry> es = {
        {COPY, REQ, REQ_CH, 1, 0, L_REQ, 0, REQ_BASE, {}},
        {COPY, 0, 0, W_COPY, S_CP, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}},
        {STATUS, MODE, 5, 2, 130, 60, 0, 0, {{1, MODE_BASE}}},
        {COPY, REQ, REQ_CH, 1, 0, L_REQ, 0, REQ_BASE, {}},
        {COPY, 0, CH1, W_COPY, S_CP, L_COPY, 0, SRC1_BASE, {{1, DST1_BASE}}},
        {STATUS, 0, 2, W_STAT, S_ST, L_STAT, 0, 0, {{1, STAT_BASE}}},
        {STATUS, MODE, 5, 2, 255, 32, 0, 0, {{1, MODE_BASE}}},
    };
    std::vector<uint32_t> r = build_rom(H1_0, 0, es, 2);
    const unsigned table = (unsigned)es.size(), ne = table + 2;
    r[C::H0_NE.word] = (r[C::H0_NE.word] & ~C::H0_NE.put(C::H0_NE.max())) | C::H0_NE.put(ne);
    r[C::H1_NEXT.word] |= C::H1_NEXT.put(0x2);                   // mode 0 may switch to mode 1
    r[C::H2_TABLE.word] |= C::H2_TABLE.put(table);
    r[C::H2_MODES.word] |= C::H2_MODES.put(2);
    r[C::H2_START_END.word] |= C::H2_START_END.put(3);           // mode 0: entries 0..2
    const uint32_t d[2][4] = {{H1_0, 0, 3, 0x2}, {H1_1, 3, 7, 0x1}};  // cycle, first, end, next
    for (unsigned m = 0; m < 2; ++m) {
        uint32_t *w = &r[rom_addr(table + m, 0)];
        w[C::D0_CYCLE.word] |= C::D0_CYCLE.put(d[m][0]) | C::D0_FIRST.put(d[m][1]) | C::D0_END.put(d[m][2]);
        w[C::D1_DROP_RUN.word] |= C::D1_DROP_RUN.put(2) | C::D1_NEXT.put(d[m][3]);
    }
    reseal(r, ne);
    return r;
}

// The first access on the bus in [t0, t1) to board brd's word range [w0, w1).
bool touches(const Sim &s, uint64_t t0, uint64_t t1, unsigned brd, unsigned w0, unsigned w1) {
    for (const Attempt &a : s.attempts(t0, t1))
        if ((a.adr >> AW) == brd && (a.adr & AMASK) >= w0 && (a.adr & AMASK) < w1) return true;
    return false;
}
}  // namespace

void scenario_modes() {
    std::printf("== modes: a mode request switches at the next cycle boundary\n");
    write_rom(modes_rom());
    Sim s;
    Setup u(s);
    Producer req{0, REQ_BASE, 1}, prod1{0, SRC1_BASE, W_COPY};
    s.wr(0, REQ_BASE, 0x3, 0x0101);                              // Actual = ReadLocked = Buffer1
    s.wr(1, DST1_BASE, 0x3, 0x0101);
    s.wr(0, SRC1_BASE, 0x3, 0x0101);
    prod1.publish(s, value(7));
    Consumer cons1{1, DST1_BASE, W_COPY + 1}, mode{1, MODE_BASE, 3};
    s.wr(1, MODE_BASE, 0x3, 0x0101);
    const uint64_t T0 = t0_of(9);
    const unsigned DSTW = 1 + 3 * (W_COPY + 1), DST1W = DSTW;

    u.prod.publish(s, value(0));
    s.run_until(T0 + 200);
    CHECK_EQ(G_DATA, "modes: error_o after a valid header with modes", 0, s.top->error_o);
    check(G_DATA, touches(s, T0, T0 + 200, 1, DST_BASE, DST_BASE + DSTW),
          "modes: cycle 0 (mode 0) carries channel 0's COPY to board 1 @0x%03x", DST_BASE);
    std::vector<uint32_t> got;
    bool isnew = mode.import(s, got);
    check(G_DATA, isnew && got[0] == 0 && got[1] == T0,
          "modes: MODE in mode 0: expected New {0, %" PRIu64 "}, got %s{%u, %u}", T0, isnew ? "New " : "Old ", got[0], got[1]);
    req.publish(s, {1});                                         // mid cycle 0: a request for mode 1
    u.prod.publish(s, value(1));                                 // (a new value: cycle 1 exports it)
    s.run_until(T0 + H1_0 + 200);
    check(G_DATA, touches(s, T0 + H1_0, T0 + 2 * H1_0, 1, DST_BASE, DST_BASE + DSTW),
          "modes: cycle 1, in which the request is read, is still mode 0 (channel 0's COPY)");
    s.run_until(T0 + 2 * H1_0 + H1_1 + 200);
    const uint64_t B = T0 + 2 * H1_0;                            // the boundary of the switch
    std::vector<Attempt> c2 = s.attempts(B, B + L_REQ);
    check(G_TIMING, !c2.empty() && c2[0].start == B + F && (c2[0].adr >> AW) == 0 && (c2[0].adr & AMASK) == REQ_BASE,
          "modes: mode 1's first entry starts the new cycle: expected its first access (board 0 @0x%03x) at %" PRIu64
          ", got %" PRIu64 " (@0x%04x)", REQ_BASE, B + F, c2.empty() ? 0 : c2[0].start, c2.empty() ? 0 : c2[0].adr);
    check(G_DATA, touches(s, B, B + H1_1, 1, DST1_BASE, DST1_BASE + DST1W) &&
                      !touches(s, B, B + H1_1, 1, DST_BASE, DST_BASE + DSTW),
          "modes: cycle 2 (mode 1) carries channel 4's COPY to @0x%03x and not channel 0's", DST1_BASE);
    std::vector<Attempt> c3 = s.attempts(B + H1_1, B + H1_1 + L_REQ);
    check(G_TIMING, !c3.empty() && c3[0].start == B + H1_1 + F,
          "modes: mode 1's cycle is %u clocks: expected the next cycle's first access at %" PRIu64 ", got %" PRIu64,
          H1_1, B + H1_1 + F, c3.empty() ? 0 : c3[0].start);
    isnew = cons1.import(s, got);
    CHECK_EQ(G_DATA, "modes: channel 4's value arrives in mode 1 (New)", 1, isnew);
    CHECK_HEX(G_DATA, "modes: channel 4's value word 0", value(7)[0], got[0]);
    isnew = mode.import(s, got);
    check(G_DATA, isnew && got[0] == 1 && got[1] == B,
          "modes: MODE in mode 1: expected New {1, %" PRIu64 "} (the boundary), got %s{%u, %u}", B, isnew ? "New " : "Old ",
          got[0], got[1]);

    // An unknown mode: ignored, counted; mode 1 runs on.
    const uint64_t C4 = B + 2 * H1_1;
    s.run_until(C4 + 200);
    // Two more cycles of mode 1 with no new value: channel 4 keeps its state
    // (its ReadLocked copy), so its value is not New twice.
    isnew = cons1.import(s, got);
    CHECK_EQ(G_DATA, "modes: channel 4's value, unchanged over two more cycles of mode 1, is Old (not New twice)", 0,
             isnew);
    req.publish(s, {7});
    prod1.publish(s, value(8));
    s.run_until(C4 + 2 * H1_1 + 260);
    std::vector<Attempt> c6 = s.attempts(C4 + 2 * H1_1, C4 + 2 * H1_1 + L_REQ);
    check(G_DATA, !c6.empty() && c6[0].start == C4 + 2 * H1_1 + F &&
                      touches(s, C4 + H1_1, C4 + 2 * H1_1, 1, DST1_BASE, DST1_BASE + DST1W),
          "modes: after a request for mode 7 (the image has 2) mode 1 runs on (its 300-clock cycle, channel 4's COPY)");
    CHECK_EQ(G_DATA, "modes: error_o", 0, s.top->error_o);
    isnew = u.stat.import(s, got);
    CHECK_EQ(G_DATA, "modes: STATUS arrives in mode 1 (New)", 1, isnew);
    CHECK_EQ(G_DATA, "modes: STATUS corrupt count of the request channel (the rejected request)", 1,
             got[2 + 2 * REQ_CH] & 0xFFFF);

    // Back to mode 0.  Channel 0 still holds value(1), delivered in cycle 1
    // before the switch to mode 1 and not published since: its state is kept
    // over both switches, so back in mode 0 it is Old, with the same taken_at.
    isnew = u.cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(1)[0],
          "modes: channel 0's value(1), delivered in mode 0 before the switch, is New once (word 0 0x%08x)", got[0]);
    const uint32_t taken1 = got[W_COPY];
    req.publish(s, {0});
    const uint64_t now = s.now;
    s.run_until(now + 3 * H1_1 + 2 * H1_0);
    isnew = mode.import(s, got);
    check(G_DATA, isnew && got[0] == 0, "modes: a request for mode 0 switches back: expected MODE New {0, ..}, got %s{%u, %u}",
          isnew ? "New " : "Old ", got[0], got[1]);
    isnew = u.cons.import(s, got);
    check(G_DATA, !isnew && got[W_COPY] == taken1,
          "modes: channel 0's value, unchanged over the switches to mode 1 and back, is Old with taken_at %u: got "
          "%s with taken_at %u (a channel's state forgotten at a switch)", taken1, isnew ? "New" : "Old", got[W_COPY]);
    u.prod.publish(s, value(3));
    const uint64_t later = s.now;
    s.run_until(later + 2 * H1_0);
    bool back = false;
    for (const Attempt &a : s.attempts(later, s.now))
        if ((a.adr >> AW) == 1 && (a.adr & AMASK) >= DST_BASE && (a.adr & AMASK) < DST_BASE + DSTW) back = true;
    isnew = u.cons.import(s, got);
    check(G_DATA, back && isnew && got[0] == value(3)[0],
          "modes: back in mode 0, channel 0's COPY runs again: its new value(3) arrives New");
    CHECK_EQ(G_ROM, "modes: rom_errors_o", 0, s.top->rom_errors_o);
}
