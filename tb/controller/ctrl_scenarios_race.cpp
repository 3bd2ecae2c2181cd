// ctrl_scenarios_race.cpp -- test_controller scenarios that put an event at
// an exact clock of a slot: deadline (the last access a slot may begin) and
// race4 (a four-slot value completed between the controller's two loads of
// the source control word).
#include "ctrl_bench.h"

// The deadline rule (docs/controller.md "Execution"): an access may begin
// in clock p only if it ends before the deadline D = S + length even when it
// times out: p <= D - TIMEOUT - 2.  The COPY's source board is dead, so the
// controller retries its Actual load until the deadline, each try timing
// out; the tries come every TIMEOUT + 2 clocks or so, so a given slot length
// puts the last allowed start at one phase of them.  Slot lengths L0 ..
// L0 + 15 cover every phase: in some of them a try falls on the last clock
// allowed (p = D - TIMEOUT - 2), and a controller whose deadline check
// allows one clock more begins one in D - TIMEOUT - 1, ending at D.  For
// each length: every try begins by D - TIMEOUT - 2 and ends before D; over
// all lengths, some try begins exactly at D - TIMEOUT - 2 (the rule is
// used to its last clock, not kept by a margin).
void scenario_deadline() {
    std::printf("== deadline: a dead source retried to its slot's deadline, 16 slot lengths\n");
    const uint32_t L0 = 60;
    unsigned at_limit = 0;
    for (uint32_t L = L0; L < L0 + 16; ++L) {
        std::vector<Entry> es = {{COPY, 0, 0, W_COPY, S_COPY, L, 0, SRC_BASE, {{1, DST_BASE}}}};
        write_rom(build_rom(H1, 0, es));
        Sim s;
        Setup u(s);
        const uint64_t T0 = t0_of((int)es.size());
        s.top->fi_dead_i = 1u << 0;   // the source board's link is down
        s.run_until(T0 + 2 * H1);
        for (unsigned c = 0; c < 2; ++c) {
            const uint64_t S = T0 + c * H1 + S_COPY, D = S + L;
            std::vector<Attempt> v = s.attempts(S, S + H1);
            uint64_t last_start = 0, last_end = 0;
            for (const Attempt &a : v) last_start = std::max(last_start, a.start), last_end = std::max(last_end, a.end);
            char m[160];
            std::snprintf(m, sizeof m, "deadline: length %u, cycle %u: the source is retried (attempts)", L, c);
            check(G_DEAD, v.size() > 2, "%s: expected more than 2, got %zu", m, v.size());
            std::snprintf(m, sizeof m, "deadline: length %u, cycle %u: no access begins after D-TIMEOUT-2 (D = %" PRIu64
                          ")", L, c, D);
            check(G_DEAD, last_start <= D - TMO - 2, "%s: expected last start <= %" PRIu64 ", got %" PRIu64, m,
                  D - TMO - 2, last_start);
            std::snprintf(m, sizeof m, "deadline: length %u, cycle %u: every access ends before the deadline", L, c);
            check(G_DEAD, last_end < D, "%s: expected last end < %" PRIu64 ", got %" PRIu64, m, D, last_end);
            at_limit += last_start == D - TMO - 2;
        }
    }
    check(G_DEAD, at_limit > 0, "deadline: some try begins in the last clock the rule allows (D-TIMEOUT-2): "
          "expected at least one of 32 slots, got %u", at_limit);
}

