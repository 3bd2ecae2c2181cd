// tb_dpram_random.cpp -- random mode: drifting speed ratios, stalls, payloads and alignments.
#include "tb_dpram_random.h"

namespace tbd {


Channel random_channel(std::mt19937_64 &rng)
{
    Channel c;
    c.size = 1 + static_cast<uint32_t>(rng() % kMaxPayload);
    uint32_t bytes = chan_bytes(c.size);
    c.base = static_cast<uint32_t>(rng() % ((RamBus::kBytes - bytes) / 4 + 1)) * 4;
    c.prod_port = static_cast<int>(rng() & 1);
    c.cons_port = 1 - c.prod_port;
    return c;
}

void run_random(uint64_t target, uint64_t seed, RandomStats &st, bool stop_on_violation, bool progress,
                double fixed_log_ratio)
{
    std::mt19937_64 rng(seed);
    Timing tm(seed ^ 0xA5A5A5A5ull);
    if (!std::isnan(fixed_log_ratio)) {
        tm.fixed = true;
        tm.log_ratio = fixed_log_ratio;
    }
    uint64_t next_report = target / 10;
    while (st.imports < target) {
        Channel c = random_channel(rng);
        Run run(c);
        run.prod.align = static_cast<unsigned>(rng() % 4);
        run.cons.align = static_cast<unsigned>(rng() % 4);
        Driver drv(tm);
        uint64_t seg = std::min<uint64_t>(target - st.imports, 5000 + rng() % 20000);
        uint64_t c0 = g_bus->cycle(), a0 = g_bus->accesses;
        const uint64_t budget = seg * g_limits.segment_cycles_per_import;
        char m[320];
        while (run.chk.imports < seg) {
            tm.drift(g_bus->cycle(), c.prod_port);
            drv.cycle();
            if (run.producer().faulted || run.consumer().faulted || drv.ram_dead) break;
            if (stop_on_violation && counted_violations(run.chk)) break;
            if (run.producer().finished() || run.consumer().finished()) {
                // Both programs call for ever: one that returned failed to attach.
                std::snprintf(m, sizeof m, "the %s program returned after %llu calls (attach result %d), expected it "
                              "to keep calling", run.producer().finished() ? "producer" : "consumer",
                              static_cast<unsigned long long>(run.producer().finished() ? run.prod.calls : run.cons.calls),
                              run.producer().finished() ? run.prod.attach_rc : run.cons.attach_rc);
                st.verdict.add_other(m);
                break;
            }
            if ((g_bus->cycle() & 1023u) == 0) {
                std::string late = run.overdue_call();
                if (late.empty() && g_bus->cycle() - c0 > budget) {
                    std::snprintf(m, sizeof m, "watchdog: a channel of %u bytes checked only %llu of %llu Imports in "
                                  "%llu cycles, expected them within %llu cycles (%llu per Import)",
                                  c.size, static_cast<unsigned long long>(run.chk.imports),
                                  static_cast<unsigned long long>(seg), static_cast<unsigned long long>(g_bus->cycle() - c0),
                                  static_cast<unsigned long long>(budget),
                                  static_cast<unsigned long long>(g_limits.segment_cycles_per_import));
                    late = m;
                }
                if (!late.empty()) {
                    st.verdict.add_watchdog(late);
                    break;
                }
            }
        }
        ++st.segments;
        st.imports += run.chk.imports;
        st.imports_new += run.chk.imports_new;
        st.exports += run.chk.exports;
        st.cycles += g_bus->cycle() - c0;
        st.accesses += g_bus->accesses - a0;
        st.worst_iter = std::max(st.worst_iter, run.chk.worst_import_iterations);
        st.worst_export_cycles = std::max(st.worst_export_cycles, run.prod.worst_call_cycles);
        st.worst_import_cycles = std::max(st.worst_import_cycles, run.cons.worst_call_cycles);
        if (run.chk.imports)
            st.worst_segment_cycles_per_import = std::max(st.worst_segment_cycles_per_import,
                                                          (g_bus->cycle() - c0) / run.chk.imports);
        st.worst_acc = std::max(st.worst_acc, run.chk.worst_import_accesses);
        st.ctl_sum += run.chk.import_ctl_sum;
        st.ctl_imports += run.chk.imports_counted;
        st.ctl_worst = std::max(st.ctl_worst, run.chk.import_ctl_worst);
        for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
            st.b_imports[k] += run.chk.bucket_imports[k];
            st.b_iter_sum[k] += run.chk.bucket_iter_sum[k];
            st.b_worst_iter[k] = std::max(st.b_worst_iter[k], run.chk.bucket_worst_iter[k]);
            st.b_worst_acc[k] = std::max(st.b_worst_acc[k], run.chk.bucket_worst_accesses[k] -
                                         std::min<uint64_t>(run.chk.bucket_worst_accesses[k], (c.size + 3) / 4));
        }
        for (int k = 0; k < 3; ++k) {
            st.ov_min[k] = std::min(st.ov_min[k], run.chk.overhead_min[k]);
            st.ov_max[k] = std::max(st.ov_max[k], run.chk.overhead_max[k]);
        }
        if (drv.ram_dead) st.verdict.add_other(drv.dead_why);
        if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
            st.verdict.add_other("attach failed on a valid RAM image");
        st.verdict.take(run);
        st.verdict.take_bus();
        if (stop_on_violation && negative_satisfied(st.verdict)) return;
        // A watchdog or a harness failure means the run cannot go on meaningfully.
        if (st.verdict.watchdog || st.verdict.other) return;
        if (run.chk.imports == 0 && !st.verdict.total()) {
            std::snprintf(m, sizeof m, "a channel of %u bytes checked no Import in %llu cycles, expected %llu",
                          c.size, static_cast<unsigned long long>(g_bus->cycle() - c0),
                          static_cast<unsigned long long>(seg));
            st.verdict.add_other(m);
            return;
        }
        if (progress && st.imports >= next_report) {
            std::printf("  %3.0f%%  %llu Imports checked, %llu violations\n", 100.0 * st.imports / target,
                        static_cast<unsigned long long>(st.imports),
                        static_cast<unsigned long long>(st.verdict.total()));
            std::fflush(stdout);
            next_report += target / 10;
        }
    }
}

