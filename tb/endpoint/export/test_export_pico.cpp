// test_export_pico.cpp -- Verilator harness of tb/endpoint/export/export_pico.v:
// an RTL producer (pair_source + albatross_export_endpoint on port A) feeds a
// PicoRV32 consumer (tb/pico/firmware/consumer.c with the real driver, port
// B).  The consumer checks every value on the core (sequence, check words,
// New only with a newer value); the protocol checker (tb/common/
// protocol_checker.h) watches both ports of the RAM (tb/endpoint/
// channel_watch.h).  The clock is driven from here (no --timing).
//
//   test_export_pico +fw1=CONSUMER.hex --values N [--max-cycles N] [--seed S]
//                    [--report FILE] [--label NAME] [--expect-checker KIND]
//
// Stalls (xorshift, seed S): pair_source is held in bursts (each free clock
// starts one with probability 1/32, 1..64 clocks), so Exports start and take
// their words in every phase; the core's local RAM is held in bursts (1/2048,
// 1..2048 clocks), so Exports overtake it inside an Import.
// Runs until the core stores to TOHOST (it stops at seq N), traps, touches an
// unmapped address, or the watchdog of --max-cycles simulated cycles fires.
// Normal run: exit code 0, no checker violation, every Export the fixed
// number of accesses, and no idle bus clock inside an Export whose stream
// never stalled.  --expect-checker KIND (a negative test with a mutant
// engine): passes only if checker KIND reported a violation.
// Exit status 0 = verdict pass.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vexport_pico.h"
#include "verilated.h"
#include "report.h"
#include "../bench_options.h"
#include "../channel_watch.h"

static const int kWords = 4, kBase = 0;

static const char *code_text(uint32_t code)
{
    switch (code & 0xffu) {
    case 0x0: return "pass";
    case 0x3: return "torn value (check words do not match)";
    case 0x4: return "sequence number went back";
    case 0x5: return "New without a newer value";
    case 0x6: return "Old with a newer value";
    default:  return (code & 0xf0u) == 0x20u ? "alb_import returned an error"
                   : (code & 0xf0u) == 0x30u ? "consumer attach failed" : "unknown code";
    }
}

