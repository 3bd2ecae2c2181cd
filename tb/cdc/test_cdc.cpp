// test_cdc -- self-checking test of albatross_dpram behind two albatross_wb_cdc
// bridges with three independent clocks (top: tb/cdc/tb_dpram_async.v).
//
// The RAM clock is fixed; the two CPU clocks drift randomly so that their
// frequency ratio wanders over 1:100..100:1.  Clocks come from this event loop
// (next edge first; coincident edges in one eval()).  Each CPU issues random
// reads and writes with random byte lanes to a few hot words, random idle gaps,
// and now and then abandons a request by dropping cyc before its ack.
//
// Checkers (each failure says what was expected and what came):
//   atomicity  every byte a CPU read returns is a value the byte held at some
//              time between stb and ack, from a reference memory built from the
//              RAM-side bus of both bridges (a torn or invented byte fails);
//   latency    every access acks within the bound documented in
//              rtl/albatross_wb_cdc.v, with Ts the longest CPU period and Tm
//              the RAM period in its window;
//   visibility every acked write is performed once on the RAM, inside its
//              window, with its own adr/sel/data; every acked read returns the
//              data of its own RAM read (also right after an abandon); a read
//              returns the CPU's own last write to a byte unless the byte was
//              written again since;
//   ram        albatross_dpram reads return the reference value, and the RAM
//              bus of each bridge follows Wishbone (stb held stable until ack);
//   coverage   the run reached the frequency ratios, collisions and abandons
//              it is meant to exercise.
// Exit status 0 if all pass, else 64 + a bit mask of the failed checkers
// (1 atomicity, 2 latency, 4 visibility, 8 ram, 16 coverage).
//
// --inject=MODE deliberately breaks one thing in this harness (never the RTL)
// to prove a checker can fail: torn (flip one byte of a read now and then),
// latency (check against a too small bound), write (drive corrupted write
// data now and then), ram (corrupt a RAM-side read sample now and then).
//
// Options: --seed=N --accesses=N --inject=MODE --json=PATH
//
// Sources: cdc_tb.h (shared declarations), cdc_model.cpp, cdc_cpu.cpp,
// cdc_ram.cpp, and this file (main, options, report).
#include "Vtb_dpram_async.h"
#include "verilated.h"
#include "cdc_tb.h"

#include <chrono>
#include <sys/stat.h>

// ------------------------------------------------------------------ JSON
static void mkdirs(const std::string &path) {
    for (size_t i = 1; i < path.size(); ++i)
        if (path[i] == '/') mkdir(path.substr(0, i).c_str(), 0777);
}

static void json_lat(FILE *f, const char *key, const LatStat &l, const char *formula, bool last) {
    std::fprintf(f,
                 "      \"%s\": {\"count\": %" PRIu64 ", \"bound_formula\": \"%s\", "
                 "\"worst_ratio_to_bound\": %.4f, \"worst_latency_ps\": %" PRIu64
                 ", \"bound_at_worst_ps\": %" PRIu64 ", \"cpu_period_at_worst_ps\": %" PRIu64
                 ", \"cpu_cycles_at_worst\": %" PRIu64 ", \"ram_cycles_at_worst\": %" PRIu64
                 ", \"max_cpu_cycles\": %" PRIu64 ", \"max_ram_cycles\": %" PRIu64 "}%s\n",
                 key, l.n, formula, l.worst_ratio, l.worst_ps, l.worst_bound_ps, l.worst_ts,
                 l.worst_s_cycles, l.worst_m_cycles, l.max_s_cycles, l.max_m_cycles,
                 last ? "" : ",");
}

