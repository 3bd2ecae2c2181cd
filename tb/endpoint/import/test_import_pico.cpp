// test_import_pico.cpp -- Verilator harness of tb/endpoint/import/import_pico.v:
// a PicoRV32 producer (tb/pico/firmware/producer.c with the real driver, port
// A) feeds an RTL consumer (albatross_import_endpoint, port B) that this
// harness drives and checks: every value it hands out must be one whole
// pair value (soc/firmware/board.h: check words match), its sequence never
// goes back, and new_o is high exactly when the value is newer than the last
// one (the first Import of a cold endpoint is New).  The protocol checker
// (tb/common/protocol_checker.h) watches both ports of the RAM
// (tb/endpoint/channel_watch.h), with the endpoint's new_o as the Import's
// result.  The clock is driven from here (no --timing).
//
//   test_import_pico +fw0=PRODUCER.hex [--values N] [--max-cycles N] [--seed S]
//                    [--report FILE] [--label NAME] [--expect-checker KIND]
//
// The harness starts Imports once the producer has stored the start flag,
// as often as the endpoint takes them, with random gaps (each free clock
// starts one with probability 1/16, 1..32 clocks); it takes the words with
// word_ready_i low one clock in 8 and in rare holds (1/256, 1..300 clocks;
// 1/4096, 1..4096 clocks: longer than one of the producer's Exports), so an
// Import can stay in its buffer while the producer exports again; the core's local RAM is held in bursts (1/2048, 1..2048).
// Runs until the endpoint has handed out seq N (default 2000, producer.c's
// PAIR_VALUES) and the core stored to TOHOST, or the watchdog of --max-cycles
// simulated cycles fires.  --expect-checker KIND (a negative test with a
// mutant engine): passes only if checker KIND reported a violation.
// Exit status 0 = verdict pass.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vimport_pico.h"
#include "verilated.h"
#include "report.h"
#include "../bench_options.h"
#include "../channel_watch.h"

static const int kWords = 4, kBase = 0;
static const uint32_t kStartFlagWord = 0x100 / 4, kStartMagic = 0x5354;

