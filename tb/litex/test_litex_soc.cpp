// test_litex_soc.cpp -- Verilator harness of the LiteX test SoC
// (tools/litex/albatross_soc.py: LiteX's VexRiscv with caches, the DPRAM as
// an uncached Wishbone slave, its port B and a TOHOST CSR as pads).  The SoC
// runs tb/litex/firmware/litex_pair.c (the real driver, on the channels of
// the generated albatross_channels.h) from its ROM.  Run it in the folder of
// sim.v (LiteX's $readmemh paths are relative).  The clock is driven from
// here (no --timing).
//
//   test_litex_soc [--max-cycles N] [--values N] [--report FILE]
//
// Runs until the program stores to TOHOST or N cycles pass (the watchdog).
// Passes if the exit code is 0 and, read through the DPRAM's other port
// (port B, Wishbone driven from here), the three-buffer channel holds the
// last value exported: its Actual names a buffer whose four words are the
// pair value of seq --values (whole: check words match).
// Exit status 0 = verdict pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vsim.h"
#include "verilated.h"
#include "report.h"
extern "C" {
#include "albatross.h"
}
#include "generated/albatross_channels.h"

int main(int argc, char **argv)
{
    uint64_t max_cycles = 2000000, values = 200;
    std::string report;
    for (int i = 1; i < argc; ++i) {
        const bool more = i + 1 < argc;
        if (!std::strcmp(argv[i], "--max-cycles") && more) max_cycles = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--values") && more) values = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--report") && more) report = argv[++i];
        else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vsim m;
    m.sys_clk = 0;
    m.sim_trace = 0;
    m.albatross_b_cyc = m.albatross_b_stb = m.albatross_b_we = 0;
    m.albatross_b_adr = 0;
    m.albatross_b_sel = 0;
    m.albatross_b_dat_w = 0;
    m.eval();                        // every clock low before the first edge
    uint64_t cycle = 0;
    auto tick = [&]() { m.sys_clk = 1; m.eval(); m.sys_clk = 0; m.eval(); ++cycle; };
    while (!m.tohost_done && cycle < max_cycles) tick();
    const uint64_t done_at = cycle;

    // Port B: one Wishbone classic read, held until ack (at most 8 clocks).
    auto read_b = [&](uint32_t byte_off, bool &ok) {
        m.albatross_b_adr = (byte_off / 4u) & 0x3ffu;
        m.albatross_b_sel = 0xf;
        m.albatross_b_cyc = m.albatross_b_stb = 1;
        uint32_t v = 0;
        ok = false;
        for (int i = 0; i < 8 && !ok; ++i) {
            tick();
            if (m.albatross_b_ack) { v = m.albatross_b_dat_r; ok = true; }
        }
        m.albatross_b_cyc = m.albatross_b_stb = 0;
        tick();
        return v;
    };

    const char *fail = nullptr;
    static char buf[256];
    uint32_t w[4] = {}, actual = 0;
    if (!m.tohost_done) {
        std::snprintf(buf, sizeof buf, "expected the program to store to TOHOST within %llu cycles (watchdog)",
                      static_cast<unsigned long long>(max_cycles));
        fail = buf;
    } else if (m.tohost_code != 0) {
        std::snprintf(buf, sizeof buf, "expected exit code 0, got 0x%x (0x1k driver error, 0x2k wrong value, "
                      "channel k)", m.tohost_code);
        fail = buf;
    } else {
        bool ok = true, all = true;
        const uint32_t ctl = read_b(ALBATROSS_PAIR_OFFSET, ok);
        all = all && ok;
        actual = (ctl >> (8 * ALB_OFF_ACTUAL)) & 0xffu;
        if (all && ALB_VALID_INDEX(actual))
            for (uint32_t i = 0; i < 4; ++i) {
                w[i] = read_b(ALBATROSS_PAIR_OFFSET + ALB_OFF_BUFFER(actual, ALBATROSS_PAIR_BYTES) + 4u * i, ok);
                all = all && ok;
            }
        auto mix = [](uint32_t x) { x ^= x << 13; x ^= x >> 17; x ^= x << 5; return x + 0x9E3779B9u; };
        if (!all) {
            fail = "expected port B to acknowledge every read within 8 clocks";
        } else if (!ALB_VALID_INDEX(actual)) {
            std::snprintf(buf, sizeof buf, "expected a valid Actual through port B, got control word 0x%08x", ctl);
            fail = buf;
        } else if (w[0] != values || w[1] != mix(w[0]) || w[2] != mix(w[1]) ||
                   w[3] != (w[0] ^ w[1] ^ w[2] ^ 0x5A5A5A5Au)) {
            std::snprintf(buf, sizeof buf, "expected the whole value of seq %llu through port B, got %08x %08x "
                          "%08x %08x", static_cast<unsigned long long>(values), w[0], w[1], w[2], w[3]);
            fail = buf;
        }
    }
    std::printf("litex-soc: %llu cycles to TOHOST, exit code 0x%x; port B: Actual %u, value seq %u\n",
                static_cast<unsigned long long>(done_at), m.tohost_code, actual, w[0]);
    JsonReport r;
    r.str("label", "litex-soc").num("cycles", static_cast<double>(done_at)).num("exit_code", m.tohost_code)
     .num("values_per_channel", static_cast<double>(values)).num("port_b_seq", w[0])
     .str("verdict", fail ? "fail" : "pass");
    if (!report.empty() && !r.write(report)) return 1;
    if (fail) { std::printf("litex-soc: FAIL: %s\n", fail); return 1; }
    std::printf("litex-soc: pass\n");
    return 0;
}
