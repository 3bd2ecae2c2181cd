// test_vex_pair.cpp -- Verilator harness of tb/pico/pico_pair.v with a
// VexRiscv core (data cache, soc/vexriscv_core.v) on one side of the channel
// and PicoRV32 on the other: both run the real driver
// (tb/pico/firmware/producer.c, consumer.c), and the protocol checker
// (tb/common/protocol_checker.h, fed by tb/endpoint/channel_watch.h) watches
// both ports of the DPRAM: mutual exclusion, definite results, actuality,
// termination and ownership on every Export and Import, from the accesses as
// the RAM performs them.  The consumer checks every value on its core
// (sequence, check words: soc/firmware/board.h).  The clock is driven from
// here (no --timing).
//
//   test_vex_pair +fw0=PRODUCER.hex +fw1=CONSUMER.hex [--max-cycles N]
//                 [--seed S] [--stall-core C] [--report FILE] [--label NAME]
//                 [--expect-caught-by KIND] [--expect-stale]
//                 [--stop-after N]
//
// Stalls as tb/pico/test_pico_pair.cpp: core C (default 1; -1 none; 2 both)
// has its local RAM held in random bursts (1/2048 per free clock, 1..4096
// clocks), so Exports overtake Imports.  Runs until both cores stored to
// TOHOST, or an unmapped access, or N cycles (the watchdog).
// Normal run: both exit codes 0 and no checker violation.
// --expect-caught-by KIND (the negative test: a cached DPRAM window): passes
// only if checker KIND reported violations, no other checker except
// definite_results did (a value torn by the same overlap), the consumer's own
// checks found torn or out-of-order values (codes 3..6; it is built with
// -DPAIR_COUNT_FAULTS and reports their number in STAT 3), and both cores
// finished without an unmapped access.  It prints how many were caught.
//
// Core-reported actuality.  A consumer built with -DPAIR_EVENTS announces
// each Import (board EVENTs PAIR_EV_*, soc/firmware/board.h): the value it
// returns must not be older than the newest value the producer had
// published (its store of Actual, seen at the RAM) when the Import began
// (its EVENT store).  This check does not depend on what reaches the RAM, so
// it also holds a consumer whose loads a cache answers.  Normal run: no
// stale Import.  --expect-stale (the negative test with the consumer's
// channel cached): passes only if stale Imports were seen, and prints how
// many and how many values the consumer received at all; with --stop-after N
// the run ends N cycles after the producer finished (a consumer that only
// ever sees a stale Actual never finishes).
// Exit status 0 = verdict pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vpico_pair.h"
#include "verilated.h"
#include "report.h"
#include "channel_watch.h"

static const uint32_t kStartFlagWord = 0x100 / 4, kStartMagic = 0x5354, kBytes = 16;

static uint32_t stat(const Vpico_pair &m, int core, int k) { return m.stat_o[core * 4 + k]; }

// The consumer's events (soc/firmware/board.h PAIR_EV_*).
static const uint32_t kEvBegin = 0x1, kEvNew = 0x2, kEvOld = 0x3;