int main(int argc, char **argv)
{
    BenchOptions opt;
    opt.values = 2000;
    opt.label = "endpoint-import";
    if (!opt.parse(argc, argv)) return 2;
    const uint64_t max_cycles = opt.max_cycles, seed = opt.seed, values = opt.values;
    const std::string &report = opt.report, &label = opt.label, &expect = opt.expect;
    const int expect_kind = opt.expect_kind;
    Verilated::commandArgs(argc, argv);
    Vimport_pico m;

    ChannelWatch watch(kBase * 4u, kWords * 4u, 0, 1);
    watch.chk.value_fn = cw_pair_value;
    watch.external_result = true;

    m.clk_i = 0;
    m.rst_i = 1;
    m.core_stall_i = 0;
    m.import_i = 0;
    m.word_ready_i = 0;
    m.eval();                                // every clock low before the first edge
    uint64_t cycle = 0;
    auto tick = [&]() { m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle; };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0;

    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 7;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    uint64_t gap_left = 0, hold_left = 0, core_left = 0;
    bool started = false;

    // The harness's own check of every value, and the figures.
    uint32_t value[kWords] = {};
    uint8_t expect_bytes[16];
    bool has_last = false;
    uint64_t last = 0, imports = 0, news = 0, corrupt = 0, value_errors = 0;
    std::string first_value_error;
    bool imp_open = false, imp_held = false;
    uint64_t imp_clocks = 0, imp_idle = 0, imp_acks = 0;
    uint64_t und_n[2] = {}, und_clocks[2] = {}, und_min[2] = {~0ull, ~0ull}, und_max[2] = {}, und_idle = 0;
    uint64_t acc_min[2] = {~0ull, ~0ull}, acc_max[2] = {};
    bool prod_touched = false;
    auto value_error = [&](const char *fmt, unsigned long long a, unsigned long long b) {
        char msg[200];
        std::snprintf(msg, sizeof msg, fmt, a, b);
        if (value_errors++ == 0) first_value_error = msg;
    };

    while (!(m.done_o && has_last && last >= values) && !m.trap_o && !m.bus_err_o && cycle < max_cycles) {
        if (core_left == 0 && (next() & 2047u) == 0) core_left = 1 + next() % 2048u;
        m.core_stall_i = core_left != 0;
        if (core_left) --core_left;
        if (gap_left == 0 && (next() & 15u) == 0) gap_left = 1 + next() % 32u;
        if (hold_left == 0 && (next() & 255u) == 0) hold_left = 1 + next() % 300u;
        if (hold_left == 0 && (next() & 4095u) == 0) hold_left = 1 + next() % 4096u;   // past an Export or two
        m.import_i = started && !m.imp_busy_o && gap_left == 0;
        m.word_ready_i = hold_left == 0 && (next() & 7u) != 0;
        if (gap_left) --gap_left;
        if (hold_left) --hold_left;
        m.eval();
        if (m.imp_word_valid_o && m.word_ready_i && m.imp_word_index_o < kWords)
            value[m.imp_word_index_o] = m.imp_word_o;
        if (imp_open && m.imp_word_valid_o && !m.word_ready_i) imp_held = true;
        tick();
        for (int p = 0; p < 2; ++p) {
            if (!((m.mon_ack_o >> p) & 1u)) continue;
            const bool we = (m.mon_we_o >> p) & 1u;
            const uint32_t adr = (m.mon_adr_o >> (10 * p)) & 0x3ffu;
            const uint32_t wdat = static_cast<uint32_t>(m.mon_wdat_o >> (32 * p));
            if (p == 0 && we && adr == kStartFlagWord && wdat == kStartMagic && !started) {
                started = true;               // the producer's image is in place
                watch.arm_producer();
                watch.arm_consumer();
                watch.chk.consumer_restarted();   // a cold endpoint: its first Import is New
                continue;
            }
            if (p == 0 && imp_open) prod_touched = true;
            watch.on_access(p, we, adr, (m.mon_sel_o >> (4 * p)) & 0xfu, wdat,
                            static_cast<uint32_t>(m.mon_rdat_o >> (32 * p)), cycle);
        }
        if (m.imp_busy_o) {
            if (!imp_open) { imp_open = true; imp_held = prod_touched = false; imp_clocks = imp_idle = imp_acks = 0; }
            ++imp_clocks;
            if (!((m.mon_stb_o >> 1) & 1u)) ++imp_idle;
        }
        if (imp_open && ((m.mon_ack_o >> 1) & 1u)) ++imp_acks;
        if (m.imp_done_o) {
            imp_open = false;
            ++imports;
            const bool is_new = m.imp_new_o;
            if (m.imp_corrupt_o) {
                ++corrupt;
                watch.import_done(ALB_ERR_CORRUPT, cycle);
            } else {
                watch.import_done(is_new ? ALB_NEW : ALB_OLD, cycle);
                const uint64_t seq = value[0];
                cw_pair_value(seq, expect_bytes, sizeof expect_bytes);
                if (std::memcmp(expect_bytes, value, sizeof expect_bytes) != 0)
                    value_error("Import %llu returned a torn value (check words do not match seq %llu)", imports, seq);
                else if (has_last && seq < last)
                    value_error("Import returned seq %llu after seq %llu: went back", seq, last);
                else if (has_last && is_new != (seq > last))
                    value_error(is_new ? "Import returned New for seq %llu after seq %llu" :
                                         "Import returned Old for seq %llu after seq %llu", seq, last);
                else if (!has_last && !is_new)
                    value_error("the first Import of a cold endpoint returned Old (seq %llu, %llu)", seq, 0);
                has_last = true;
                last = seq;
                if (is_new) ++news;
                const int k = is_new ? 1 : 0;
                if (imports > 1) {
                    acc_min[k] = std::min(acc_min[k], imp_acks);
                    acc_max[k] = std::max(acc_max[k], imp_acks);
                }
                if (!imp_held && !prod_touched && imports > 1) {   // undisturbed
                    ++und_n[k];
                    und_clocks[k] += imp_clocks;
                    und_min[k] = std::min(und_min[k], imp_clocks);
                    und_max[k] = std::max(und_max[k], imp_clocks);
                    und_idle += imp_idle;
                }
            }
        }
        if (expect_kind >= 0 && watch.chk.violations[expect_kind]) break;   // caught: enough
    }

    const uint32_t code = m.code_o;
    const ProtocolChecker &chk = watch.chk;
    std::printf("%s: seed %llu, %llu cycles, producer %s, %llu Imports (%llu New), last seq %llu of %llu\n",
                label.c_str(), static_cast<unsigned long long>(seed), static_cast<unsigned long long>(cycle),
                m.done_o ? (code == 0 ? "passed" : "failed") : "still running",
                static_cast<unsigned long long>(imports), static_cast<unsigned long long>(news),
                static_cast<unsigned long long>(last), static_cast<unsigned long long>(values));
    std::printf("  checker: %llu Imports watched, %llu Exports watched, worst Import %llu loop iterations / "
                "%llu accesses\n", static_cast<unsigned long long>(chk.imports),
                static_cast<unsigned long long>(chk.exports),
                static_cast<unsigned long long>(chk.worst_import_iterations),
                static_cast<unsigned long long>(chk.worst_import_accesses));
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (chk.violations[k])
            std::printf("  checker %s: %llu violations, first: %s\n", ProtocolChecker::kind_name(k),
                        static_cast<unsigned long long>(chk.violations[k]), chk.first_message[k].c_str());
    const char *kn[2] = {"Old", "New"};
    double mean[2] = {};
    for (int k = 0; k < 2; ++k) {
        mean[k] = und_n[k] ? double(und_clocks[k]) / double(und_n[k]) : 0.0;
        std::printf("  Import engine, %s: %llu..%llu accesses; %llu undisturbed: %.2f clocks busy each "
                    "(min %llu, max %llu)\n", kn[k], static_cast<unsigned long long>(acc_min[k] == ~0ull ? 0 : acc_min[k]),
                    static_cast<unsigned long long>(acc_max[k]), static_cast<unsigned long long>(und_n[k]), mean[k],
                    static_cast<unsigned long long>(und_n[k] ? und_min[k] : 0),
                    static_cast<unsigned long long>(und_max[k]));
    }
    std::printf("  %llu idle bus clocks inside undisturbed Imports\n", static_cast<unsigned long long>(und_idle));

    static char buf[512];
    const char *fail = nullptr;
    const uint64_t want_acc[2] = {1u + kWords, 3u + kWords};
    if (expect_kind >= 0) {
        if (!chk.violations[expect_kind]) {
            std::snprintf(buf, sizeof buf, "expected checker %s to catch the mutant, it reported nothing "
                          "(%llu Imports)", expect.c_str(), static_cast<unsigned long long>(imports));
            fail = buf;
        }
    } else if (m.trap_o) {
        fail = "expected no trap, got a trap on the producer core";
    } else if (m.bus_err_o) {
        fail = "expected no unmapped access, got one from the producer core";
    } else if (!(m.done_o && has_last && last >= values)) {
        std::snprintf(buf, sizeof buf, "expected the endpoint to hand out seq %llu and the producer to finish "
                      "within %llu cycles (watchdog), got seq %llu, producer %s",
                      static_cast<unsigned long long>(values), static_cast<unsigned long long>(max_cycles),
                      static_cast<unsigned long long>(last), m.done_o ? "done" : "still running");
        fail = buf;
    } else if (code != 0) {
        std::snprintf(buf, sizeof buf, "expected producer exit code 0, got 0x%x", code);
        fail = buf;
    } else if (value_errors) {
        std::snprintf(buf, sizeof buf, "expected every value whole and in order, got %llu errors, first: %s",
                      static_cast<unsigned long long>(value_errors), first_value_error.c_str());
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
    } else if (corrupt) {
        std::snprintf(buf, sizeof buf, "expected valid control bytes, got corrupt_o on %llu Imports",
                      static_cast<unsigned long long>(corrupt));
        fail = buf;
    } else if (acc_min[0] != want_acc[0] || acc_max[0] != want_acc[0] || acc_min[1] != want_acc[1]) {
        std::snprintf(buf, sizeof buf, "expected %llu accesses per Old Import and at least %llu per New one, "
                      "got %llu..%llu and %llu..%llu", static_cast<unsigned long long>(want_acc[0]),
                      static_cast<unsigned long long>(want_acc[1]), static_cast<unsigned long long>(acc_min[0]),
                      static_cast<unsigned long long>(acc_max[0]), static_cast<unsigned long long>(acc_min[1]),
                      static_cast<unsigned long long>(acc_max[1]));
        fail = buf;
    } else if (und_idle) {
        std::snprintf(buf, sizeof buf, "expected no idle bus clock inside an undisturbed Import, got %llu",
                      static_cast<unsigned long long>(und_idle));
        fail = buf;
    } else {
        for (int k = 0; k < 2 && !fail; ++k)
            if (!und_n[k] || und_min[k] < 2 * want_acc[k] || und_max[k] > 2 * want_acc[k] + 1) {
                // 2 clocks per access back to back, plus 1 when the first
                // request falls in the other port's slot of albatross_dpram.
                std::snprintf(buf, sizeof buf, "expected an undisturbed %s Import to take %llu or %llu clocks, "
                              "got %llu..%llu (%llu seen)", kn[k], static_cast<unsigned long long>(2 * want_acc[k]),
                              static_cast<unsigned long long>(2 * want_acc[k] + 1),
                              static_cast<unsigned long long>(und_min[k]), static_cast<unsigned long long>(und_max[k]),
                              static_cast<unsigned long long>(und_n[k]));
                fail = buf;
            }
    }

    JsonReport r;
    r.str("label", label).num("seed", static_cast<double>(seed)).num("cycles", static_cast<double>(cycle))
     .num("values", static_cast<double>(last)).num("words", kWords)
     .num("imports", static_cast<double>(imports)).num("imports_new", static_cast<double>(news))
     .num("accesses_per_import_old", static_cast<double>(acc_min[0] == ~0ull ? 0 : acc_min[0]))
     .num("accesses_per_import_new", static_cast<double>(acc_min[1] == ~0ull ? 0 : acc_min[1]))
     .num("undisturbed_old", static_cast<double>(und_n[0])).num("clocks_per_import_old_mean", mean[0])
     .num("undisturbed_new", static_cast<double>(und_n[1])).num("clocks_per_import_new_mean", mean[1])
     .num("idle_bus_clocks_inside", static_cast<double>(und_idle))
     .num("worst_import_iterations", static_cast<double>(chk.worst_import_iterations))
     .num("producer_exports", static_cast<double>(chk.exports)).num("producer_code", code);
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