// A four-slot Import's L comes from its second control-word load, the one
// after its ReadLocked store (docs/four_slot.md "Import"): a value the
// producer completes in the announced pair between the two loads is the one
// taken.  The producer publishes v1 in pair 0 (the controller holds v0 in
// pair 1), then writes v2 into the other slot of pair 0 (it read ReadLocked
// before the controller's next store) and stores that pair's Slot byte in
// the clock after the controller's first load of the next COPY slot is
// acked, before its second: the controller must take and publish v2, with
// taken_at = time_o in the ack clock of the second load.
void scenario_race4() {
    std::printf("== race4: a four-slot value completed between the Import's two control-word loads\n");
    const unsigned FS = C::EFLAG_FOUR_SLOT;
    std::vector<Entry> es = {{COPY, FS, 0, W_COPY, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}}};
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Producer4 prod{0, SRC_BASE, W_COPY};
    Consumer4 cons{1, DST_BASE, W_COPY + 1};
    prod.init(s);
    cons.init(s);
    const uint64_t T0 = t0_of((int)es.size());
    std::vector<uint32_t> got;
    const unsigned b0 = prod.publish(s, value(0));   // (CHECK_EQ evaluates its arguments twice)
    CHECK_EQ(G_DATA, "race4: v0 in buffer 4 (ReadLocked 1: pair 1)", 4, b0);
    s.run_until(T0 + TAIL);                              // cycle 0 takes v0: source ReadLocked 4
    cons.import(s, got);
    const unsigned b1 = prod.publish(s, value(1));
    CHECK_EQ(G_DATA, "race4: v1 in buffer 2 (ReadLocked 4: pair 0, Slot0 0)", 2, b1);
    // v2: the Export's steps 1 and 2 now (ReadLocked still 4: pair 0, the
    // slot other than Slot0 = 1: buffer 1), its Slot store in the race.
    const uint32_t ctl = s.rd(0, SRC_BASE);
    const unsigned p = 1 - fs_pair(ctl >> 8 & 0xFF), sl = 1 - (ctl >> (16 + 8 * p) & 1);
    CHECK_EQ(G_DATA, "race4: v2 goes to buffer 1 (pair 0, slot 0)", 1, fs_buf(p, sl));
    for (unsigned i = 0; i < W_COPY; ++i) s.wr(0, SRC_BASE + 1 + (fs_buf(p, sl) - 1) * W_COPY + i, 0xF, value(2)[i]);
    const uint64_t C1 = T0 + H1;
    s.run_until(C1 + S_COPY);
    size_t seen = s.ram.size();
    uint64_t first_load = 0;
    while (!first_load && s.now < C1 + S_COPY + L_COPY) {
        s.tick();
        for (; seen < s.ram.size(); ++seen)
            if (s.ram[seen].board == 0 && s.ram[seen].adr == SRC_BASE && !s.ram[seen].we) first_load = s.ram[seen].t;
    }
    s.wr(0, SRC_BASE, 1u << (2 + p), sl << (16 + 8 * p));   // Slot_p := sl: v2 complete
    const uint64_t slot_store = s.now;
    s.wr(0, SRC_BASE, 0x1, fs_buf(p, sl));                 // Actual := buffer 1
    s.run_until(C1 + TAIL);
    std::vector<uint64_t> loads;   // the controller's acked loads of the source control word in the slot
    for (const RamOp &op : s.ram)
        if (op.t >= C1 && op.t < C1 + L_COPY && op.board == 0 && op.adr == SRC_BASE && !op.we) loads.push_back(op.t);
    check(G_DATA, first_load && loads.size() == 2 && slot_store > loads[0] && slot_store < loads[1],
          "race4: the Slot store lands between the Import's two control-word loads: expected loads at t1 < %" PRIu64
          " < t2, got %zu loads, first at %" PRIu64 ", second at %" PRIu64, slot_store, loads.size(),
          loads.empty() ? 0 : loads[0], loads.size() > 1 ? loads[1] : 0);
    bool isnew = cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(2)[0] && got[1] == value(2)[1] && got[2] == value(2)[2],
          "race4: the controller took the value completed before its second load: expected New %08x %08x %08x (v2), "
          "got %s %08x %08x %08x", value(2)[0], value(2)[1], value(2)[2], isnew ? "New" : "Old", got[0], got[1], got[2]);
    std::vector<Attempt> v = s.attempts(C1 + S_COPY, C1 + S_COPY + L_COPY);
    if (v.size() >= 3)
        CHECK_EQ(G_DATA, "race4: taken_at = time_o in the ack clock of the second control-word load", v[2].end,
                 got[W_COPY]);
    isnew = cons.import(s, got);
    CHECK_EQ(G_DATA, "race4: a second Import returns Old", 0, isnew);
}
