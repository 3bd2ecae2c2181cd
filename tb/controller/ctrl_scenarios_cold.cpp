// ctrl_scenarios_cold.cpp -- test_controller scenario cold: the controller on
// zeroed board RAMs, before and after the CPUs run their init (docs/protocol.md
// and docs/controller.md, "Cold start").  A source Actual of 0 is nothing new,
// a destination ReadLocked of 0 is Buffer1 (four-slot: the Export writes pair
// 1), a destination Actual of 0 loaded is nothing published; none of them
// counts corrupt, and every value arrives once the CPUs have started.
#include "ctrl_bench.h"

// The STATUS words {abandoned, corrupt} of channels 0..n-1 must all be 0.
static void check_no_corrupt(const char *what, const std::vector<uint32_t> &got, unsigned n) {
    for (unsigned c = 0; c < n; ++c) {
        char m[128];
        std::snprintf(m, sizeof m, "%s: STATUS channel %u {abandoned, corrupt}", what, c);
        CHECK_HEX(G_DATA, m, 0u, got[2 + 2 * c]);
    }
}

// Three-buffer: cycle 0 on zeros, then every CPU runs its init, the producer
// publishes, and cycle 1 delivers.
static void cold_three() {
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;                                            // every board RAM is zero
    Producer prod{0, SRC_BASE, W_COPY};
    Consumer cons{1, DST_BASE, W_COPY + 1}, time0{0, TIME_BASE, 2}, time1{1, TIME_BASE, 2};
    Consumer stat{1, STAT_BASE, W_STAT + 1};
    const uint64_t T0 = t0_of((int)es.size()), C1 = T0 + H1;
    s.run_until(T0 + TAIL);
    std::vector<Attempt> c0 = s.attempts(T0 + S_COPY, T0 + S_COPY + L_COPY);
    CHECK_EQ(G_DATA, "cold cycle 0 COPY: accesses (the source's Actual 0 is loaded, the transfer ends)", 1, c0.size());
    CHECK_HEX(G_DATA, "cold cycle 0 COPY: the source's control word (no ReadLocked store)", 0u, s.rd(0, SRC_BASE));
    CHECK_HEX(G_DATA, "cold cycle 0 COPY: the destination's control word (nothing published)", 0u, s.rd(1, DST_BASE));
    for (int b = 0; b < 2; ++b) {
        char m[128];
        std::snprintf(m, sizeof m, "cold cycle 0 TIME on board %d: Actual (ReadLocked 0 as Buffer1: the last of 1..3)", b);
        CHECK_EQ(G_DATA, m, 3, s.rd(b, TIME_BASE) & 0xFF);
    }
    // The CPUs start: each side's init (only its own control byte), then a value.
    for (unsigned i = 0; i < W_COPY; ++i) s.wr(0, SRC_BASE + 1 + i, 0xF, value(0)[i]);
    prod.init(s);
    cons.init(s);
    time0.init(s);
    time1.init(s);
    stat.init(s);
    prod.publish(s, value(1));
    s.run_until(C1 + TAIL);
    std::vector<uint32_t> got;
    bool isnew = cons.import(s, got);
    CHECK_EQ(G_DATA, "cold cycle 1: consumer Import returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char m[64];
        std::snprintf(m, sizeof m, "cold cycle 1: value word %u", i);
        CHECK_HEX(G_DATA, m, value(1)[i], got[i]);
    }
    for (int b = 0; b < 2; ++b) {
        Consumer &t = b ? time1 : time0;
        isnew = t.import(s, got);
        char m[96];
        std::snprintf(m, sizeof m, "cold cycle 1 TIME on board %d: Import New", b);
        CHECK_EQ(G_DATA, m, 1, isnew);
        std::snprintf(m, sizeof m, "cold cycle 1 TIME on board %d: value = slot start", b);
        CHECK_EQ(G_DATA, m, C1 + S_TIME, got[0]);
    }
    isnew = stat.import(s, got);
    CHECK_EQ(G_DATA, "cold cycle 1 STATUS: Import New", 1, isnew);
    CHECK_HEX(G_DATA, "cold cycle 1 STATUS channel 0 {transfers, retries}", 1u << 16, got[1]);
    CHECK_HEX(G_DATA, "cold cycle 1 STATUS channel 1 {transfers, retries}", 4u << 16, got[3]);
    check_no_corrupt("cold cycle 1 (three-buffer)", got, 3);
}

