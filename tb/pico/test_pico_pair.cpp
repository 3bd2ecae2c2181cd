// test_pico_pair.cpp -- Verilator harness of tb/pico/pico_pair.v: two PicoRV32
// cores run the real C driver (tb/pico/firmware/producer.c, tb/pico/firmware/consumer.c)
// against one albatross_dpram.  The clock is driven from here (no --timing).
//
//   test_pico_pair +fw0=PRODUCER.hex +fw1=CONSUMER.hex [--max-cycles N]
//                  [--report FILE] [--label NAME] [--expect-consumer-failure]
//                  [--seed S] [--stall-core C]
//
// Stalls: core C (default 1, the consumer; -1: none; 2: both, each with its
// own bursts) has its local-RAM accesses held (stall_i) in bursts: each free
// cycle starts one with probability 1/2048, lasting 1..4096 cycles
// (xorshift, seed S).  That varies
// the cores' relative speed and phase, so a consumer can be overtaken by
// several Exports inside one Import, as an interrupt would do.
//
// Runs until both cores stored to TOHOST, a core traps or touches an unmapped
// address, or N cycles pass (then it fails, naming what was still running).
// Normal run: both exit codes must be 0.  --expect-consumer-failure (negative
// test with a broken driver on either core): the consumer must report a torn
// or out-of-order value (codes 3..6, tb/pico/firmware/consumer.c) and the producer
// must still finish with 0.
// Exit status 0 = verdict pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vpico_pair.h"
#include "verilated.h"
#include "report.h"

static const char *code_text(uint32_t code)
{
    switch (code & 0xffu) {
    case 0x0: return "pass";
    case 0x3: return "torn value (check words do not match)";
    case 0x4: return "sequence number went back";
    case 0x5: return "New without a newer value";
    case 0x6: return "Old with a newer value";
    default:  return (code & 0xf0u) == 0x20u ? "alb_import returned an error"
                   : (code & 0xf0u) == 0x30u ? "consumer attach failed"
                   : (code & 0xf0u) == 0x10u ? "producer driver error" : "unknown code";
    }
}

static uint32_t stat(const Vpico_pair &m, int core, int k) { return m.stat_o[core * 4 + k]; }

