// ctrl_scenarios_faults.cpp -- test_controller scenarios faults (retried fault
// kinds), dead (a board's link down), sync (position-synchronised mode) and
// abandon (the abandoned count of a COPY whose Import ends without choosing).
#include "ctrl_bench.h"

// Fault kinds 1..3 on single accesses of the COPY slot, one cycle each.
void scenario_faults() {
    std::printf("== faults: kinds 1, 2, 3 are retried; a landed Actual store is not published twice\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);

    struct Plan { int kind; size_t nth; const char *what; };   // nth: attempt of the slot, 1-based
    const Plan plans[3] = {{1, 1, "source Actual load"}, {2, 2, "source ReadLocked store"}, {3, 6, "first word store"}};
    for (unsigned c = 1; c <= 3; ++c) {
        const Plan &pl = plans[c - 1];
        const uint64_t C = T0 + c * H1;
        u.prod.publish(s, value(c));
        size_t seen = 0;
        s.fault = [&](const Attempt &a) {
            if (a.start < C || a.start >= C + L_COPY) return 0;
            return ++seen == pl.nth ? pl.kind : 0;
        };
        s.run_until(C + TAIL);
        s.fault = nullptr;
        std::vector<Attempt> v = s.attempts(C, C + L_COPY);
        char m[160];
        if (v.size() < pl.nth + 1) {
            check(G_FAULT, false, "kind %d on the %s: expected a retry, got %zu attempts", pl.kind, pl.what, v.size());
            continue;
        }
        const Attempt &f = v[pl.nth - 1], &r = v[pl.nth];
        int exp_res = pl.kind == 1 ? 2 : 3;
        std::snprintf(m, sizeof m, "kind %d on the %s: the attempt ends with %s", pl.kind, pl.what,
                      exp_res == 2 ? "err" : "a timeout (1 ack, 2 err, 3 timeout)");
        CHECK_EQ(G_FAULT, m, exp_res, f.result);
        if (exp_res == 3) {
            std::snprintf(m, sizeof m, "kind %d: cyc dropped after TIMEOUT clocks without ack", pl.kind);
            CHECK_EQ(G_FAULT, m, TMO, f.end - f.start);
        }
        std::snprintf(m, sizeof m, "kind %d: the same access is retried (we, board, word)", pl.kind);
        CHECK_HEX(G_FAULT, m, (uint64_t)f.we << 16 | f.adr, (uint64_t)r.we << 16 | r.adr);
        std::snprintf(m, sizeof m, "kind %d: cyc low at least one clock before the retry (gap)", pl.kind);
        check(G_FAULT, r.start >= f.end + (f.result == 3 ? 1 : 2), "%s: expected retry start >= %" PRIu64
              ", got %" PRIu64, m, f.end + (f.result == 3 ? 1 : 2), r.start);
        size_t performed = 0;
        for (const RamOp &op : s.ram)
            if (op.t >= f.start && op.t <= f.end + 1 && op.board == (int)(f.adr >> AW) &&
                op.adr == (f.adr & AMASK) && op.we == f.we)
                ++performed;
        std::snprintf(m, sizeof m, "kind %d: the RAM performed the faulted access (1) or not (0)", pl.kind);
        CHECK_EQ(G_FAULT, m, pl.kind == 2 ? 0 : 1, performed);
        bool isnew = u.cons.import(s, got);
        std::snprintf(m, sizeof m, "kind %d: the value still arrives (New, all words)", pl.kind);
        check(G_FAULT, isnew && got[0] == value(c)[0] && got[1] == value(c)[1] && got[2] == value(c)[2],
              "%s: expected New %08x %08x %08x, got %s %08x %08x %08x", m, value(c)[0], value(c)[1], value(c)[2],
              isnew ? "New" : "Old", got[0], got[1], got[2]);
    }
    bool isnew = u.stat.import(s, got);
    CHECK_HEX(G_FAULT, "STATUS after the three faults: channel 0 {transfers, retries}", 4u << 16 | 3u, got[1]);

    // kind 3 on the final Actual store, then the link is down to the slot end:
    // the store landed, so the next cycle's control-word load shows it and nothing is published again.
    const uint64_t C4 = T0 + 4 * H1;
    u.prod.publish(s, value(4));
    size_t seen = 0;
    const size_t A = 3 + W_COPY + (W_COPY + 3);
    s.fault = [&](const Attempt &a) {
        if (a.start < C4 || a.start >= C4 + L_COPY) return 0;
        if (++seen == A) {
            s.dead_next = 1u << 1;   // link down from the attempt's second clock on
            return 3;
        }
        return 0;
    };
    s.run_until(C4 + L_COPY);
    s.fault = nullptr;
    s.top->fi_dead_i = 0;
    s.run_until(C4 + TAIL);
    uint32_t act4 = s.rd(1, DST_BASE) & 0xFF;
    isnew = u.cons.import(s, got);
    check(G_FAULT, isnew && got[0] == value(4)[0],
          "landed Actual store: the consumer sees the value once: expected New 0x%08x, got %s 0x%08x",
          value(4)[0], isnew ? "New" : "Old", got[0]);
    const uint64_t C5 = C4 + H1;
    s.run_until(C5 + TAIL);
    std::vector<Attempt> v5 = s.attempts(C5, C5 + L_COPY);
    CHECK_EQ(G_FAULT, "next cycle: 2 accesses (source Actual load, the destination control-word load)", 2,
             v5.size());
    if (v5.size() >= 2) CHECK_HEX(G_FAULT, "next cycle: access 2 loads the destination control word",
                                  (uint64_t)ba(1, DST_BASE), v5[1].adr);
    CHECK_EQ(G_FAULT, "next cycle: the destination Actual is unchanged", act4, s.rd(1, DST_BASE) & 0xFF);
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_FAULT, "next cycle: the consumer's Import returns Old (not published twice)", 0, isnew);
    isnew = u.stat.import(s, got);
    CHECK_EQ(G_FAULT, "STATUS: channel 0 transfers (the landed store counted once, in the next cycle)", 5,
             got[1] >> 16);
    check(G_FAULT, (got[1] & 0xFFFF) > 4, "STATUS: channel 0 retries: expected > 4 (3 faults, then the dead link), got %u",
          got[1] & 0xFFFF);
    CHECK_EQ(G_FAULT, "STATUS: channel 0 abandoned (the slot of the landed store)", 1, got[2] >> 16);
}