// Four-slot: the source starts at once, the COPY and TIME destinations'
// consumers only after cycle 1, so two Exports see ReadLocked 0: both write
// pair 1 (the second one although its Actual copy, 4, is in pair 1 too).
static void cold_four() {
    const unsigned FS = C::EFLAG_FOUR_SLOT;
    std::vector<Entry> es = {
        {COPY, FS, 0, W_COPY, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}},
        {TIME, FS, 1, 1, S_TIME, L_TIME, 0, 0, {{0, TIME_BASE}, {1, TIME_BASE}}},
        {STATUS, 0, 2, W_STAT, S_STAT, L_STAT, 0, 0, {{1, STAT_BASE}}},
    };
    write_rom(build_rom(H1, 0, es));
    Sim s;                                            // every board RAM is zero
    Producer4 prod{0, SRC_BASE, W_COPY};
    Consumer4 cons{1, DST_BASE, W_COPY + 1};
    Consumer stat{1, STAT_BASE, W_STAT + 1};
    const uint64_t T0 = t0_of((int)es.size()), C1 = T0 + H1;
    // The producer's init: Buffer1 := value 0, Slots 0, Actual := Buffer1.
    for (unsigned i = 0; i < W_COPY; ++i) s.wr(0, SRC_BASE + 1 + i, 0xF, value(0)[i]);
    s.wr(0, SRC_BASE, 0x1, 1);
    s.run_until(T0 + TAIL);
    CHECK_HEX(G_DATA, "cold four cycle 0: destination control word {Slot1, Slot0, ReadLocked, Actual} (pair 1)",
              0x01000004u, s.rd(1, DST_BASE));
    stat.init(s);
    prod.publish(s, value(1));
    s.run_until(C1 + TAIL);
    CHECK_HEX(G_DATA, "cold four cycle 1: destination control word, ReadLocked still 0: pair 1 again",
              0x00000003u, s.rd(1, DST_BASE));
    for (int b = 0; b < 2; ++b) {
        char m[128];
        std::snprintf(m, sizeof m, "cold four cycle 1 TIME on board %d: control word, ReadLocked still 0: pair 1 again", b);
        CHECK_HEX(G_DATA, m, 0x00000003u, s.rd(b, TIME_BASE));
    }
    std::vector<uint32_t> got;
    bool isnew = stat.import(s, got);
    CHECK_EQ(G_DATA, "cold four cycle 1 STATUS: Import New", 1, isnew);
    check_no_corrupt("cold four cycle 1", got, 3);
    // The consumer's init: ReadLocked := Buffer1 (its own byte only); it then reads value 1.
    s.wr(1, DST_BASE, 0x2, 1u << 8);
    cons.l = 0;
    isnew = cons.import(s, got);
    CHECK_EQ(G_DATA, "cold four: consumer Import after its init returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char m[64];
        std::snprintf(m, sizeof m, "cold four: value word %u", i);
        CHECK_HEX(G_DATA, m, value(1)[i], got[i]);
    }
    // A next value, published now (the reads above took simulated time):
    // the first cycle that starts after it delivers it.
    prod.publish(s, value(2));
    const uint64_t Cn = T0 + ((s.now - T0) / H1 + 1) * H1;
    s.run_until(Cn + TAIL);
    isnew = cons.import(s, got);
    CHECK_EQ(G_DATA, "cold four, the cycle after the next publish: consumer Import returns New", 1, isnew);
    CHECK_HEX(G_DATA, "cold four, the cycle after the next publish: value word 0", value(2)[0], got[0]);
}

void scenario_cold() {
    std::printf("== cold: zeroed RAMs: a source Actual 0 is nothing new, a ReadLocked 0 is Buffer1, no corrupt count\n");
    cold_three();
    cold_four();
}