int main(int argc, char **argv)
{
    uint64_t max_cycles = 20000000;
    std::string report, label = "pico-pair";
    bool expect_fail = false;
    uint64_t seed = 1;
    int stall_core = 1;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--max-cycles") && i + 1 < argc) max_cycles = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--label") && i + 1 < argc) label = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-consumer-failure")) expect_fail = true;
        else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--stall-core") && i + 1 < argc) stall_core = std::atoi(argv[++i]);
        else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vpico_pair m;

    // Every clock low before the first edge (TOOLCHAIN.md), then reset.
    m.clk_i = 0;
    m.rst_i = 1;
    m.stall_i = 0;
    m.eval();
    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 1, stall_left = 0, stalled = 0;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    uint64_t cycle = 0;
    auto tick = [&]() { m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle; };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0;
    uint64_t done_at[2] = {0, 0}, both_left[2] = {0, 0};
    while ((m.done_o & 3u) != 3u && cycle < max_cycles && !(m.trap_o & 3u) && !(m.bus_err_o & 3u)) {
        if (stall_core == 0 || stall_core == 1) {
            if (stall_left == 0 && (next() & 2047u) == 0) stall_left = 1 + next() % 4096u;
            m.stall_i = stall_left ? static_cast<uint8_t>(1u << stall_core) : 0u;
            if (stall_left) { --stall_left; ++stalled; }
        } else if (stall_core == 2) {  // both cores, independent bursts
            uint8_t s = 0;
            for (int c = 0; c < 2; ++c) {
                if (both_left[c] == 0 && (next() & 2047u) == 0) both_left[c] = 1 + next() % 4096u;
                if (both_left[c]) { --both_left[c]; ++stalled; s |= static_cast<uint8_t>(1u << c); }
            }
            m.stall_i = s;
        }
        tick();
        for (int c = 0; c < 2; ++c)
            if (((m.done_o >> c) & 1u) && !done_at[c]) done_at[c] = cycle;
    }
    const uint32_t done = m.done_o & 3u, trap = m.trap_o & 3u, err = m.bus_err_o & 3u;
    const uint32_t code[2] = {static_cast<uint32_t>(m.code_o & 0xffffffffu),
                              static_cast<uint32_t>(m.code_o >> 32)};
    const char *name[2] = {"producer", "consumer"};
    std::printf("%s: seed %llu, %llu cycles (%llu of them stalled on core %d), done %u%u, trap %u%u, "
                "bus error %u%u\n", label.c_str(), static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(cycle), static_cast<unsigned long long>(stalled), stall_core,
                done & 1u, done >> 1, trap & 1u, trap >> 1, err & 1u, err >> 1);
    for (int c = 0; c < 2; ++c)
        if (done >> c & 1u)
            std::printf("  %s: exit code 0x%x (%s) after %llu cycles\n", name[c], code[c],
                        code[c] == 0 ? "pass" : code_text(code[c]), static_cast<unsigned long long>(done_at[c]));

    const char *fail = nullptr;
    static char buf[256];
    if (trap) {
        std::snprintf(buf, sizeof buf, "expected no trap, got a trap on %s", trap & 1u ? name[0] : name[1]);
        fail = buf;
    } else if (err) {
        std::snprintf(buf, sizeof buf, "expected no unmapped access, got one from %s", err & 1u ? name[0] : name[1]);
        fail = buf;
    } else if (done != 3u) {
        std::snprintf(buf, sizeof buf, "expected both cores done within %llu cycles, got %s still running",
                      static_cast<unsigned long long>(max_cycles), done & 1u ? name[1] : name[0]);
        fail = buf;
    } else if (code[0] != 0) {
        std::snprintf(buf, sizeof buf, "expected producer exit code 0, got 0x%x (%s)", code[0], code_text(code[0]));
        fail = buf;
    } else if (!expect_fail && code[1] != 0) {
        std::snprintf(buf, sizeof buf, "expected consumer exit code 0, got 0x%x (%s at sequence %u)", code[1],
                      code_text(code[1]), code[1] >> 8);
        fail = buf;
    } else if (expect_fail && ((code[1] & 0xffu) < 3u || (code[1] & 0xffu) > 6u)) {
        std::snprintf(buf, sizeof buf, "expected the consumer to report a torn or out-of-order value "
                      "(codes 3..6), got 0x%x (%s)", code[1], code_text(code[1]));
        fail = buf;
    }

    JsonReport r;
    r.str("label", label).num("seed", static_cast<double>(seed)).num("cycles", static_cast<double>(cycle))
     .num("stall_core", stall_core).num("stalled_cycles", static_cast<double>(stalled))
     .num("producer_code", code[0]).num("consumer_code", code[1]);
    if (!expect_fail && !fail) {
        const uint32_t exports = stat(m, 0, 1), ex_cyc = stat(m, 0, 2);
        const uint32_t news = stat(m, 1, 0), imports = stat(m, 1, 1), im_cyc = stat(m, 1, 2);
        std::printf("  producer: %u exports, %.1f cycles per alb_export (rdcycle around the call), "
                    "%u instructions, CPI %.2f\n", exports, double(ex_cyc) / exports, stat(m, 0, 3),
                    double(done_at[0]) / stat(m, 0, 3));
        std::printf("  consumer: %u imports, %u New, %.1f cycles per alb_import, %u instructions, CPI %.2f\n",
                    imports, news, double(im_cyc) / imports, stat(m, 1, 3), double(done_at[1]) / stat(m, 1, 3));
        r.num("exports", exports).num("cycles_per_export", double(ex_cyc) / exports)
         .num("producer_instructions", stat(m, 0, 3))
         .num("imports", imports).num("imports_new", news).num("cycles_per_import", double(im_cyc) / imports)
         .num("consumer_instructions", stat(m, 1, 3));
    }
    r.str("verdict", fail ? "fail" : "pass");
    if (!report.empty() && !r.write(report)) return 1;
    if (fail) { std::printf("%s: FAIL: %s\n", label.c_str(), fail); return 1; }
    std::printf("%s: pass%s\n", label.c_str(), expect_fail ? ": the broken driver was caught, as expected" : "");
    return 0;
}