std::string bucket_json(const RandomStats &st)
{
    std::string s = "[";
    for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
        char b[240];
        double lo = -2.0 + 0.5 * k;
        std::snprintf(b, sizeof b,
                      "%s{\"log10_ratio_from\": %.1f, \"log10_ratio_to\": %.1f, \"imports\": %llu, "
                      "\"mean_iterations\": %.4f, \"worst_iterations\": %llu, \"worst_control_accesses\": %llu}",
                      k ? ", " : "", lo, lo + 0.5, static_cast<unsigned long long>(st.b_imports[k]),
                      st.b_imports[k] ? static_cast<double>(st.b_iter_sum[k]) / st.b_imports[k] : 0.0,
                      static_cast<unsigned long long>(st.b_worst_iter[k]),
                      static_cast<unsigned long long>(st.b_worst_acc[k]));
        s += b;
    }
    return s + "]";
}

void print_buckets(const RandomStats &st)
{
    std::printf("  termination: Import loop iterations against writer/reader speed ratio\n");
    std::printf("    %-17s %12s %10s %10s %16s\n", "writer:reader", "imports", "mean iter", "worst iter", "worst ctl acc");
    for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
        double lo = -2.0 + 0.5 * k;
        char range[40];
        std::snprintf(range, sizeof range, "%g..%g", std::pow(10, lo), std::pow(10, lo + 0.5));
        std::printf("    %-17s %12llu %10.3f %10llu %16llu\n", range, static_cast<unsigned long long>(st.b_imports[k]),
                    st.b_imports[k] ? static_cast<double>(st.b_iter_sum[k]) / st.b_imports[k] : 0.0,
                    static_cast<unsigned long long>(st.b_worst_iter[k]),
                    static_cast<unsigned long long>(st.b_worst_acc[k]));
    }
}