int main(int argc, char **argv)
{
    BenchOptions opt;
    opt.values = 0;
    opt.label = "endpoint-export";
    if (!opt.parse(argc, argv)) return 2;
    const uint64_t max_cycles = opt.max_cycles, seed = opt.seed, values = opt.values;
    const std::string &report = opt.report, &label = opt.label, &expect = opt.expect;
    const int expect_kind = opt.expect_kind;
    Verilated::commandArgs(argc, argv);
    Vexport_pico m;

    ChannelWatch watch(kBase * 4u, kWords * 4u, 0, 1);
    watch.chk.value_fn = cw_pair_value;
    watch.skip_consumer_ctrl_reads = 1;      // consumer.c's alb_consumer_attach
    watch.arm_producer();
    watch.arm_consumer();

    m.clk_i = 0;
    m.rst_i = 1;
    m.gen_stall_i = 0;
    m.core_stall_i = 0;
    m.eval();                                // every clock low before the first edge
    uint64_t cycle = 0;
    auto tick = [&]() { m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle; };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0;

    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 1;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    uint64_t gen_left = 0, core_left = 0, gen_stalled = 0, core_stalled = 0;

    // Per Export of the endpoint: busy clocks, clocks with the bus idle, acks,
    // and whether the stream stalled (asked for a word, none offered).
    uint64_t exports = 0, exp_clocks = 0, exp_idle = 0, exp_acks = 0;
    bool exp_open = false, exp_stalled = false;
    uint64_t smooth = 0, smooth_clocks = 0, smooth_min = ~0ull, smooth_max = 0, smooth_idle = 0;
    uint64_t acc_min = ~0ull, acc_max = 0, corrupt = 0, stalled_exports = 0;

    while (!m.done_o && !m.trap_o && !m.bus_err_o && cycle < max_cycles) {
        if (gen_left == 0 && (next() & 31u) == 0) gen_left = 1 + next() % 64u;
        if (core_left == 0 && (next() & 2047u) == 0) core_left = 1 + next() % 2048u;
        m.gen_stall_i = gen_left != 0;
        m.core_stall_i = core_left != 0;
        if (gen_left) { --gen_left; ++gen_stalled; }
        if (core_left) { --core_left; ++core_stalled; }
        // Sample this clock's stream handshake before the edge.
        m.eval();
        if (exp_open && m.exp_word_ready_o && !m.exp_word_valid_o) exp_stalled = true;
        tick();
        for (int p = 0; p < 2; ++p)
            if ((m.mon_ack_o >> p) & 1u)
                watch.on_access(p, (m.mon_we_o >> p) & 1u, (m.mon_adr_o >> (10 * p)) & 0x3ffu,
                                (m.mon_sel_o >> (4 * p)) & 0xfu, static_cast<uint32_t>(m.mon_wdat_o >> (32 * p)),
                                static_cast<uint32_t>(m.mon_rdat_o >> (32 * p)), cycle);
        if (m.exp_busy_o) {
            if (!exp_open) { exp_open = true; exp_stalled = false; exp_clocks = exp_idle = exp_acks = 0; }
            ++exp_clocks;
            if (!(m.mon_stb_o & 1u)) ++exp_idle;
        }
        if (exp_open && (m.mon_ack_o & 1u)) ++exp_acks;
        if (m.exp_done_o) {
            exp_open = false;
            ++exports;
            if (m.exp_corrupt_o) ++corrupt;
            if (exports > 1) {               // the first reads Actual back: one access more
                acc_min = std::min(acc_min, exp_acks);
                acc_max = std::max(acc_max, exp_acks);
            }
            if (exp_stalled) {
                ++stalled_exports;
            } else if (exports > 1) {
                ++smooth;
                smooth_clocks += exp_clocks;
                smooth_min = std::min(smooth_min, exp_clocks);
                smooth_max = std::max(smooth_max, exp_clocks);
                smooth_idle += exp_idle;
            }
        }
        if (expect_kind >= 0 && watch.chk.violations[expect_kind]) break;   // caught: enough
    }

    const uint32_t code = m.code_o;
    const ProtocolChecker &chk = watch.chk;
    std::printf("%s: seed %llu, %llu cycles (pair_source held %llu, core held %llu), %llu Exports "
                "(last seq %u), consumer %s\n", label.c_str(), static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(cycle), static_cast<unsigned long long>(gen_stalled),
                static_cast<unsigned long long>(core_stalled), static_cast<unsigned long long>(exports),
                m.seq_o, m.done_o ? (code == 0 ? "passed" : code_text(code)) : "still running");
    std::printf("  checker: %llu Imports watched (%llu New), %llu Exports watched, worst Import %llu loop "
                "iterations / %llu accesses\n", static_cast<unsigned long long>(chk.imports),
                static_cast<unsigned long long>(chk.imports_new), static_cast<unsigned long long>(chk.exports),
                static_cast<unsigned long long>(chk.worst_import_iterations),
                static_cast<unsigned long long>(chk.worst_import_accesses));
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (chk.violations[k])
            std::printf("  checker %s: %llu violations, first: %s\n", ProtocolChecker::kind_name(k),
                        static_cast<unsigned long long>(chk.violations[k]), chk.first_message[k].c_str());
    const double mean = smooth ? double(smooth_clocks) / double(smooth) : 0.0;
    std::printf("  Export engine: %llu accesses per Export (after the first), %llu Exports with the stream "
                "never stalled: %.2f clocks busy each (min %llu, max %llu), %llu idle bus clocks inside; "
                "%llu Exports waited for a word\n",
                static_cast<unsigned long long>(acc_min), static_cast<unsigned long long>(smooth), mean,
                static_cast<unsigned long long>(smooth ? smooth_min : 0),
                static_cast<unsigned long long>(smooth_max), static_cast<unsigned long long>(smooth_idle),
                static_cast<unsigned long long>(stalled_exports));

    static char buf[512];
    const char *fail = nullptr;
    if (expect_kind >= 0) {
        if (!chk.violations[expect_kind]) {
            std::snprintf(buf, sizeof buf, "expected checker %s to catch the mutant, it reported nothing "
                          "(%llu Exports, consumer code 0x%x)", expect.c_str(),
                          static_cast<unsigned long long>(exports), code);
            fail = buf;
        }
    } else if (m.trap_o) {
        fail = "expected no trap, got a trap on the consumer core";
    } else if (m.bus_err_o) {
        fail = "expected no unmapped access, got one from the consumer core";
    } else if (!m.done_o) {
        std::snprintf(buf, sizeof buf, "expected the consumer to reach seq %llu within %llu cycles (watchdog), "
                      "got it still running with the producer at seq %u",
                      static_cast<unsigned long long>(values), static_cast<unsigned long long>(max_cycles), m.seq_o);
        fail = buf;
    } else if (code != 0) {
        std::snprintf(buf, sizeof buf, "expected consumer exit code 0, got 0x%x (%s at sequence %u)", code,
                      code_text(code), code >> 8);
        fail = buf;
    } else if (chk.total_violations()) {
        for (int k = 0; k < ProtocolChecker::KINDS && !fail; ++k)
            if (chk.violations[k]) {
                std::snprintf(buf, sizeof buf, "expected no %s violation, got %llu: %s",
                              ProtocolChecker::kind_name(k), static_cast<unsigned long long>(chk.violations[k]),
                              chk.first_message[k].c_str());
                fail = buf;
            }
    } else if (watch.export_order_errors) {
        std::snprintf(buf, sizeof buf, "expected the Exports in sequence, got: %s", watch.first_order_error.c_str());
        fail = buf;
    } else if (values && exports != values) {
        std::snprintf(buf, sizeof buf, "expected %llu Exports, got %llu", static_cast<unsigned long long>(values),
                      static_cast<unsigned long long>(exports));
        fail = buf;
    } else if (corrupt) {
        std::snprintf(buf, sizeof buf, "expected valid control bytes, got corrupt_o on %llu Exports",
                      static_cast<unsigned long long>(corrupt));
        fail = buf;
    } else if (acc_min != kWords + 2 || acc_max != kWords + 2) {
        std::snprintf(buf, sizeof buf, "expected %d accesses per Export, got %llu..%llu", kWords + 2,
                      static_cast<unsigned long long>(acc_min), static_cast<unsigned long long>(acc_max));
        fail = buf;
    } else if (smooth_idle) {
        std::snprintf(buf, sizeof buf, "expected no idle bus clock inside an Export whose stream never stalled, "
                      "got %llu", static_cast<unsigned long long>(smooth_idle));
        fail = buf;
    } else if (!smooth || smooth_min < 2u * (kWords + 2) || smooth_max > 2u * (kWords + 2) + 1u) {
        // 2 clocks per access back to back, plus 1 when the first request
        // falls in the other port's slot of albatross_dpram.
        std::snprintf(buf, sizeof buf, "expected an undisturbed Export to take %d or %d clocks, got %llu..%llu",
                      2 * (kWords + 2), 2 * (kWords + 2) + 1, static_cast<unsigned long long>(smooth_min),
                      static_cast<unsigned long long>(smooth_max));
        fail = buf;
    }

    JsonReport r;
    r.str("label", label).num("seed", static_cast<double>(seed)).num("cycles", static_cast<double>(cycle))
     .num("values", static_cast<double>(exports)).num("words", kWords)
     .num("accesses_per_export", static_cast<double>(acc_min == ~0ull ? 0 : acc_min))
     .num("undisturbed_exports", static_cast<double>(smooth))
     .num("clocks_per_export_mean", mean).num("clocks_per_export_min", static_cast<double>(smooth ? smooth_min : 0))
     .num("clocks_per_export_max", static_cast<double>(smooth_max))
     .num("idle_bus_clocks_inside", static_cast<double>(smooth_idle))
     .num("consumer_imports", static_cast<double>(chk.imports))
     .num("consumer_imports_new", static_cast<double>(chk.imports_new))
     .num("worst_import_iterations", static_cast<double>(chk.worst_import_iterations))
     .num("consumer_code", code);
    std::string v = "{";
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        v += std::string(k ? ", " : "") + "\"" + ProtocolChecker::kind_name(k) + "\": " +
             std::to_string(chk.violations[k]);
    r.raw("violations", v + "}");
    r.str("verdict", fail ? "fail" : "pass");
    if (!report.empty() && !r.write(report)) return 1;
    if (fail) { std::printf("%s: FAIL: %s\n", label.c_str(), fail); return 1; }
    std::printf("%s: pass%s\n", label.c_str(), expect_kind >= 0 ? (": checker " + expect + " caught the mutant, as expected").c_str() : "");
    return 0;
}
