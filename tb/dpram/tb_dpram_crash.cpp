// tb_dpram_crash.cpp -- crash mode: one side frozen or reset at every access point.
#include "tb_dpram_random.h"

namespace tbd {


// -------------------------------------------------------------------- crash
//
// A victim side stops at access point k of one of its calls: frozen forever
// (never resumed) or reset (its coroutine restarted later, re-attaching from
// the RAM).  The survivor keeps calling; every call must finish within its
// fixed bound and every value stay consistent.
struct CrashResult {
    uint64_t runs = 0, not_reached = 0, survivor_calls = 0, cycles = 0;
    std::string first_not_reached;   // the first crash point never reached, in words
    Verdict verdict;
};

struct CrashPlan : public IssueGate {
    Run &run;
    Driver &drv;
    bool victim_producer, reset;
    unsigned k;
    int vport;
    SideCtx &victim, &surv;
    uint64_t crash_call;
    bool crashed = false;
    uint64_t crash_cycle = 0, restart_at = 0, surv_calls_at_crash = 0;
    uint8_t held = 0;            // ReadLocked of a frozen consumer
    uint64_t held_writes = 0;    // producer writes to it in Exports begun after the freeze
    uint64_t prod_calls_at_crash = 0, next_export_cycle = 0;

    CrashPlan(Run &r, Driver &d, bool vp, bool rs, unsigned kk, uint64_t call)
        : run(r), drv(d), victim_producer(vp), reset(rs), k(kk),
          vport(vp ? r.chan.prod_port : r.chan.cons_port), victim(vp ? r.prod : r.cons),
          surv(vp ? r.cons : r.prod), crash_call(call) {}