int mode_random(const Options &o)
{
    std::printf("random: %llu Imports, %s channels, seed %llu, speed ratios 1:100..100:1, payloads 1..%u bytes\n",
                static_cast<unsigned long long>(o.imports), kind_label(), static_cast<unsigned long long>(o.seed), kMaxPayload);
    std::fflush(stdout);
    RandomStats st;
    auto t0 = std::chrono::steady_clock::now();
    run_random(o.imports, o.seed, st, o.expect_violation, !o.expect_violation);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("random: %llu Imports checked (%llu New), %llu Exports, %llu channels, %llu cycles, "
                "%llu violations (%.1f s)\n",
                static_cast<unsigned long long>(st.imports), static_cast<unsigned long long>(st.imports_new),
                static_cast<unsigned long long>(st.exports), static_cast<unsigned long long>(st.segments),
                static_cast<unsigned long long>(st.cycles), static_cast<unsigned long long>(st.verdict.total()), sec);
    st.verdict.print();
    const char *names[3] = {"Import, no new data", "Import, new data", "Export"};
    // Four-slot: an Old Import is 1, or 3 when Actual still lags a value the
    // consumer already read (the producer between its Slot and Actual stores).
    const bool fs = g_kind == ALB_FOUR_SLOT;
    const uint64_t want_lo[3] = {1, 3, fs ? 3u : 2u}, want[3] = {fs ? 3u : 1u, 3, fs ? 3u : 2u};
    bool overhead_ok = true;
    std::printf("  RAM accesses beyond the payload, undisturbed calls (expected %s):\n",
                fs ? "1 or 3, 3, 3" : "1, 3, 2");
    for (int k = 0; k < 3; ++k) {
        if (st.ov_min[k] > st.ov_max[k]) {
            std::printf("    %-20s none seen\n", names[k]);
            overhead_ok = false;
            continue;
        }
        std::printf("    %-20s %llu..%llu\n", names[k], static_cast<unsigned long long>(st.ov_min[k]),
                    static_cast<unsigned long long>(st.ov_max[k]));
        if (st.ov_min[k] < want_lo[k] || st.ov_max[k] > want[k]) overhead_ok = false;
    }
    print_buckets(st);
    std::printf("  longest calls: Export %llu cycles, Import %llu cycles (watchdog %llu); "
                "worst channel %llu cycles per Import (watchdog %llu)\n",
                static_cast<unsigned long long>(st.worst_export_cycles), static_cast<unsigned long long>(st.worst_import_cycles),
                static_cast<unsigned long long>(g_limits.call_cycles),
                static_cast<unsigned long long>(st.worst_segment_cycles_per_import),
                static_cast<unsigned long long>(g_limits.segment_cycles_per_import));
    if (!o.report.empty()) {
        JsonReport rep;
        char ov[160];
        std::snprintf(ov, sizeof ov, "{\"import_old\": %llu, \"import_new\": %llu, \"export\": %llu}",
                      static_cast<unsigned long long>(st.ov_max[0]), static_cast<unsigned long long>(st.ov_max[1]),
                      static_cast<unsigned long long>(st.ov_max[2]));
        rep.str("variant", o.variant).str("kind", kind_label()).num("seed", o.seed).num("imports_checked", st.imports)
            .num("imports_new", st.imports_new).num("exports", st.exports).num("channels", st.segments)
            .num("cycles", st.cycles).num("accesses", st.accesses).num("violations_total", st.verdict.total())
            .raw("violations", st.verdict.json()).str("caught_by", st.verdict.caught_by())
            .raw("accesses_beyond_payload", ov).num("worst_import_iterations", st.worst_iter)
            .raw("termination_by_speed_ratio", bucket_json(st)).num("worst_export_cycles", st.worst_export_cycles)
            .num("worst_import_cycles", st.worst_import_cycles)
            .num("worst_channel_cycles_per_import", st.worst_segment_cycles_per_import).num("seconds", sec);
        rep.write(o.report);
    }
    if (o.expect_violation || st.verdict.total()) return verdict_status(o, st.verdict, "Imports", st.imports);
    if (!overhead_ok) {
        std::printf("FAIL: accesses beyond the payload differ from the expected %s\n", fs ? "1 or 3, 3, 3" : "1, 3, 2");
        return 1;
    }
    return 0;
}