// A board's link is down for a whole cycle: first board 1 (COPY's and STATUS's
// destination, TIME's second), then board 0 (COPY's source, TIME's first).
void scenario_dead() {
    std::printf("== dead: a board link down for a cycle; slots stay on time, the others are served\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);
    u.time0.import(s, got);
    u.time1.import(s, got);
    u.prod.publish(s, value(1));
    const uint32_t starts[3] = {S_COPY, S_TIME, S_STAT}, lens[3] = {L_COPY, L_TIME, L_STAT};
    const char *names[3] = {"COPY", "TIME", "STATUS"};
    for (int dead = 1; dead >= 0; --dead) {
        const uint64_t C = T0 + (dead ? 1 : 3) * H1;
        s.run_until(C);
        s.top->fi_dead_i = 1u << dead;
        s.run_until(C + H1);
        s.top->fi_dead_i = 0;
        for (int e = 0; e < 3; ++e) {
            uint64_t S = C + starts[e], D = S + lens[e];
            std::vector<Attempt> v = s.attempts(S, D);
            char m[160];
            std::snprintf(m, sizeof m, "board %d dead, %s: first access at slot start + FETCH_CYCLES", dead, names[e]);
            CHECK_EQ(G_DEAD, m, S + F, v.empty() ? 0 : v[0].start);
            uint64_t last_start = 0, last_end = 0;
            size_t to_dead = 0, failed = 0;
            for (const Attempt &a : v) {
                last_start = std::max(last_start, a.start);
                last_end = std::max(last_end, a.end);
                to_dead += (a.adr >> AW) == (unsigned)dead;
                failed += a.result == 3;
            }
            std::snprintf(m, sizeof m, "board %d dead, %s: no access starts after D-TIMEOUT-2 (D = %" PRIu64 ")",
                          dead, names[e], D);
            check(G_DEAD, last_start <= D - TMO - 2, "%s: expected last start <= %" PRIu64 ", got %" PRIu64, m,
                  D - TMO - 2, last_start);
            std::snprintf(m, sizeof m, "board %d dead, %s: every access ends before the deadline", dead, names[e]);
            check(G_DEAD, last_end < D, "%s: expected last end < %" PRIu64 ", got %" PRIu64, m, D, last_end);
            bool source = dead == 0 && e == 0;   // COPY from the dead board: retried until the deadline
            if (source) {
                std::snprintf(m, sizeof m, "board %d dead, %s: only the source is tried, every try times out", dead,
                              names[e]);
                check(G_DEAD, to_dead == v.size() && failed == v.size() && v.size() > 2,
                      "%s: expected > 2 attempts, all to board %d and all timed out, got %zu attempts, %zu to it, "
                      "%zu timed out", m, dead, v.size(), to_dead, failed);
            } else if (!(dead == 0 && e == 2)) {   // STATUS does not touch board 0
                std::snprintf(m, sizeof m, "board %d dead, %s: the dead destination is tried twice, then dropped",
                              dead, names[e]);
                check(G_DEAD, to_dead == 2 && failed == 2, "%s: expected 2 attempts to it, both timed out, got %zu, "
                      "%zu timed out", m, to_dead, failed);
            }
        }
        // TIME still reaches the healthy board, whether the dead one comes first or second
        int live = 1 - dead;
        bool isnew = (live ? u.time1 : u.time0).import(s, got);
        char m[128];
        std::snprintf(m, sizeof m, "board %d dead: TIME still published to board %d (New, value = slot start)", dead,
                      live);
        check(G_DEAD, isnew && got[0] == C + S_TIME, "%s: expected New %" PRIu64 ", got %s %u", m, C + S_TIME,
              isnew ? "New" : "Old", got[0]);
        (dead ? u.time0 : u.time1).import(s, got);   // catch up with the other one
        if (dead == 1) {
            const uint64_t C2 = C + H1;
            s.run_until(C2 + TAIL);
            std::vector<Attempt> v2 = s.attempts(C2, C2 + L_COPY);
            CHECK_EQ(G_DEAD, "link back: COPY starts on time", C2 + F, v2.empty() ? 0 : v2[0].start);
            isnew = u.cons.import(s, got);
            check(G_DEAD, isnew && got[0] == value(1)[0],
                  "link back: the abandoned value is delivered: expected New 0x%08x, got %s 0x%08x", value(1)[0],
                  isnew ? "New" : "Old", got[0]);
            isnew = u.stat.import(s, got);
            CHECK_HEX(G_DEAD, "STATUS: channel 0 {abandoned, corrupt}", 1u << 16 | 0u, got[2]);
            CHECK_HEX(G_DEAD, "STATUS: channel 1 (TIME) {abandoned, corrupt}: only the dead destination", 1u << 16,
                      got[4]);
            CHECK_HEX(G_DEAD, "STATUS: channel 1 (TIME) {transfers, retries}: 2 + 1 + 2, 2 retries", 5u << 16 | 2u,
                      got[3]);
            u.time0.import(s, got);
            u.time1.import(s, got);
        }
    }
}

// The drop run from the ROM: H2 = 3, board 1's link down for a
// cycle: COPY's only destination is tried 3 times (not 2) and dropped; TIME
// still reaches board 0 (tried first) and drops board 1 after 3 failures.
void scenario_droprun() {
    std::printf("== droprun: H2 drop run 3: a dead destination is tried 3 times in a row, then dropped\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es, 3));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);
    u.time0.import(s, got);
    u.time1.import(s, got);
    u.prod.publish(s, value(1));
    const uint64_t C = T0 + H1;
    s.run_until(C);
    s.top->fi_dead_i = 1u << 1;
    s.run_until(C + H1);
    s.top->fi_dead_i = 0;
    const uint32_t starts[2] = {S_COPY, S_TIME}, lens[2] = {L_COPY, L_TIME};
    const char *names[2] = {"COPY", "TIME"};
    for (int e = 0; e < 2; ++e) {
        std::vector<Attempt> v = s.attempts(C + starts[e], C + starts[e] + lens[e]);
        size_t to_dead = 0, failed = 0;
        for (const Attempt &a : v) {
            to_dead += (a.adr >> AW) == 1u;
            failed += (a.adr >> AW) == 1u && a.result == 3;
        }
        char m[160];
        std::snprintf(m, sizeof m, "drop run 3, %s: the dead destination is tried 3 times, then dropped", names[e]);
        check(G_DEAD, to_dead == 3 && failed == 3, "%s: expected 3 attempts to it, all timed out, got %zu, %zu timed out",
              m, to_dead, failed);
    }
    bool isnew = u.time0.import(s, got);
    check(G_DEAD, isnew && got[0] == C + S_TIME, "drop run 3: TIME still published to board 0: expected New %" PRIu64
          ", got %s %u", C + S_TIME, isnew ? "New" : "Old", got[0]);
}

// Position-synchronised mode: entry 0 is the SYNC COPY.  After the last entry the
// controller polls the SYNC source's Actual every POLL clocks; a new value starts
// the next cycle in the clock after the poll's ack, else the cycle ends at H1.
void scenario_sync() {
    std::printf("== sync: polls every POLL clocks, a new position starts the cycle, else H1 does\n");
    const int POLL = 16;
    std::vector<Entry> es = schedule();
    es[0].flags = C::EFLAG_SYNC;     // SYNC
    es.pop_back();                   // COPY, TIME
    write_rom(build_rom(H1, C::HFLAG_SYNC_MODE, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    bool isnew = u.cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(0)[0], "sync cycle 0: the position arrives: expected New 0x%08x, got %s 0x%08x",
          value(0)[0], isnew ? "New" : "Old", got[0]);
    // polls: loads of the source's control word after the last slot
    auto polls = [&](uint64_t t0, uint64_t t1) {
        std::vector<Attempt> v;
        for (const Attempt &a : s.attempts(t0, t1))
            if (!a.we && a.adr == ba(0, SRC_BASE)) v.push_back(a);
        return v;
    };
    std::vector<Attempt> p0 = polls(T0 + S_TIME + L_TIME, T0 + TAIL);
    check(G_DATA, p0.size() >= 5, "sync cycle 0: the source is polled after the last slot: expected >= 5 polls, got %zu",
          p0.size());
    for (size_t i = 1; i < p0.size() && i < 4; ++i) {
        char m[96];
        std::snprintf(m, sizeof m, "sync cycle 0: poll %zu starts POLL clocks after poll %zu", i + 1, i);
        CHECK_EQ(G_TIMING, m, p0[i - 1].start + POLL, p0[i].start);
    }
    // a new position: the next cycle starts in the clock after the poll that sees it
    u.prod.publish(s, value(1));
    const uint64_t t_pub = s.now;
    s.run_until(T0 + H1 + TAIL);
    std::vector<Attempt> p1 = polls(t_pub, T0 + H1);
    uint64_t c1 = 0;
    for (const Attempt &a : p1)
        if (a.start > t_pub) { c1 = a.end + 1; break; }    // the first poll after the Actual store
    std::vector<Attempt> v1 = s.attempts(c1, c1 + L_COPY);
    check(G_TIMING, c1 && !v1.empty() && v1[0].start == c1 + S_COPY + F,
          "sync: a new position starts the cycle in the clock after the poll's ack (%" PRIu64
          "): SYNC COPY first access: expected %" PRIu64 ", got %" PRIu64, c1, c1 + S_COPY + F,
          v1.empty() ? 0 : v1[0].start);
    check(G_TIMING, c1 && c1 < T0 + H1, "sync: the cycle started early: expected before the H1 end %" PRIu64
          ", got %" PRIu64, T0 + H1, c1);
    if (c1) check_slot_timing("sync cycle 1 SYNC COPY (new)", v1, c1 + S_COPY, 3 + W_COPY + 1 * (W_COPY + 3));
    isnew = u.cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(1)[0], "sync cycle 1: the new position arrives: expected New 0x%08x, got %s 0x%08x",
          value(1)[0], isnew ? "New" : "Old", got[0]);
    // no new position: the cycle ends at H1
    s.run_until(c1 + H1 + TAIL);
    std::vector<Attempt> v2 = s.attempts(c1 + H1, c1 + H1 + L_COPY);
    CHECK_EQ(G_TIMING, "sync: without a new position the next cycle starts at H1: first access", c1 + H1 + S_COPY + F,
             v2.empty() ? 0 : v2[0].start);
    std::vector<Attempt> p2 = polls(c1 + S_TIME + L_TIME, c1 + H1);
    uint64_t last_end = 0;
    for (const Attempt &a : p2) last_end = std::max(last_end, a.end);
    check(G_TIMING, !p2.empty() && last_end <= c1 + H1, "sync: polls until the cycle end: expected polls ending by %"
          PRIu64 ", got %zu polls, last end %" PRIu64, c1 + H1, p2.size(), last_end);
}

// The abandoned count of a COPY slot whose Import ends without choosing (its
// source board dead for the slot): the destinations still in need are the
// channel's stored need (state RAM), not what the last Export of another
// channel left in the controller's registers.  The regression 7e46d73 fixed
// (the field-by-field state-RAM write-back of 59c3c2d, the abandoned count
// taken from the Export's need unconditionally) counted 0 here instead of 1:
// its mutant tb/mutants/controller/stale_need.sed must fail this scenario.
void scenario_abandon() {
    std::printf("== abandon: a COPY whose Import ends without choosing counts the channel's stored need\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);
    bool isnew = u.stat.import(s, got);
    const uint32_t ab0 = got[2] >> 16;            // channel 0 abandoned before (0)
    u.prod.publish(s, value(1));
    // Cycle 1: board 1 (COPY's destination) dead for the COPY slot only: the
    // Import chooses value(1), the Export drops the destination: need stays 1,
    // abandoned + 1.  TIME and STATUS then publish to every destination, so
    // the last Export before cycle 2's COPY published its destination 0.
    const uint64_t C1 = T0 + H1, C2 = C1 + H1, C3 = C2 + H1;
    s.run_until(C1);
    s.top->fi_dead_i = 1u << 1;
    s.run_until(C1 + L_COPY);
    s.top->fi_dead_i = 0;
    // Cycle 2: board 0 (COPY's source) dead for the COPY slot: the Import is
    // retried to the deadline and never chooses, no Export runs: the
    // destination still needs value(1): abandoned + 1.
    s.run_until(C2);
    s.top->fi_dead_i = 1u << 0;
    s.run_until(C2 + L_COPY);
    s.top->fi_dead_i = 0;
    std::vector<Attempt> v2 = s.attempts(C2, C2 + L_COPY);
    size_t src_fail = 0;
    for (const Attempt &a : v2) src_fail += (a.adr >> AW) == 0 && a.result != 1;
    check(G_FAULT, !v2.empty() && src_fail == v2.size(),
          "abandon: cycle 2's COPY slot only tries its dead source (the Import never chooses): expected every one "
          "of %zu attempts to board 0 and failed, got %zu", v2.size(), src_fail);
    // Cycle 3: healthy: the Import finds value(1) Old and serves the stored need.
    s.run_until(C3 + TAIL);
    isnew = u.cons.import(s, got);
    check(G_FAULT, isnew && got[0] == value(1)[0],
          "abandon: cycle 3 delivers the value abandoned twice: expected New 0x%08x, got %s 0x%08x", value(1)[0],
          isnew ? "New" : "Old", got[0]);
    isnew = u.stat.import(s, got);
    check(G_ABANDON, isnew && (got[2] >> 16) == ab0 + 2,
          "abandon: STATUS channel 0 abandoned after cycles 1 (destination dead) and 2 (source dead, Import ended "
          "without choosing; the count must come from the state RAM's need): expected %u, got %u", ab0 + 2,
          got[2] >> 16);
}