int main(int argc, char **argv)
{
    uint64_t max_cycles = 20000000, seed = 1;
    std::string report, label = "vex-pair", expect;
    int stall_core = 1, expect_kind = -1;
    bool expect_stale = false;
    uint64_t stop_after = 0;
    for (int i = 1; i < argc; ++i) {
        const bool more = i + 1 < argc;
        if (!std::strcmp(argv[i], "--max-cycles") && more) max_cycles = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--seed") && more) seed = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--stall-core") && more) stall_core = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--report") && more) report = argv[++i];
        else if (!std::strcmp(argv[i], "--label") && more) label = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-caught-by") && more) expect = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-stale")) expect_stale = true;
        else if (!std::strcmp(argv[i], "--stop-after") && more) stop_after = std::strtoull(argv[++i], 0, 0);
        else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    if (!expect.empty()) {
        for (int k = 0; k < ProtocolChecker::KINDS; ++k)
            if (expect == ProtocolChecker::kind_name(k)) expect_kind = k;
        if (expect_kind < 0) { std::fprintf(stderr, "unknown checker %s\n", expect.c_str()); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vpico_pair m;

    ChannelWatch watch(0u, kBytes, 0, 1);
    watch.chk.value_fn = cw_pair_value;
    watch.skip_consumer_ctrl_reads = 1;   // alb_consumer_attach's load of ReadLocked

    // Every clock low before the first edge (TOOLCHAIN.md), then reset.
    m.clk_i = 0;
    m.rst_i = 1;
    m.stall_i = 0;
    m.eval();
    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 1, left[2] = {0, 0}, stalled = 0, cycle = 0;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    auto tick = [&]() { m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle; };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0;
    bool armed = false;
    uint64_t done_at[2] = {0, 0};
    // Core-reported Imports: begun, ended, stale, the newest seq received.
    uint64_t ev_begun = 0, ev_imports = 0, stale = 0, pub_at_begin = 0, newest_got = 0;
    bool ev_open = false;
    std::string first_stale;
    auto stopped = [&]() { return stop_after && (m.done_o & 1u) && cycle >= done_at[0] + stop_after; };
    while ((m.done_o & 3u) != 3u && cycle < max_cycles && !(m.bus_err_o & 3u) && !stopped()) {
        uint8_t s = 0;
        for (int c = 0; c < 2; ++c) {
            if (stall_core != c && stall_core != 2) continue;
            if (left[c] == 0 && (next() & 2047u) == 0) left[c] = 1 + next() % 4096u;
            if (left[c]) { --left[c]; ++stalled; s |= static_cast<uint8_t>(1u << c); }
        }
        m.stall_i = s;
        tick();
        for (int p = 0; p < 2; ++p) {
            if (!((m.mon_ack_o >> p) & 1u)) continue;
            const bool we = (m.mon_we_o >> p) & 1u;
            const uint32_t adr = (m.mon_adr_o >> (10 * p)) & 0x3ffu;
            const uint32_t wdat = static_cast<uint32_t>(m.mon_wdat_o >> (32 * p));
            if (p == 0 && we && adr == kStartFlagWord && wdat == kStartMagic && !armed) {
                armed = true;                 // the start image is in place, both attached next
                watch.arm_producer();
                watch.arm_consumer();
                continue;
            }
            watch.on_access(p, we, adr, (m.mon_sel_o >> (4 * p)) & 0xfu, wdat,
                            static_cast<uint32_t>(m.mon_rdat_o >> (32 * p)), cycle);
        }
        if ((m.ev_valid_o >> 1) & 1u) {
            const uint32_t key = static_cast<uint32_t>(m.ev_data_o >> 32), arg = static_cast<uint32_t>(m.ev_arg_o >> 32);
            if (key == kEvBegin) {
                ev_open = true;
                ++ev_begun;
                pub_at_begin = watch.chk.newest_published_seq();
            } else if ((key == kEvNew || key == kEvOld) && ev_open) {
                ev_open = false;
                ++ev_imports;
                if (arg > newest_got) newest_got = arg;
                if (arg < pub_at_begin && stale++ == 0) {
                    char msg[200];
                    std::snprintf(msg, sizeof msg, "Import %llu returned seq %u (%s), but seq %llu was published "
                                  "before it began", static_cast<unsigned long long>(ev_imports), arg,
                                  key == kEvNew ? "New" : "Old", static_cast<unsigned long long>(pub_at_begin));
                    first_stale = msg;
                }
            }
        }
        for (int c = 0; c < 2; ++c)
            if (((m.done_o >> c) & 1u) && !done_at[c]) done_at[c] = cycle;
    }
    const uint32_t done = m.done_o & 3u, err = m.bus_err_o & 3u;
    const uint32_t code[2] = {static_cast<uint32_t>(m.code_o & 0xffffffffu), static_cast<uint32_t>(m.code_o >> 32)};
    const char *name[2] = {"producer", "consumer"};
    const ProtocolChecker &chk = watch.chk;
    std::printf("%s: seed %llu, %llu cycles (%llu stalled), done %u%u, bus error %u%u\n", label.c_str(),
                static_cast<unsigned long long>(seed), static_cast<unsigned long long>(cycle),
                static_cast<unsigned long long>(stalled), done & 1u, done >> 1, err & 1u, err >> 1);
    for (int c = 0; c < 2; ++c)
        if (done >> c & 1u)
            std::printf("  %s: exit code 0x%x after %llu cycles\n", name[c], code[c],
                        static_cast<unsigned long long>(done_at[c]));
    std::printf("  checker: %llu Exports, %llu Imports (%llu New) watched at the RAM, worst Import %llu loop "
                "iterations\n", static_cast<unsigned long long>(chk.exports),
                static_cast<unsigned long long>(chk.imports), static_cast<unsigned long long>(chk.imports_new),
                static_cast<unsigned long long>(chk.worst_import_iterations));
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (chk.violations[k])
            std::printf("  checker %s: %llu violations, first: %s\n", ProtocolChecker::kind_name(k),
                        static_cast<unsigned long long>(chk.violations[k]), chk.first_message[k].c_str());

    if (ev_begun)
        std::printf("  consumer-reported Imports: %llu, stale %llu (older than the newest value published when they "
                    "began)%s%s; newest seq received %llu\n", static_cast<unsigned long long>(ev_imports),
                    static_cast<unsigned long long>(stale), stale ? ", first: " : "", first_stale.c_str(),
                    static_cast<unsigned long long>(newest_got));

    const char *fail = nullptr;
    static char buf[512];
    const uint32_t faults = stat(m, 1, 3);
    if (expect_stale) {
        if (err) {
            std::snprintf(buf, sizeof buf, "expected no unmapped access, got one from the %s", err & 1u ? name[0] : name[1]);
            fail = buf;
        } else if (!(done & 1u)) {
            fail = "expected the producer to finish, it is still running";
        } else if (code[0] != 0) {
            std::snprintf(buf, sizeof buf, "expected producer exit code 0, got 0x%x", code[0]);
            fail = buf;
        } else if (!stale) {
            std::snprintf(buf, sizeof buf, "expected stale Imports from the cached consumer, got none of %llu",
                          static_cast<unsigned long long>(ev_imports));
            fail = buf;
        } else if ((done >> 1) && (code[1] & 0xffu) != 0 && ((code[1] & 0xffu) < 3u || (code[1] & 0xffu) > 6u)) {
            std::snprintf(buf, sizeof buf, "expected the consumer to end with a value check or not at all, got exit "
                          "code 0x%x", code[1]);
            fail = buf;
        }
    } else if (err) {
        std::snprintf(buf, sizeof buf, "expected no unmapped access, got one from the %s", err & 1u ? name[0] : name[1]);
        fail = buf;
    } else if (done != 3u) {
        std::snprintf(buf, sizeof buf, "expected both cores done within %llu cycles (watchdog), got the %s still "
                      "running", static_cast<unsigned long long>(max_cycles), done & 1u ? name[1] : name[0]);
        fail = buf;
    } else if (code[0] != 0) {
        std::snprintf(buf, sizeof buf, "expected producer exit code 0, got 0x%x", code[0]);
        fail = buf;
    } else if (expect_kind < 0) {
        if (stale) {
            std::snprintf(buf, sizeof buf, "expected no stale Import, got %llu: %s", static_cast<unsigned long long>(stale),
                          first_stale.c_str());
            fail = buf;
        } else if (code[1] != 0) {
            std::snprintf(buf, sizeof buf, "expected consumer exit code 0, got 0x%x (check code %u at sequence %u)",
                          code[1], code[1] & 0xffu, code[1] >> 8);
            fail = buf;
        } else if (watch.export_order_errors) {
            std::snprintf(buf, sizeof buf, "expected the Exports in sequence, got: %s", watch.first_order_error.c_str());
            fail = buf;
        } else if (chk.imports == 0 || chk.exports == 0) {
            std::snprintf(buf, sizeof buf, "expected the checker to watch Exports and Imports, got %llu and %llu",
                          static_cast<unsigned long long>(chk.exports), static_cast<unsigned long long>(chk.imports));
            fail = buf;
        } else {
            for (int k = 0; k < ProtocolChecker::KINDS && !fail; ++k)
                if (chk.violations[k]) {
                    std::snprintf(buf, sizeof buf, "expected no %s violation, got %llu: %s", ProtocolChecker::kind_name(k),
                                  static_cast<unsigned long long>(chk.violations[k]), chk.first_message[k].c_str());
                    fail = buf;
                }
        }
    } else {
        if (!chk.violations[expect_kind]) {
            std::snprintf(buf, sizeof buf, "expected checker %s to catch the cached window, it reported nothing "
                          "(%llu Imports watched)", expect.c_str(), static_cast<unsigned long long>(chk.imports));
            fail = buf;
        } else if ((code[1] & 0xffu) < 3u || (code[1] & 0xffu) > 6u || faults == 0) {
            std::snprintf(buf, sizeof buf, "expected the consumer to find torn or out-of-order values (codes 3..6), "
                          "got exit code 0x%x with %u faulty imports", code[1], faults);
            fail = buf;
        } else {
            for (int k = 0; k < ProtocolChecker::KINDS && !fail; ++k)
                if (chk.violations[k] && k != expect_kind && k != ProtocolChecker::DEFINITE) {
                    std::snprintf(buf, sizeof buf, "expected only %s (and definite_results) violations, got %llu %s: %s",
                                  expect.c_str(), static_cast<unsigned long long>(chk.violations[k]),
                                  ProtocolChecker::kind_name(k), chk.first_message[k].c_str());
                    fail = buf;
                }
        }
    }

    JsonReport r;
    r.str("label", label).num("seed", static_cast<double>(seed)).num("cycles", static_cast<double>(cycle))
     .num("stall_core", stall_core).num("stalled_cycles", static_cast<double>(stalled))
     .num("producer_code", code[0]).num("consumer_code", code[1])
     .num("checked_exports", static_cast<double>(chk.exports)).num("checked_imports", static_cast<double>(chk.imports));
    r.num("consumer_reported_imports", static_cast<double>(ev_imports)).num("stale_imports", static_cast<double>(stale))
     .num("newest_seq_received", static_cast<double>(newest_got));
    if (expect_kind < 0 && !expect_stale && !fail) {
        const uint32_t exports = stat(m, 0, 1), ex_cyc = stat(m, 0, 2);
        const uint32_t news = stat(m, 1, 0), imports = stat(m, 1, 1), im_cyc = stat(m, 1, 2);
        std::printf("  producer: %u exports, %.1f cycles per alb_export; consumer: %u imports (%u New), %.1f cycles "
                    "per alb_import (board cycle counter around each call, stalls included)\n", exports,
                    double(ex_cyc) / exports, imports, news, double(im_cyc) / imports);
        r.num("exports", exports).num("cycles_per_export", double(ex_cyc) / exports)
         .num("imports", imports).num("imports_new", news).num("cycles_per_import", double(im_cyc) / imports);
    }
    if (expect_kind >= 0) {
        std::printf("  caught: consumer found %u faulty imports (first: code %u at sequence %u); checker %s %llu, "
                    "definite_results %llu violations\n", faults, code[1] & 0xffu, code[1] >> 8, expect.c_str(),
                    static_cast<unsigned long long>(chk.violations[expect_kind]),
                    static_cast<unsigned long long>(chk.violations[ProtocolChecker::DEFINITE]));
        r.num("consumer_faulty_imports", faults);
    }
    std::string v = "{";
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        v += std::string(k ? ", " : "") + "\"" + ProtocolChecker::kind_name(k) + "\": " + std::to_string(chk.violations[k]);
    r.raw("violations", v + "}");
    r.str("verdict", fail ? "fail" : "pass");
    if (!report.empty() && !r.write(report)) return 1;
    if (fail) { std::printf("%s: FAIL: %s\n", label.c_str(), fail); return 1; }
    std::printf("%s: pass%s\n", label.c_str(), expect_kind >= 0 || expect_stale ? ": the cached window was caught, as expected" : "");
    return 0;
}