// ------------------------------------------------------------------ main
int main(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!std::strncmp(a, "--seed=", 7)) g_seed = std::strtoull(a + 7, nullptr, 0);
        else if (!std::strncmp(a, "--accesses=", 11)) g_accesses = std::strtoull(a + 11, nullptr, 0);
        else if (!std::strncmp(a, "--inject=", 9)) g_inject = a + 9;
        else if (!std::strncmp(a, "--json=", 7)) g_json = a + 7;
        else if (a[0] == '+') { /* Verilator plusargs */ }
        else { std::fprintf(stderr, "test_cdc: unknown option %s\n", a); return 2; }
    }
    if (!g_inject.empty() && g_inject != "torn" && g_inject != "latency" && g_inject != "write" &&
        g_inject != "ram") {
        std::fprintf(stderr, "test_cdc: unknown --inject=%s\n", g_inject.c_str());
        return 2;
    }
    std::printf("test_cdc: seed=%" PRIu64 " accesses=%" PRIu64 " SYNC_STAGES=%d ADDR_WIDTH=%d%s%s\n",
                g_seed, g_accesses, N, ADDR_WIDTH, g_inject.empty() ? "" : " inject=",
                g_inject.c_str());
    g_rng.seed(g_seed);
    const auto wall0 = std::chrono::steady_clock::now();

    Verilated::commandArgs(argc, argv);
    Verilated::randReset(2);
    Verilated::randSeed((int)(g_seed & 0x7fffffff));
    Vtb_dpram_async *top = new Vtb_dpram_async;

    g_ref.resize(NWORDS * 4);
    for (auto &hb : g_ref) hb.h.emplace_back(0, UNKNOWN);

    // drift: the ratio sweeps its full range a few times over the run
    g_vmax = 6 * 2 * (4 * LN10) / (double)std::max<uint64_t>(g_accesses, 1000);
    g_turn_p = 8.0 / (double)std::max<uint64_t>(g_accesses, 1000);
    g_rho.x = (2 * rnd32() / 4294967296.0 - 1) * 2 * LN10;
    g_rho.dir = rnd32() & 1 ? 1 : -1;
    g_rho.speed = g_c.speed = g_vmax / 2;

    Cpu cpu[2];
    Mon mon[2];
    for (int i = 0; i < 2; ++i) {
        cpu[i].id = i;
        cpu[i].name = mon[i].name = (char)('A' + i);
        cpu[i].own.resize(NWORDS * 4);
        cpu[i].rst_hold = 4;
    }
    bool     ram_level = false, ram_rst = true;
    uint64_t ram_next = 1 + rnd((uint32_t)TM), ram_last_rise = 0;
    cpu[0].next_edge = 1 + rnd(100000);
    cpu[1].next_edge = 1 + rnd(100000);

    // everything low, resets high, one eval before the first edge
    top->ram_clk_i = 0; top->a_clk_i = 0; top->b_clk_i = 0;
    top->ram_rst_i = 1; top->a_rst_i = 1; top->b_rst_i = 1;
    top->a_cyc_i = 0; top->a_stb_i = 0; top->a_we_i = 0; top->a_adr_i = 0; top->a_sel_i = 0; top->a_dat_i = 0;
    top->b_cyc_i = 0; top->b_stb_i = 0; top->b_we_i = 0; top->b_adr_i = 0; top->b_sel_i = 0; top->b_dat_i = 0;
    top->eval();

    const uint64_t RESET_UNTIL = 40 * TM * 10;  // > 20 edges of the slowest clock
    uint64_t t = 0, evals = 0, next_prune = 0;
    bool stop = false;
    uint64_t stop_time = 0;
    bool aborted = false;
    // Progress watchdog: the per-access one above covers a request that waits
    // for its ack, not one abandoned and retried for ever, nor CPUs that stop
    // issuing.  Until the last access, some access must complete at least
    // every PROGRESS_PS: an access needs at most 4 * ((2N + 4) * 10 * TM +
    // (2N + 10) * TM) with the slowest CPU (10 * TM), a gap at most 200 of its
    // edges, far below 100000 RAM cycles.
    const uint64_t PROGRESS_PS = 100000 * TM;
    uint64_t progress_t = 0, progress_n = 0;

    for (;;) {
        t = std::min(ram_next, std::min(cpu[0].next_edge, cpu[1].next_edge));
        const bool ram_edge = ram_next == t, ram_rise = ram_edge && !ram_level;
        bool cpu_edge[2], cpu_rise[2], ack_s[2];
        uint32_t dat_s[2];
        MonSample ms[2];
        for (int i = 0; i < 2; ++i) {
            cpu_edge[i] = cpu[i].next_edge == t;
            cpu_rise[i] = cpu_edge[i] && !cpu[i].level;
        }
        // sample what each rising edge sees
        if (cpu_rise[0]) { ack_s[0] = top->a_ack_o; dat_s[0] = top->a_dat_o; }
        if (cpu_rise[1]) { ack_s[1] = top->b_ack_o; dat_s[1] = top->b_dat_o; }
        if (ram_rise) {
            ms[0] = {(bool)top->mon_a_cyc_o, (bool)top->mon_a_stb_o, (bool)top->mon_a_we_o,
                     (bool)top->mon_a_ack_o, top->mon_a_adr_o, top->mon_a_sel_o,
                     top->mon_a_wdat_o, top->mon_a_rdat_o};
            ms[1] = {(bool)top->mon_b_cyc_o, (bool)top->mon_b_stb_o, (bool)top->mon_b_we_o,
                     (bool)top->mon_b_ack_o, top->mon_b_adr_o, top->mon_b_sel_o,
                     top->mon_b_wdat_o, top->mon_b_rdat_o};
            for (int i = 0; i < 2; ++i)
                if (g_inject == "ram" && ms[i].ack && !ms[i].we && chance(0.005))
                    ms[i].rdat ^= 0x80u << (8 * rnd(4));  // fault: corrupt a RAM read sample
        }
        // advance the clocks
        if (ram_edge) {
            ram_level = !ram_level;
            top->ram_clk_i = ram_level;
            ram_next = t + TM / 2;
        }
        for (int i = 0; i < 2; ++i) {
            if (!cpu_edge[i]) continue;
            Cpu &c = cpu[i];
            c.level = !c.level;
            if (c.level) {
                if (c.edges > 0) {
                    const uint64_t p = t - c.last_rise;
                    c.epoch_ts_max = std::max(c.epoch_ts_max, p);
                }
                c.last_rise = t;
                ++c.edges;
                c.period = cpu_period(i);
                c.next_edge = t + c.period / 2;
            } else {
                c.next_edge = c.last_rise + c.period;
            }
        }
        top->a_clk_i = cpu[0].level;
        top->b_clk_i = cpu[1].level;
        top->eval();
        ++evals;

        if (ram_rise) {
            ++g_ram_edges;
            for (int i = 0; i < 2; ++i) ram_access(cpu[i], mon[i], ms[i], ram_last_rise, t, ram_rst);
            ram_last_rise = t;
            if (ram_rst && t >= RESET_UNTIL) { ram_rst = false; top->ram_rst_i = 0; }
        }
        for (int i = 0; i < 2; ++i) {
            if (!cpu_rise[i]) continue;
            Cpu &c = cpu[i];
            if (c.rst && t >= RESET_UNTIL) { c.rst = false; }
            else c.rise(t, ack_s[i], dat_s[i], stop);
            // watchdog: far beyond the bound means a hang
            if (c.busy && !c.rst) {
                const uint64_t wd = 4 * ((uint64_t)(2 * N + 4) * std::max(c.epoch_ts_max, c.period) +
                                         (uint64_t)(2 * N + 10) * TM);
                if (t - c.cur.t_stb > wd) {
                    fail(CHK_LAT, "CPU %c %s adr 0x%02x from t=%" PRIu64 ": expected an ack, came"
                         " none after %" PRIu64 " ps (hang); aborting",
                         c.name, c.cur.we ? "write" : "read", c.cur.adr, c.cur.t_stb, t - c.cur.t_stb);
                    aborted = true;
                }
            }
        }
        top->a_rst_i = cpu[0].rst;
        top->b_rst_i = cpu[1].rst;
        top->a_cyc_i = cpu[0].cyc; top->a_stb_i = cpu[0].cyc; top->a_we_i = cpu[0].we;
        top->a_adr_i = cpu[0].adr & ADDR_MASK; top->a_sel_i = cpu[0].sel & 0xfu; top->a_dat_i = cpu[0].dat;
        top->b_cyc_i = cpu[1].cyc; top->b_stb_i = cpu[1].cyc; top->b_we_i = cpu[1].we;
        top->b_adr_i = cpu[1].adr & ADDR_MASK; top->b_sel_i = cpu[1].sel & 0xfu; top->b_dat_i = cpu[1].dat;

        // track the ratio reached (while traffic runs)
        if (!stop && ram_rise && !ram_rst) {
            const double r = std::log((double)cpu[1].period / (double)cpu[0].period);  // ln(fA/fB)
            g_rho_min = std::min(g_rho_min, r);
            g_rho_max = std::max(g_rho_max, r);
        }
        if (ram_rise && t >= next_prune) {
            uint64_t oldest = t;
            for (auto &c : cpu) {
                if (c.busy) oldest = std::min(oldest, c.cur.t_stb);
                for (auto &r : c.abandoned) oldest = std::min(oldest, r.t_stb);
            }
            ref_prune(oldest);
            next_prune = t + 1000 * TM;
        }
        if (!stop && !ram_rst && ram_rise) {
            if (g_completed != progress_n || progress_t == 0) { progress_n = g_completed; progress_t = t; }
            else if (t - progress_t > PROGRESS_PS) {
                fail(CHK_LAT, "expected an access to complete at least every %" PRIu64 " ps, came none from t=%"
                     PRIu64 " to t=%" PRIu64 " (%" PRIu64 " of %" PRIu64 " accesses done; CPU A %s, CPU B %s);"
                     " aborting", PROGRESS_PS, progress_t, t, g_completed, g_accesses,
                     cpu[0].busy ? "waiting for an ack" : "idle", cpu[1].busy ? "waiting for an ack" : "idle");
                aborted = true;
            }
        }
        if (aborted) break;
        if (!stop && g_completed >= g_accesses) { stop = true; stop_time = t; }
        if (stop && !cpu[0].busy && !cpu[1].busy && t > stop_time + 400 * TM * 10) break;
    }

    // abandoned requests at the end: their RAM accesses must match them
    for (auto &c : cpu) {
        size_t ai = 0;
        for (const RamTx &x : c.ramq) {
            while (ai < c.abandoned.size() && !c.matches(c.abandoned[ai], x)) ++ai;
            if (ai == c.abandoned.size()) {
                fail(CHK_VIS, "CPU %c at the end: expected no RAM access but abandoned ones, came"
                     " %s adr 0x%02x at t=%" PRIu64, c.name, x.we ? "write" : "read", x.adr, x.t_go);
                break;
            }
            ++c.n_abandon_performed;
            ++ai;
        }
    }

    // coverage: what the run is meant to exercise
    const double ratio_lo = std::exp(g_rho_min), ratio_hi = std::exp(g_rho_max);
    uint64_t n_ab = cpu[0].n_abandoned + cpu[1].n_abandoned;
    uint64_t n_abp = cpu[0].n_abandon_performed + cpu[1].n_abandon_performed;
    uint64_t n_after = cpu[0].lat_after_abandon.n + cpu[1].lat_after_abandon.n;
    if (!aborted && g_accesses >= 20000) {
        ++g_checks[CHK_COV];
        if (ratio_lo > 1.0 / 50 || ratio_hi < 50)
            fail(CHK_COV, "expected fA/fB to reach 1:50 and 50:1, came %.4g..%.4g", ratio_lo, ratio_hi);
        if (g_contended < g_accesses / 200)
            fail(CHK_COV, "expected at least %" PRIu64 " reads with a byte changing in their window,"
                 " came %" PRIu64, g_accesses / 200, g_contended);
        if (n_abp < 10 || n_after < 10)
            fail(CHK_COV, "expected at least 10 abandoned-and-performed accesses and 10 accesses"
                 " after an abandon, came %" PRIu64 " and %" PRIu64, n_abp, n_after);
    }

    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    char fn[128], fa[128];
    std::snprintf(fn, sizeof fn, "(N+4)*Ts + (N+5)*Tm = %d*Ts + %d*Tm", N + 4, N + 5);
    std::snprintf(fa, sizeof fa, "(2N+4)*Ts + (2N+10)*Tm = %d*Ts + %d*Tm", 2 * N + 4, 2 * N + 10);
    std::printf("test_cdc: simulated %.3f ms, %" PRIu64 " RAM cycles, %" PRIu64 " evals, %.2f s wall\n",
                t / 1e9, g_ram_edges, evals, wall);
    std::printf("test_cdc: fA/fB ranged %.4g..%.4g (1:%.1f..%.1f:1), RAM period %" PRIu64 " ps\n",
                ratio_lo, ratio_hi, 1 / ratio_lo, ratio_hi, TM);
    for (auto &c : cpu) {
        std::printf("test_cdc: CPU %c: %" PRIu64 " reads, %" PRIu64 " writes, %" PRIu64
                    " abandoned (%" PRIu64 " still performed on the RAM), %" PRIu64 " acks after abandon ignored\n",
                    c.name, c.reads, c.writes, c.n_abandoned, c.n_abandon_performed, c.idle_acks);
        const LatStat *ls[2] = {&c.lat_normal, &c.lat_after_abandon};
        const char *lab[2] = {fn, fa};
        for (int k = 0; k < 2; ++k)
            std::printf("test_cdc: CPU %c latency %s: %" PRIu64 " accesses, worst %.1f%% of bound"
                        " (%" PRIu64 " ps of %" PRIu64 " ps, Ts=%" PRIu64 " ps: %" PRIu64
                        " CPU + %" PRIu64 " RAM cycles); max %" PRIu64 " CPU / %" PRIu64 " RAM cycles\n",
                        c.name, k ? "after abandon" : "normal", ls[k]->n, 100 * ls[k]->worst_ratio,
                        ls[k]->worst_ps, ls[k]->worst_bound_ps, ls[k]->worst_ts, ls[k]->worst_s_cycles,
                        ls[k]->worst_m_cycles, ls[k]->max_s_cycles, ls[k]->max_m_cycles);
        (void)lab;
    }
    std::printf("test_cdc: RAM accesses A %" PRIu64 " B %" PRIu64 ", reads with a byte changing in"
                " their window %" PRIu64 ", bytes read before first known %" PRIu64 "\n",
                mon[0].n_tx, mon[1].n_tx, g_contended, g_unknown_reads);
    int mask = 0;
    for (int k = 0; k < CHK_COUNT; ++k) {
        std::printf("test_cdc: checker %-10s %10" PRIu64 " checks, %" PRIu64 " failures\n",
                    CHK_NAME[k], g_checks[k], g_fail[k]);
        if (g_fail[k]) mask |= 1 << k;
    }

    if (!g_json.empty()) {
        mkdirs(g_json);
        FILE *f = std::fopen(g_json.c_str(), "w");
        if (!f) { std::perror(g_json.c_str()); return 2; }
        std::fprintf(f, "{\n  \"test\": \"cdc\",\n  \"seed\": %" PRIu64 ",\n  \"accesses\": %" PRIu64
                     ",\n  \"inject\": \"%s\",\n  \"sync_stages\": %d,\n  \"addr_width\": %d,\n"
                     "  \"ram_period_ps\": %" PRIu64 ",\n  \"cpu_period_range_ps\": [%" PRIu64 ", %" PRIu64 "],\n"
                     "  \"freq_ratio_a_to_b_range\": [%.6g, %.6g],\n"
                     "  \"simulated_ps\": %" PRIu64 ",\n  \"ram_cycles\": %" PRIu64 ",\n  \"evals\": %" PRIu64
                     ",\n  \"wall_s\": %.3f,\n  \"reads_contended\": %" PRIu64 ",\n",
                     g_seed, g_accesses, g_inject.c_str(), N, ADDR_WIDTH, TM, TM / 10, TM * 10,
                     ratio_lo, ratio_hi, t, g_ram_edges, evals, wall, g_contended);
        std::fprintf(f, "  \"cpus\": {\n");
        for (int i = 0; i < 2; ++i) {
            Cpu &c = cpu[i];
            std::fprintf(f, "    \"%c\": {\"reads\": %" PRIu64 ", \"writes\": %" PRIu64
                         ", \"abandoned\": %" PRIu64 ", \"abandoned_performed\": %" PRIu64
                         ", \"ram_accesses\": %" PRIu64 ",\n    \"latency\": {\n",
                         c.name, c.reads, c.writes, c.n_abandoned, c.n_abandon_performed, mon[i].n_tx);
            json_lat(f, "normal", c.lat_normal, fn, false);
            json_lat(f, "after_abandon", c.lat_after_abandon, fa, true);
            std::fprintf(f, "    }}%s\n", i ? "" : ",");
        }
        std::fprintf(f, "  },\n  \"checkers\": {");
        for (int k = 0; k < CHK_COUNT; ++k)
            std::fprintf(f, "%s\"%s\": {\"checks\": %" PRIu64 ", \"failures\": %" PRIu64 "}",
                         k ? ", " : "", CHK_NAME[k], g_checks[k], g_fail[k]);
        std::fprintf(f, "},\n  \"pass\": %s\n}\n", mask ? "false" : "true");
        std::fclose(f);
        std::printf("test_cdc: report %s\n", g_json.c_str());
    }

    top->final();
    delete top;
    if (mask) {
        std::printf("test_cdc: FAILED (checkers:");
        for (int k = 0; k < CHK_COUNT; ++k)
            if (mask >> k & 1) std::printf(" %s", CHK_NAME[k]);
        std::printf("), exit %d\n", 64 | mask);
        return 64 | mask;
    }
    std::printf("test_cdc: PASSED %" PRIu64 " accesses, all checkers clean\n", g_completed);
    return 0;
}