// -------------------------------------------------------------------- ratio
//
// The figure of the termination bound: RAM accesses per Import beyond the payload against
// the writer:reader speed ratio, held fixed at each point of --ratios (log10,
// default -2..2 in steps of 0.5) for --imports Imports each, with the
// checkers on.  Four-slot: flat at its bound 3 (1 with nothing new); the
// three-buffer loop grows as the writer gets faster.
int mode_ratio(const Options &o)
{
    std::vector<double> pts;
    std::string list = o.ratios.empty() ? "-2,-1.5,-1,-0.5,0,0.5,1,1.5,2" : o.ratios;
    for (size_t i = 0; i < list.size();) {
        size_t j = list.find(',', i);
        if (j == std::string::npos) j = list.size();
        pts.push_back(std::atof(list.substr(i, j - i).c_str()));
        i = j + 1;
    }
    // A reader held at 1/100 of the writer's speed spends about 10^4 cycles
    // per Import (3 + W accesses, each gap 0-2 CPU cycles of 100 RAM cycles,
    // with stalls): the drifting model's budget of 2000 per Import is for a
    // mix of speeds.
    g_limits.segment_cycles_per_import = 50000;
    std::printf("ratio: %s channels, %llu Imports per speed ratio, seed %llu\n", kind_label(),
                static_cast<unsigned long long>(o.imports), static_cast<unsigned long long>(o.seed));
    std::printf("  %-14s %10s %10s %12s %12s\n", "writer:reader", "imports", "new", "mean ctl acc", "worst ctl acc");
    Verdict all;
    std::string points = "[";
    uint64_t total = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        RandomStats st;
        run_random(o.imports, o.seed + i, st, false, false, pts[i]);
        double mean = st.ctl_imports ? static_cast<double>(st.ctl_sum) / st.ctl_imports : 0.0;
        std::printf("  10^%-11.2f %10llu %10llu %12.3f %12llu\n", pts[i], static_cast<unsigned long long>(st.imports),
                    static_cast<unsigned long long>(st.imports_new), mean, static_cast<unsigned long long>(st.ctl_worst));
        char b[320];
        std::snprintf(b, sizeof b, "%s{\"log10_ratio\": %.2f, \"imports\": %llu, \"imports_new\": %llu, "
                      "\"mean_control_accesses\": %.4f, \"worst_control_accesses\": %llu, \"worst_import_iterations\": %llu}",
                      i ? ", " : "", pts[i], static_cast<unsigned long long>(st.imports),
                      static_cast<unsigned long long>(st.imports_new), mean,
                      static_cast<unsigned long long>(st.ctl_worst), static_cast<unsigned long long>(st.worst_iter));
        points += b;
        total += st.imports;
        all.merge(st.verdict);
    }
    if (!o.report.empty()) {
        JsonReport rep;
        rep.str("kind", kind_label()).num("seed", o.seed).num("imports_per_point", o.imports)
            .num("violations_total", all.total()).raw("points", points + "]");
        rep.write(o.report);
    }
    all.print();
    return verdict_status(o, all, "Imports", total);
}

}  // namespace tbd
