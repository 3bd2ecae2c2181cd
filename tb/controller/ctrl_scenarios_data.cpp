// ctrl_scenarios_data.cpp -- test_controller scenarios basic (values, exact timing,
// access sequence) and corrupt (invalid entry, flipped ROM bits).
#include "ctrl_bench.h"

void scenario_basic() {
    std::printf("== basic: delivery, exact COPY timing, TIME, STATUS\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);  // cycle 0

    CHECK_EQ(G_DATA, "error_o after a valid header", 0, s.top->error_o);
    CHECK_EQ(G_ROM, "rom_errors_o with a valid ROM", 0, s.top->rom_errors_o);
    std::vector<Attempt> c0 = s.attempts(T0, T0 + L_COPY);
    check(G_TIMING, !c0.empty() && c0[0].start == T0 + S_COPY + F,
          "cycle 0 COPY: first access on the bus at cycle start + E1 + FETCH_CYCLES: expected %" PRIu64
          ", got %" PRIu64, T0 + S_COPY + F, c0.empty() ? 0 : c0[0].start);
    // first transfer after reset: the destination's control-word load reads its Actual too (no read-back)
    check_slot_timing("cycle 0 COPY (new, first after reset)", c0, T0 + S_COPY, 3 + W_COPY + 1 * (W_COPY + 3));

    std::vector<uint32_t> got;
    bool isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 0: consumer Import on board 1 returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char b[64];
        std::snprintf(b, sizeof b, "cycle 0: value word %u", i);
        CHECK_HEX(G_DATA, b, value(0)[i], got[i]);
    }
    if (c0.size() >= 3) CHECK_EQ(G_DATA, "cycle 0: taken_at = time_o in the ack clock of the final Actual load",
                                 c0[2].end, got[W_COPY]);
    CHECK_EQ(G_DATA, "cycle 0: destination Actual = last buffer neither Actual(1) nor ReadLocked(1)", 3,
             s.rd(1, DST_BASE) & 0xFF);

    // cycle 1: steady state, a new value
    u.prod.publish(s, value(1));
    const uint64_t C1 = T0 + H1;
    s.run_until(C1 + TAIL);
    std::vector<Attempt> c1 = s.attempts(C1, C1 + L_COPY);
    const size_t A = 3 + W_COPY + 1 * (W_COPY + 3);
    check_slot_timing("cycle 1 COPY (new, steady state)", c1, C1 + S_COPY, A);
    if (c1.size() == A) {
        // the access sequence: Import, Export control, streamed words, taken_at, Actual
        unsigned sb = u.prod.actual, db = pick(3, 3);   // dest Actual copy 3, ReadLocked 3 (consumer)
        std::vector<std::pair<bool, uint32_t>> exp = {
            {false, ba(0, SRC_BASE)}, {true, ba(0, SRC_BASE)}, {false, ba(0, SRC_BASE)},
            {false, ba(1, DST_BASE)}};
        for (unsigned i = 0; i < W_COPY; ++i) {
            exp.push_back({false, ba(0, SRC_BASE + 1 + (sb - 1) * W_COPY + i)});
            exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + i)});
        }
        exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + W_COPY)});
        exp.push_back({true, ba(1, DST_BASE)});
        for (size_t k = 0; k < A; ++k) {
            char b[96];
            std::snprintf(b, sizeof b, "cycle 1 COPY access %zu: {we, board, word}", k + 1);
            CHECK_HEX(G_DATA, b, (uint64_t)exp[k].first << 16 | exp[k].second,
                      (uint64_t)c1[k].we << 16 | c1[k].adr);
        }
    }
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1: consumer Import returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char b[64];
        std::snprintf(b, sizeof b, "cycle 1: value word %u", i);
        CHECK_HEX(G_DATA, b, value(1)[i], got[i]);
    }
    if (c1.size() >= 3) CHECK_EQ(G_DATA, "cycle 1: taken_at", c1[2].end, got[W_COPY]);
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1: a second Import returns Old", 0, isnew);

    // TIME: value = taken_at = time at the slot start, on both boards
    for (int b = 0; b < 2; ++b) {
        Consumer &c = b ? u.time1 : u.time0;
        isnew = c.import(s, got);
        char m[96];
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: Import New", b);
        CHECK_EQ(G_DATA, m, 1, isnew);
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: value = slot start", b);
        CHECK_EQ(G_DATA, m, C1 + S_TIME, got[0]);
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: taken_at = slot start", b);
        CHECK_EQ(G_DATA, m, C1 + S_TIME, got[1]);
    }
    std::vector<Attempt> t1 = s.attempts(C1 + S_TIME, C1 + S_TIME + L_TIME);
    check_slot_timing("cycle 1 TIME (2 destinations)", t1, C1 + S_TIME, 2 * (1 + 3));

    // STATUS: {rom_errors, cycles}, then {transfers, retries}, {abandoned, corrupt} per channel
    isnew = u.stat.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1 STATUS: Import New", 1, isnew);
    CHECK_HEX(G_DATA, "cycle 1 STATUS word 0 {rom_errors, cycles}", 0u << 16 | 2u, got[0]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 0 {transfers, retries}", 2u << 16 | 0u, got[1]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 0 {abandoned, corrupt}", 0u, got[2]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 1 {transfers, retries}", 4u << 16 | 0u, got[3]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 2 {transfers, retries}", 1u << 16 | 0u, got[5]);
    CHECK_EQ(G_DATA, "cycle 1 STATUS taken_at = slot start", C1 + S_STAT, got[W_STAT]);
    std::vector<Attempt> st = s.attempts(C1 + S_STAT, C1 + S_STAT + L_STAT);
    check_slot_timing("cycle 1 STATUS", st, C1 + S_STAT, W_STAT + 3);
}

