// test_pico_boards.cpp -- Verilator harness of tb/rtl/pico_boards.v: four
// PicoRV32 boards (radar, odometry, navigation, motor of the MOBOT-III
// example) run firmware/mobot_<board>.c with the compiler-generated channel
// code and the real C driver; albatross_controller copies the channels
// between their DPRAMs by the compiler's schedule ROM.
//
//   test_pico_boards +fw0..3=FILE +ram0..3=FILE +rom=FILE [--max-cycles N]
//                    [--report FILE] [--label NAME] [--seed S] [--stall P]
//
// Stalls: every core's local RAM is held in random bursts (xorshift, seed S;
// each free cycle starts one with probability 1/P, default 2048, lasting
// 1..1024 cycles; --stall 0: none), so the cores drift against the schedule.
// Runs until every core stored to TOHOST, a core traps or touches an
// unmapped address, the controller flags an error, or N cycles pass (then it
// fails, naming the cores still running).  Then it runs 20000 more cycles so
// that a check failing after the report overwrites TOHOST, and asserts every
// exit code is 0 (firmware/mobot_check.h decodes them).  Exit status 0 = pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vpico_boards.h"
#include "verilated.h"
#include "../report.h"

static const int NB = 4;
static const char *const kBoard[NB] = {"radar", "odometry", "navigation", "motor"};
static const char *const kChan[5] = {"RadarMap", "Position", "MotorCmd", "GlobalTime", "Status"};
// STAT k of each board: the channel whose New count it holds (-1: none / exports).
static const int kStatChan[NB][3] = {{1, 3, -1}, {-1, 3, -1}, {0, 1, 3}, {2, 3, -1}};

static std::string code_text(uint32_t code)
{
    static const char *what[8] = {"pass", "alb_import error", "attach error", "checksum wrong",
                                  "sequence number went back", "New without a newer value",
                                  "Old with a newer value", "export error"};
    if (code == 0) return "pass";
    const uint32_t chk = code & 0xfu, id = (code >> 4) & 0xfu, seq = code >> 12;
    char b[160];
    std::snprintf(b, sizeof b, "%s, channel %s, sequence %u", chk < 8 ? what[chk] : "unknown code",
                  id < 5 ? kChan[id] : "-", seq);
    return b;
}

