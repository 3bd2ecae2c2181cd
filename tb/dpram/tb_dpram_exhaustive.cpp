// tb_dpram_exhaustive.cpp -- exhaustive mode: every interleaving of 2 Exports against 2 Imports.
#include "tb_dpram.h"

namespace tbd {


// ---------------------------------------------------------------- exhaustive
//
// Stateless search: each schedule is replayed from the start along a path of
// choices.  At every point both CPUs are suspended at their next access; the
// choices are: A's access alone, B's alone, and, if the two touch a common
// byte, both issued in the same cycle with the RAM serving A first or B
// first.  Independent simultaneous accesses equal either order, so they are
// not repeated.  Warm-up calls (bringing the channel to a start state) run
// forced, producer first.
enum Choice : uint8_t { STEP_A, STEP_B, BOTH_A_FIRST, BOTH_B_FIRST };

struct Search {
    uint32_t payload = 0;
    unsigned warm_exports = 0, warm_imports = 0;
    uint64_t schedules = 0, steps = 0, collisions = 0, imports = 0;
    uint64_t imports_new = 0, max_depth = 0;
    Verdict verdict;
};

bool overlap(const BusRequest &a, const BusRequest &b)
{
    return a.addr == b.addr && (a.sel & b.sel) != 0;
}

// Runs one schedule; extends path/counts to a leaf.  Returns false if the
// replay diverged (nondeterminism: a harness bug).
bool run_schedule(Search &s, std::vector<uint8_t> &path, std::vector<uint8_t> &counts)
{
    Channel c{0, s.payload, 0, 1};
    Run run(c);
    run.prod.limit = s.warm_exports + 2;
    run.prod.warmup_calls = s.warm_exports;
    run.cons.limit = s.warm_imports + 2;
    run.cons.warmup_calls = s.warm_imports;
    RamBus &bus = *g_bus;
    SimCpu &a = bus.cpu[0], &b = bus.cpu[1];
    size_t depth = 0;
    for (;;) {
        for (SimCpu *cpu : {&a, &b})
            if (!cpu->has_request && !cpu->finished() && !cpu->faulted) cpu->resume();
        bool pa = a.has_request, pb = b.has_request;
        if (!pa && !pb) break;
        uint8_t opts[4];
        int n = 0;
        if (pa && a.warmup) opts[n++] = STEP_A;
        else if (pb && b.warmup) opts[n++] = STEP_B;
        else {
            if (pa) opts[n++] = STEP_A;
            if (pb) opts[n++] = STEP_B;
            if (pa && pb && overlap(a.request, b.request)) {
                opts[n++] = BOTH_A_FIRST;
                opts[n++] = BOTH_B_FIRST;
            }
        }
        uint8_t pick;
        if (depth < path.size()) {
            if (counts[depth] != n) return false;
            pick = path[depth];
        } else {
            path.push_back(0);
            counts.push_back(static_cast<uint8_t>(n));
            pick = 0;
        }
        Choice ch = static_cast<Choice>(opts[pick]);
        bool ok;
        std::string why;
        if (ch == STEP_A || ch == STEP_B) {
            int p = ch == STEP_A ? 0 : 1;
            bus.issue(p);
            ok = run_until(1u << p, why);
        } else {
            ++s.collisions;
            int first = ch == BOTH_A_FIRST ? 0 : 1;
            if (bus.next_slot() != first) bus.tick();
            bus.issue(0);
            bus.issue(1);
            ok = run_until(3u, why);
        }
        ++depth;
        ++s.steps;
        if (!ok) {
            s.verdict.add_other(why);
            break;
        }
        std::string late = run.overdue_call();
        if (!late.empty()) {
            s.verdict.add_watchdog(late);
            break;
        }
        if (depth > g_limits.schedule_steps) {
            char m[400];
            std::snprintf(m, sizeof m, "watchdog: a schedule of %u Exports and %u Imports (%u-byte payload) ran past "
                          "%llu RAM accesses, expected under 100: %s",
                          s.warm_exports + 2, s.warm_imports + 2, s.payload,
                          static_cast<unsigned long long>(g_limits.schedule_steps), run.calls_under_way().c_str());
            s.verdict.add_watchdog(m);
            break;
        }
    }
    s.max_depth = std::max<uint64_t>(s.max_depth, depth);
    ++s.schedules;
    s.imports += run.chk.imports;
    s.imports_new += run.chk.imports_new;
    if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
        s.verdict.add_other("attach failed on a valid RAM image");
    s.verdict.take(run);
    s.verdict.take_bus();
    return true;
}

int mode_exhaustive(const Options &o)
{
    if (o.payload < 3 || o.payload > kMaxPayload) {
        std::fprintf(stderr, "exhaustive: --payload must be 3..%u bytes, got %u\n", kMaxPayload, o.payload);
        return 2;
    }
    if (!g_limits.schedules) {
        g_limits.schedules = 5000000;
        for (unsigned w = 3; w < (o.payload + 3) / 4 && g_limits.schedules < (1ull << 60); ++w) g_limits.schedules *= 10;
    }
    std::printf("exhaustive: %s channel, 2 Exports against 2 Imports of %u bytes (%u word accesses each), "
                "every interleaving, same-cycle collisions in both orders\n",
                kind_label(), o.payload, (o.payload + 3) / 4);
    uint64_t total = 0, collisions = 0, imports = 0, imports_new = 0;
    Verdict all;
    JsonReport rep;
    std::string states = "[";
    bool stop = false;
    for (unsigned we = 0; we <= 2 && !stop; ++we) {
        for (unsigned wi = 0; wi <= 1 && !stop; ++wi) {
            Search s;
            s.payload = o.payload;
            s.warm_exports = we;
            s.warm_imports = wi;
            std::vector<uint8_t> path, counts;
            auto t0 = std::chrono::steady_clock::now();
            for (;;) {
                if (!run_schedule(s, path, counts)) {
                    s.verdict.add_other("replay diverged: the harness is not deterministic");
                    break;
                }
                if (o.expect_violation && negative_satisfied(s.verdict)) { stop = true; break; }
                // A schedule that hit a watchdog would be replayed and extended
                // in every sibling: stop at the first one.
                if (s.verdict.watchdog) { stop = true; break; }
                if (s.schedules >= g_limits.schedules) {
                    char m[200];
                    std::snprintf(m, sizeof m, "watchdog: the start state with %u warm-up Exports and %u warm-up Imports explored %llu schedules "
                                  "without finishing, "
                                  "expected at most %llu (--max-schedules to change)", we, wi,
                                  static_cast<unsigned long long>(s.schedules),
                                  static_cast<unsigned long long>(g_limits.schedules));
                    s.verdict.add_watchdog(m);
                    stop = true;
                    break;
                }
                int d = static_cast<int>(path.size()) - 1;
                while (d >= 0 && path[d] + 1 >= counts[d]) --d;
                if (d < 0) break;
                path.resize(d + 1);
                counts.resize(d + 1);
                ++path[d];
            }
            double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("  start state: %u warm-up Exports, %u warm-up Imports: %llu schedules, "
                        "%llu same-cycle collisions, %llu Imports checked (%.1f s)\n",
                        we, wi, static_cast<unsigned long long>(s.schedules),
                        static_cast<unsigned long long>(s.collisions),
                        static_cast<unsigned long long>(s.imports), sec);
            std::fflush(stdout);
            char b[200];
            std::snprintf(b, sizeof b, "%s{\"warm_exports\": %u, \"warm_imports\": %u, \"schedules\": %llu, \"collisions\": %llu}",
                          states.size() > 1 ? ", " : "", we, wi, static_cast<unsigned long long>(s.schedules),
                          static_cast<unsigned long long>(s.collisions));
            states += b;
            total += s.schedules;
            collisions += s.collisions;
            imports += s.imports;
            imports_new += s.imports_new;
            all.merge(s.verdict);
        }
    }
    std::printf("exhaustive: %llu schedules explored, %llu same-cycle same-byte collisions, "
                "%llu Imports checked (%llu New), %llu violations\n",
                static_cast<unsigned long long>(total), static_cast<unsigned long long>(collisions),
                static_cast<unsigned long long>(imports), static_cast<unsigned long long>(imports_new),
                static_cast<unsigned long long>(all.total()));
    all.print();
    rep.str("variant", o.variant).str("kind", kind_label()).num("payload_bytes", o.payload).num("schedules", total)
        .num("collisions", collisions).num("imports_checked", imports).num("imports_new", imports_new)
        .num("violations_total", all.total()).raw("violations", all.json()).raw("start_states", states + "]")
        .str("caught_by", all.caught_by());
    if (!o.report.empty()) rep.write(o.report);
    return verdict_status(o, all, "schedules", total);
}

}  // namespace tbd