void scenario_corrupt() {
    std::printf("== corrupt: an invalid entry is flagged and skipped; a flipped ROM bit stops the controller\n");
    std::vector<Entry> es = schedule();
    std::vector<uint32_t> rom = build_rom(H1, 0, es);
    rom[rom_addr(1, C::E0_W.word)] ^= C::E0_W.put(3);   // entry 1 (TIME): W = 2, CRC resealed
    reseal(rom, es.size());
    write_rom(rom);
    {
        Sim s;
        Setup u(s);
        const uint64_t T0 = t0_of((int)es.size());
        u.prod.publish(s, value(0));
        for (unsigned c = 0; c < 3; ++c) {
            uint64_t C = T0 + c * H1;
            s.run_until(C + TAIL);
            char m[128];
            std::snprintf(m, sizeof m, "cycle %u: rom_errors_o counts the bad entry once per cycle", c);
            CHECK_EQ(G_ROM, m, c + 1, s.top->rom_errors_o);
            std::vector<Attempt> cp = s.attempts(C + S_COPY, C + S_COPY + L_COPY);
            std::snprintf(m, sizeof m, "cycle %u: COPY first access at its slot start + FETCH_CYCLES", c);
            CHECK_EQ(G_ROM, m, C + S_COPY + F, cp.empty() ? 0 : cp[0].start);
            std::vector<Attempt> tm = s.attempts(C + S_TIME, C + S_TIME + L_TIME);
            std::snprintf(m, sizeof m, "cycle %u: the skipped TIME entry makes no access", c);
            CHECK_EQ(G_ROM, m, 0, tm.size());
            std::vector<Attempt> st = s.attempts(C + S_STAT, C + S_STAT + L_STAT);
            std::snprintf(m, sizeof m, "cycle %u: STATUS first access at its slot start + FETCH_CYCLES", c);
            CHECK_EQ(G_ROM, m, C + S_STAT + F, st.empty() ? 0 : st[0].start);
            std::vector<uint32_t> got;
            bool isnew = u.cons.import(s, got);
            std::snprintf(m, sizeof m, "cycle %u: COPY still delivers (New, word 0)", c);
            check(G_ROM, isnew && got[0] == value(c)[0], "%s: expected New 0x%08x, got %s 0x%08x", m,
                  value(c)[0], isnew ? "New" : "Old", got[0]);
            isnew = u.stat.import(s, got);
            std::snprintf(m, sizeof m, "cycle %u: STATUS word 0 {rom_errors, cycles}", c);
            CHECK_HEX(G_ROM, m, (c + 1) << 16 | (c + 1), got[0]);
            u.prod.publish(s, value(c + 1));
        }
        size_t n0 = s.att.size();
        s.run_until(s.now + 3 * H1);
        check(G_ROM, s.att.size() - n0 >= 3 * (W_STAT + 3 + 1),
              "no hang: 3 more cycles of COPY (1 access) and STATUS (%u): expected >= %zu accesses, got %zu",
              W_STAT + 3, (size_t)(3 * (W_STAT + 3 + 1)), s.att.size() - n0);
    }
    // a flipped bit in the header, or in an entry: the CRC fails, error_o, and the bus stays idle
    for (size_t word : {(size_t)C::H1_CYCLE.word, rom_addr(1, C::E1_START.word), rom_addr(2, 7)}) {
        rom = build_rom(H1, 0, es);
        rom[word] ^= 1u << 5;   // the CRC (H3) no longer matches
        write_rom(rom);
        Sim s;
        s.run_until(4 * H1);
        char m[96];
        std::snprintf(m, sizeof m, "bit flipped in ROM word %zu: error_o", word);
        CHECK_EQ(G_ROM, m, 1, s.top->error_o);
        std::snprintf(m, sizeof m, "bit flipped in ROM word %zu: bus accesses", word);
        CHECK_EQ(G_ROM, m, 0, s.att.size() + (s.in_att ? 1 : 0));
    }
}