    // Stop the victim just before it issues access k of call crash_call or later.
    bool stop_before_issue(int port) override {
        SimCpu &vcpu = g_bus->cpu[vport];
        if (crashed || port != vport || victim.calls < crash_call || vcpu.accesses - victim.call_start_acc != k)
            return false;
        crashed = true;
        crash_cycle = g_bus->cycle();
        surv_calls_at_crash = surv.calls;
        prod_calls_at_crash = run.prod.calls;
        drv.frozen[vport] = true;
        vcpu.has_request = false;
        if (victim_producer) {
            run.chk.producer_restarted();
            run.chk.set_import_iteration_limit(1);   // Actual can no longer change
        } else {
            run.chk.consumer_restarted();
            held = g_bus->ram_byte(run.chan.base + ALB_OFF_READLOCKED);
        }
        return true;
    }
};

void crash_run(uint32_t size, bool victim_producer, bool reset, unsigned k, uint64_t seed, CrashResult &cr)
{
    std::mt19937_64 rng(seed);
    Timing tm(seed * 7 + 3);
    Channel c{64, size, static_cast<int>(seed & 1), static_cast<int>(1 - (seed & 1))};
    Run run(c);
    Driver drv(tm);
    CrashPlan plan(run, drv, victim_producer, reset, k, 3 + rng() % 5);
    drv.gate = &plan;
    SimCpu &vcpu = g_bus->cpu[plan.vport];
    const uint64_t after = 300;
    bool restarted = false, gave_up = false;
    tm.log_ratio = static_cast<double>(rng() % 5) - 2.0;
    const char *vname = victim_producer ? "producer" : "consumer", *sname = victim_producer ? "consumer" : "producer";
    const char *vcall = victim_producer ? "Export" : "Import";
    const uint64_t c0 = g_bus->cycle();
    uint64_t victim_most = 0;    // the most accesses the victim made in one call before the crash
    char m[320];
    for (;;) {
        if (g_bus->cycle() - c0 > g_limits.crash_run_cycles) {
            std::snprintf(m, sizeof m, "watchdog: a crash run (%s %s at access %u of %s, %u-byte payload, seed %llu) "
                          "went on for %llu cycles: %s; expected it within %llu cycles",
                          vname, reset ? "reset" : "frozen", k, vcall, size, static_cast<unsigned long long>(seed),
                          static_cast<unsigned long long>(g_bus->cycle() - c0),
                          plan.crashed ? "the survivor had not made its calls" : "the crash point was not reached",
                          static_cast<unsigned long long>(g_limits.crash_run_cycles));
            cr.verdict.add_watchdog(m);
            break;
        }
        tm.drift(g_bus->cycle(), c.prod_port);
        // A frozen consumer's ReadLocked must be honoured by every Export that
        // begins after the freeze (the one under way may still be writing the
        // buffer the consumer had not yet confirmed).  Four-slot: it holds
        // both buffers of its pair.
        const bool fs = g_kind == ALB_FOUR_SLOT;
        if (plan.crashed && !reset && !victim_producer && plan.held >= 1 && plan.held <= (fs ? 4 : 3)) {
            if (!plan.next_export_cycle && run.prod.calls > plan.prod_calls_at_crash)
                plan.next_export_cycle = g_bus->cycle();
            if (plan.next_export_cycle) {
                int b0 = fs ? 1 + 2 * ((plan.held - 1) >> 1) : plan.held, b1 = fs ? b0 + 1 : b0;
                if (run.chk.producer_wrote_since(b0, plan.next_export_cycle) ||
                    run.chk.producer_wrote_since(b1, plan.next_export_cycle))
                    ++plan.held_writes;
            }
        }
        if (plan.crashed && reset && !restarted && g_bus->cycle() >= plan.crash_cycle + 1 + (seed % 400)) {
            restarted = true;
            drv.frozen[plan.vport] = false;
            plan.victim.in_call = false;   // the call under way is abandoned
            // Four-slot: an abandoned Export that stored its Slot byte made its
            // value complete, and a consumer may have read it (unpublished, but
            // whole): the restarted producer exports a new value, not that one
            // again (the checker tells values apart by their sequence number).
            if (victim_producer && g_kind == ALB_FOUR_SLOT) ++plan.victim.next_seq;
            vcpu.start(victim_producer ? producer_program : consumer_program);
            if (victim_producer) run.chk.set_import_iteration_limit(-1);
        }
        if (!plan.crashed && plan.victim.in_call)
            victim_most = std::max(victim_most, vcpu.accesses - plan.victim.call_start_acc);
        drv.cycle();
        if (vcpu.faulted || g_bus->cpu[1 - plan.vport].faulted || drv.ram_dead) break;
        if (plan.crashed && plan.surv.calls >= plan.surv_calls_at_crash + after) break;
        // A protocol violation already names the fault: no need to go on.
        if (counted_violations(run.chk)) break;
        std::string late = run.overdue_call(drv.frozen);
        if (!late.empty()) {
            cr.verdict.add_watchdog(late);
            break;
        }
        // The crash point is searched for in the planned call and the next
        // ones (an Import with new data is longer than one without); give up
        // after a bounded number of calls.
        if (!plan.crashed && plan.victim.calls > plan.crash_call + g_limits.crash_search_calls) {
            gave_up = true;
            break;
        }
        if (vcpu.finished() || g_bus->cpu[1 - plan.vport].finished()) {
            std::snprintf(m, sizeof m, "the %s program returned (attach result %d), expected it to keep calling",
                          vcpu.finished() ? vname : sname, vcpu.finished() ? plan.victim.attach_rc : plan.surv.attach_rc);
            cr.verdict.add_other(m);
            break;
        }
    }
    if (drv.ram_dead) cr.verdict.add_other(drv.dead_why);
    cr.cycles += g_bus->cycle() - c0;
    ++cr.runs;
    if (!plan.crashed) {
        ++cr.not_reached;
        if (gave_up && cr.first_not_reached.empty()) {
            std::snprintf(m, sizeof m, "the %s never reached access %u of an %s in %llu calls (%u-byte payload; "
                          "its longest call made %llu accesses, expected %u + %u)",
                          vname, k, vcall, static_cast<unsigned long long>(g_limits.crash_search_calls), size,
                          static_cast<unsigned long long>(victim_most), victim_producer ? export_overhead() : 3u, (size + 3) / 4);
            cr.first_not_reached = m;
        }
    } else if (!cr.verdict.watchdog && !counted_violations(run.chk)) {
        uint64_t made = plan.surv.calls - plan.surv_calls_at_crash;
        cr.survivor_calls += made;
        if (made < after) {
            std::snprintf(m, sizeof m, "after the %s crashed at access %u the %s made only %llu calls, expected %llu",
                          vname, k, sname, static_cast<unsigned long long>(made), static_cast<unsigned long long>(after));
            cr.verdict.add_other(m);
        }
        // Four-slot: the value the frozen producer completed (Slot stored)
        // without publishing it may have been read too.
        uint64_t ls = run.chk.last_seq(), pub = run.chk.newest_published_seq();
        uint64_t hi = g_kind == ALB_FOUR_SLOT ? std::max(pub, run.chk.newest_complete_seq()) : pub;
        if (victim_producer && !reset && (ls < pub || ls > hi)) {
            std::snprintf(m, sizeof m, "frozen producer: the consumer's last value is seq %llu, expected the last published seq %llu%s",
                          static_cast<unsigned long long>(ls), static_cast<unsigned long long>(pub),
                          hi > pub ? " (or the last completed one)" : "");
            cr.verdict.add_other(m);
        }
        if (plan.held_writes) {
            std::snprintf(m, sizeof m, "the producer wrote %s%u, held by the frozen consumer's ReadLocked, expected never",
                          g_kind == ALB_FOUR_SLOT ? "the pair of Buffer" : "Buffer", plan.held);
            cr.verdict.add_other(m);
        }
    }
    if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
        cr.verdict.add_other("attach failed after a restart");
    cr.verdict.take(run);
    cr.verdict.take_bus();
}

// The crash runs, one per (payload, victim, frozen/reset, access point, seed);
// the enumeration stops at the first run that fails (or, for a negative test,
// once the expected checkers have fired): every run is bounded by its
// watchdogs, so the whole mode is too.

int mode_crash(const Options &o)
{
    CrashResult cr;
    const uint32_t sizes[2] = {12, 33};
    bool stop = false;
    std::printf("crash: %s channels, each side frozen or reset at every access point of its call, payloads 12 and 33 bytes\n",
                kind_label());
    for (uint32_t size : sizes) {
        unsigned words = (size + 3) / 4;
        for (int vp = 1; vp >= 0; --vp) {
            unsigned points = vp ? export_overhead() + words : 3 + words;   // Export: 2 (four-slot 3) + W; Import (new data): 3 + W
            for (int rs = 0; rs <= 1; ++rs) {
                uint64_t before = cr.runs - cr.not_reached;
                for (unsigned k = 0; k < points && !stop; ++k)
                    for (uint64_t s = 0; s < 8 && !stop; ++s) {
                        crash_run(size, vp != 0, rs != 0, k, o.seed * 1000 + k * 10 + s, cr);
                        stop = o.expect_violation ? negative_satisfied(cr.verdict) : cr.verdict.total() != 0;
                        if (stop)
                            std::printf("  stopped at the first failing run: %s %s at access %u of %s, %u-byte payload, "
                                        "seed %llu\n", vp ? "producer" : "consumer", rs ? "reset" : "frozen", k,
                                        vp ? "Export" : "Import", size,
                                        static_cast<unsigned long long>(o.seed * 1000 + k * 10 + s));
                    }
                std::printf("  %-8s %-6s at %2u access points of %s: %llu runs crashed as planned\n",
                            vp ? "producer" : "consumer", rs ? "reset" : "frozen", points,
                            vp ? "Export" : "Import", static_cast<unsigned long long>(cr.runs - cr.not_reached - before));
                std::fflush(stdout);
                if (stop) break;
            }
            if (stop) break;
        }
        if (stop) break;
    }
    std::printf("crash: %llu runs, %llu crash points not reached, %llu survivor calls checked, %llu cycles, %llu violations\n",
                static_cast<unsigned long long>(cr.runs), static_cast<unsigned long long>(cr.not_reached),
                static_cast<unsigned long long>(cr.survivor_calls), static_cast<unsigned long long>(cr.cycles),
                static_cast<unsigned long long>(cr.verdict.total()));
    cr.verdict.print();
    if (!cr.first_not_reached.empty()) std::printf("  first crash point not reached: %s\n", cr.first_not_reached.c_str());
    if (!o.report.empty()) {
        JsonReport rep;
        rep.str("variant", o.variant).str("kind", kind_label()).num("runs", cr.runs).num("not_reached", cr.not_reached)
            .num("survivor_calls", cr.survivor_calls).num("cycles", cr.cycles)
            .num("violations_total", cr.verdict.total()).raw("violations", cr.verdict.json())
            .str("caught_by", cr.verdict.caught_by());
        rep.write(o.report);
    }
    if (o.expect_violation || cr.verdict.total()) return verdict_status(o, cr.verdict, "crash runs", cr.runs);
    if (cr.not_reached * 10 > cr.runs) {
        std::printf("FAIL: %llu of %llu crash points were never reached, expected under 10%% (first: %s)\n",
                    static_cast<unsigned long long>(cr.not_reached), static_cast<unsigned long long>(cr.runs),
                    cr.first_not_reached.c_str());
        return 1;
    }
    return 0;
}

}  // namespace tbd