int main(int argc, char **argv)
{
    uint64_t max_cycles = 5000000, seed = 1, stall_p = 2048;
    std::string report, label = "pico-boards";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--max-cycles") && i + 1 < argc) max_cycles = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--label") && i + 1 < argc) label = argv[++i];
        else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--stall") && i + 1 < argc) stall_p = std::strtoull(argv[++i], 0, 0);
        else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vpico_boards m;

    m.clk_i = 0;
    m.rst_i = 1;
    m.stall_i = 0;
    m.eval();
    uint64_t rng = seed * 0x9E3779B97F4A7C15ull + 1, stall_left[NB] = {0, 0, 0, 0}, stalled = 0, busy = 0;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    uint64_t cycle = 0;
    auto tick = [&]() {
        uint32_t st = 0;
        for (int c = 0; c < NB; ++c) {
            if (stall_p && stall_left[c] == 0 && next() % stall_p == 0) stall_left[c] = 1 + next() % 1024u;
            if (stall_left[c]) { --stall_left[c]; st |= 1u << c; ++stalled; }
        }
        m.stall_i = st;
        busy += m.m_cyc_o;
        m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle;
    };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0; busy = 0; stalled = 0;
    const uint32_t all = (1u << NB) - 1u;
    uint64_t done_at[NB] = {0, 0, 0, 0};
    auto bad = [&]() { return (m.trap_o & all) || (m.bus_err_o & all) || m.error_o; };
    while ((m.done_o & all) != all && cycle < max_cycles && !bad()) {
        tick();
        for (int c = 0; c < NB; ++c)
            if (((m.done_o >> c) & 1u) && !done_at[c]) done_at[c] = cycle;
    }
    const uint64_t all_done = cycle;
    // Keep running: a check that fails after a core reported overwrites TOHOST.
    for (int i = 0; i < 20000 && (m.done_o & all) == all && !bad(); ++i) tick();

    const uint32_t done = m.done_o & all, trap = m.trap_o & all, err = m.bus_err_o & all;
    uint32_t code[NB], stat[NB][4];
    for (int c = 0; c < NB; ++c) {
        code[c] = m.code_o[c];
        for (int k = 0; k < 4; ++k) stat[c][k] = m.stat_o[c * 4 + k];
    }
    std::printf("%s: seed %llu, %llu cycles to all done (+%llu after), %llu core cycles stalled, "
                "controller time %u, rom errors %u, bus busy %.1f %%\n", label.c_str(),
                static_cast<unsigned long long>(seed), static_cast<unsigned long long>(all_done),
                static_cast<unsigned long long>(cycle - all_done), static_cast<unsigned long long>(stalled),
                m.time_o, m.rom_errors_o, cycle ? 100.0 * double(busy) / double(cycle) : 0.0);
    JsonReport r;
    r.str("label", label).num("seed", static_cast<double>(seed)).num("cycles_all_done", static_cast<double>(all_done))
     .num("cycles", static_cast<double>(cycle)).num("stalled_core_cycles", static_cast<double>(stalled))
     .num("bus_busy_fraction", cycle ? double(busy) / double(cycle) : 0.0);
    for (int c = 0; c < NB; ++c) {
        std::string line;
        char b[96];
        for (int k = 0; k < 3; ++k)
            if (kStatChan[c][k] >= 0) {
                std::snprintf(b, sizeof b, ", %u New %s", stat[c][k], kChan[kStatChan[c][k]]);
                line += b;
                r.num((std::string(kBoard[c]) + "_new_" + kChan[kStatChan[c][k]]).c_str(), stat[c][k]);
            }
        if (c != 3) {
            std::snprintf(b, sizeof b, ", %u exports", stat[c][3]);
            line += b;
            r.num((std::string(kBoard[c]) + "_exports").c_str(), stat[c][3]);
        }
        std::printf("  board %d %-10s %s at cycle %llu, exit code 0x%x (%s)%s\n", c, kBoard[c],
                    (done >> c & 1u) ? "done" : "RUNNING", static_cast<unsigned long long>(done_at[c]), code[c],
                    code_text(code[c]).c_str(), line.c_str());
        r.num((std::string(kBoard[c]) + "_done_cycle").c_str(), static_cast<double>(done_at[c]))
         .num((std::string(kBoard[c]) + "_code").c_str(), code[c]);
    }

    std::string fail;
    char buf[256];
    for (int c = 0; c < NB && fail.empty(); ++c) {
        if (trap >> c & 1u) fail = std::string("expected no trap, got a trap on ") + kBoard[c];
        else if (err >> c & 1u) fail = std::string("expected no unmapped access, got one from ") + kBoard[c];
    }
    if (fail.empty() && m.error_o) {
        std::snprintf(buf, sizeof buf, "expected no controller error, got error_o with %u rom errors", m.rom_errors_o);
        fail = buf;
    }
    if (fail.empty() && done != all) {
        std::string running;
        for (int c = 0; c < NB; ++c)
            if (!(done >> c & 1u)) running += std::string(running.empty() ? "" : ", ") + kBoard[c];
        std::snprintf(buf, sizeof buf, "expected every core done within %llu cycles, got %s still running",
                      static_cast<unsigned long long>(max_cycles), running.c_str());
        fail = buf;
    }
    for (int c = 0; c < NB && fail.empty(); ++c)
        if (code[c] != 0) {
            std::snprintf(buf, sizeof buf, "expected %s exit code 0, got 0x%x (%s)", kBoard[c], code[c],
                          code_text(code[c]).c_str());
            fail = buf;
        }
    r.str("verdict", fail.empty() ? "pass" : "fail");
    if (!report.empty() && !r.write(report)) return 1;
    if (!fail.empty()) { std::printf("%s: FAIL: %s\n", label.c_str(), fail.c_str()); return 1; }
    std::printf("%s: pass\n", label.c_str());
    return 0;
}