void scenario_four() {
    std::printf("== four: a four-slot COPY and a four-slot TIME (E0 flag FOUR_SLOT) beside a three-buffer STATUS\n");
    const unsigned FS = C::EFLAG_FOUR_SLOT;
    std::vector<Entry> es = {
        {COPY, FS, 0, W_COPY, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}},
        {TIME, FS, 1, 1, S_TIME, L_TIME, 0, 0, {{0, TIME_BASE}, {1, TIME_BASE}}},
        {STATUS, 0, 2, W_STAT, S_STAT, L_STAT, 0, 0, {{1, STAT_BASE}}},
    };
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Producer4 prod{0, SRC_BASE, W_COPY};
    Consumer4 cons{1, DST_BASE, W_COPY + 1}, time0{0, TIME_BASE, 2}, time1{1, TIME_BASE, 2};
    Consumer stat{1, STAT_BASE, W_STAT + 1};
    prod.init(s);
    cons.init(s);
    time0.init(s);
    time1.init(s);
    s.wr(1, STAT_BASE, 0x3, 0x0101);
    const uint64_t T0 = t0_of((int)es.size());
    // Import New (3 control + W loads), Export: control load, W words, taken_at, Slot, Actual
    const size_t A_NEW = 3 + W_COPY + (1 + W_COPY + 1 + 2);
    unsigned sb = prod.publish(s, value(0));
    CHECK_EQ(G_DATA, "four: the producer's first buffer (ReadLocked 1: pair 1, Slot1 0)", 4, sb);
    std::vector<uint32_t> got;
    for (unsigned c = 0; c < 3; ++c) {
        const uint64_t Cs = T0 + c * H1;
        s.run_until(Cs + TAIL);
        char m[128];
        std::vector<Attempt> cp = s.attempts(Cs + S_COPY, Cs + S_COPY + L_COPY);
        bool fresh = c != 1;                                    // a value published before cycles 0 and 2
        std::snprintf(m, sizeof m, "four cycle %u COPY (%s)", c, fresh ? "New" : "Old: one control load");
        check_slot_timing(m, cp, Cs + S_COPY, fresh ? A_NEW : 1);
        if (fresh && cp.size() == A_NEW) {
            // source: load, ReadLocked store, load; dest: control load; words; taken_at; Slot; Actual
            unsigned db = c == 0 ? 4 : 2;                       // dest ReadLocked 1 (pair 0) / 4 (pair 1)
            std::vector<std::pair<bool, uint32_t>> exp = {
                {false, ba(0, SRC_BASE)}, {true, ba(0, SRC_BASE)}, {false, ba(0, SRC_BASE)},
                {false, ba(1, DST_BASE)}};
            for (unsigned i = 0; i < W_COPY; ++i) {
                exp.push_back({false, ba(0, SRC_BASE + 1 + (sb - 1) * W_COPY + i)});
                exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + i)});
            }
            exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + W_COPY)});
            exp.push_back({true, ba(1, DST_BASE)});
            exp.push_back({true, ba(1, DST_BASE)});
            for (size_t k = 0; k < A_NEW; ++k) {
                std::snprintf(m, sizeof m, "four cycle %u COPY access %zu: {we, board, word}", c, k + 1);
                CHECK_HEX(G_DATA, m, (uint64_t)exp[k].first << 16 | exp[k].second,
                          (uint64_t)cp[k].we << 16 | cp[k].adr);
            }
            uint32_t ctl = s.rd(1, DST_BASE);
            std::snprintf(m, sizeof m, "four cycle %u: destination control word {Slot1, Slot0, ReadLocked, Actual}", c);
            CHECK_HEX(G_DATA, m, c == 0 ? 0x01000104u : 0x01010402u, ctl);
        }
        bool isnew = cons.import(s, got);
        std::snprintf(m, sizeof m, "four cycle %u: consumer Import returns %s", c, fresh ? "New" : "Old");
        CHECK_EQ(G_DATA, m, fresh, isnew);
        std::snprintf(m, sizeof m, "four cycle %u: consumer control accesses (wait-free)", c);
        CHECK_EQ(G_DATA, m, fresh ? 3 : 1, cons.accesses);
        std::snprintf(m, sizeof m, "four cycle %u: value word 0", c);
        CHECK_HEX(G_DATA, m, value(c < 2 ? 0 : 1)[0], got[0]);
        if (fresh && cp.size() >= 3) {
            std::snprintf(m, sizeof m, "four cycle %u: taken_at = time_o in the ack clock of the Import's last control load", c);
            CHECK_EQ(G_DATA, m, cp[2].end, got[W_COPY]);
        }
        isnew = cons.import(s, got);
        std::snprintf(m, sizeof m, "four cycle %u: a second Import returns Old", c);
        CHECK_EQ(G_DATA, m, 0, isnew);
        // TIME, four-slot, two destinations: per destination load, value, taken_at, Slot, Actual
        std::vector<Attempt> tm = s.attempts(Cs + S_TIME, Cs + S_TIME + L_TIME);
        std::snprintf(m, sizeof m, "four cycle %u TIME (2 four-slot destinations)", c);
        check_slot_timing(m, tm, Cs + S_TIME, 2 * (1 + 1 + 1 + 2));
        for (int b = 0; b < 2; ++b) {
            Consumer4 &t = b ? time1 : time0;
            isnew = t.import(s, got);
            std::snprintf(m, sizeof m, "four cycle %u TIME on board %d: New, value = taken_at = slot start", c, b);
            check(G_DATA, isnew && got[0] == Cs + S_TIME && got[1] == Cs + S_TIME,
                  "%s: expected New %" PRIu64 "/%" PRIu64 ", got %s %u/%u", m, Cs + S_TIME, Cs + S_TIME,
                  isnew ? "New" : "Old", got[0], got[1]);
        }
        if (c == 1) sb = prod.publish(s, value(1));
        if (c == 1) CHECK_EQ(G_DATA, "four: the producer's second buffer (ReadLocked 4: pair 0, Slot0 0)", 2, sb);
    }
    // STATUS (three-buffer): channel 0 delivered twice, channel 1 (TIME) 2 destinations x 3 cycles
    bool isnew = stat.import(s, got);
    CHECK_EQ(G_DATA, "four: STATUS Import New", 1, isnew);
    CHECK_HEX(G_DATA, "four: STATUS channel 0 {transfers, retries}", 2u << 16 | 0u, got[1]);
    CHECK_HEX(G_DATA, "four: STATUS channel 0 {abandoned, corrupt}", 0u, got[2]);
    CHECK_HEX(G_DATA, "four: STATUS channel 1 {transfers, retries}", 6u << 16 | 0u, got[3]);
    CHECK_HEX(G_DATA, "four: STATUS channel 1 {abandoned, corrupt}", 0u, got[4]);

    // A destination Actual store that lands but times out, then the link is
    // down to the slot end: the next cycle's control-word load reads it back
    // (the tried buffer, 3 bits in the state RAM) and publishes nothing.
    const uint64_t C3 = T0 + 4 * H1;                            // (cycle 3's COPY ran during the STATUS read)
    s.run_until(C3 - H1 + TAIL);
    sb = prod.publish(s, value(3));
    size_t seen = 0;
    s.fault = [&](const Attempt &a) {
        if (a.start < C3 || a.start >= C3 + L_COPY) return 0;
        if (++seen == A_NEW) {
            s.dead_next = 1u << 1;   // link down from the attempt's second clock on
            return 3;
        }
        return 0;
    };
    s.run_until(C3 + L_COPY);
    s.fault = nullptr;
    s.top->fi_dead_i = 0;
    s.run_until(C3 + TAIL);
    uint32_t ctl3 = s.rd(1, DST_BASE);
    isnew = cons.import(s, got);
    check(G_FAULT, isnew && got[0] == value(3)[0],
          "four: landed Actual store: the consumer sees the value once: expected New 0x%08x, got %s 0x%08x",
          value(3)[0], isnew ? "New" : "Old", got[0]);
    const uint64_t C4 = C3 + H1;
    s.run_until(C4 + TAIL);
    std::vector<Attempt> v4 = s.attempts(C4 + S_COPY, C4 + S_COPY + L_COPY);
    CHECK_EQ(G_FAULT, "four: next cycle: 2 accesses (source control load: Old; destination control load: landed)",
             2, v4.size());
    if (v4.size() >= 2) CHECK_HEX(G_FAULT, "four: next cycle: access 2 loads the destination control word",
                                  (uint64_t)ba(1, DST_BASE), v4[1].adr);
    CHECK_HEX(G_FAULT, "four: next cycle: the destination's Actual and slot bytes are unchanged", ctl3 & 0xFFFF00FFu,
              s.rd(1, DST_BASE) & 0xFFFF00FFu);
    isnew = cons.import(s, got);
    CHECK_EQ(G_FAULT, "four: next cycle: the consumer's Import returns Old (not published twice)", 0, isnew);
    isnew = stat.import(s, got);
    CHECK_EQ(G_FAULT, "four: STATUS channel 0 transfers (the landed store counted once, in the next cycle)", 3,
             got[1] >> 16);
    CHECK_EQ(G_FAULT, "four: STATUS channel 0 abandoned (the slot of the landed store)", 1, got[2] >> 16);

    // Entry checks of the flag: a fourth buffer past the RAM (base + 4 * (W + 1)
    // = 1024 for a destination at 0x3F0; three buffers would fit) and SYNC with
    // FOUR_SLOT make the entry invalid: skipped, rom_errors + 1 a cycle.
    struct Case { const char *what; unsigned hflags, flags, dbase; size_t errs; };
    const Case cases[] = {
        {"three-buffer COPY to 0x3F0 (3 buffers fit)", 0, 0, 0x3F0, 0},
        {"four-slot COPY to 0x3F0 (the fourth buffer does not fit)", 0, FS, 0x3F0, 1},
        {"sync mode, entry 0 SYNC with FOUR_SLOT", C::HFLAG_SYNC_MODE, C::EFLAG_SYNC | FS, DST_BASE, 1},
    };
    for (const Case &k : cases) {
        std::vector<Entry> e2 = es;
        e2[0].flags = k.flags;
        e2[0].dst[0].base = k.dbase;
        write_rom(build_rom(H1, k.hflags, e2));
        Sim s2;
        s2.run_until(T0 + TAIL);
        char m[128];
        std::snprintf(m, sizeof m, "four: %s: rom_errors_o after cycle 0", k.what);
        CHECK_EQ(G_ROM, m, k.errs, s2.top->rom_errors_o);
        std::snprintf(m, sizeof m, "four: %s: accesses in the COPY slot", k.what);
        check(G_ROM, (s2.attempts(T0 + S_COPY, T0 + S_COPY + L_COPY).size() == 0) == (k.errs != 0),
              "%s: expected %s, got %zu", m, k.errs ? "none" : "some",
              s2.attempts(T0 + S_COPY, T0 + S_COPY + L_COPY).size());
    }
}
