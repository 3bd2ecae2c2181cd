// test_fpga_soc.cpp -- Verilator harness of fpga/icebreaker_top.v: the FPGA
// demonstration as it runs on the board, with its block-RAM images
// (build/fpga/duo/) and its power-on reset, the button released.
//
//   test_fpga_soc [--cycles N] [--report FILE] [--expect-error]
//
// Watches the LEDs for N clocks (default 30,000,000, 2.5 s at 12 MHz) and
// passes when both heartbeats (LED1: sensor, every 256 Exports; LED2:
// actuator, every 256 New Imports) changed at least twice, neither core
// stopped (LED3, LED4), the controller flagged no error (LED5) and the red
// LED never lit.  --expect-error (negative test: a model built with a
// corrupted image) inverts the verdict: it passes only if the red LED lit.
// Exit status 0 = pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "Vicebreaker_top.h"
#include "verilated.h"
#include "../report.h"

int main(int argc, char **argv)
{
    uint64_t cycles = 30000000;
    std::string report;
    bool expect_error = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--cycles") && i + 1 < argc) cycles = std::strtoull(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-error")) expect_error = true;
        else { std::fprintf(stderr, "usage: test_fpga_soc [--cycles N] [--report FILE] [--expect-error]\n"); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vicebreaker_top m;
    m.clk_i = 0;
    m.btn_n_i = 1;
    m.eval();
    uint64_t toggles[2] = {0, 0}, red_at = 0, stop_at = 0, first_beat[2] = {0, 0};
    unsigned prev = m.led_o;
    for (uint64_t c = 1; c <= cycles; ++c) {
        m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval();
        const unsigned led = m.led_o;
        for (int b = 0; b < 2; ++b)
            if (((led ^ prev) >> b) & 1u) {
                if (!toggles[b]) first_beat[b] = c;
                ++toggles[b];
            }
        if (!m.led_r_n_o && !red_at) red_at = c;
        if ((led & 0x1cu) && !stop_at) stop_at = c;
        prev = led;
        if (c % (cycles / 10) == 0)
            std::printf("  [%3llu%%] cycle %llu: heartbeat changes sensor %llu, actuator %llu, LEDs %02x\n",
                        (unsigned long long)(100 * c / cycles), (unsigned long long)c,
                        (unsigned long long)toggles[0], (unsigned long long)toggles[1], led);
    }
    std::string fail;
    char b[256];
    if (red_at) {
        std::snprintf(b, sizeof b, "expected the red LED off, it lit at cycle %llu (LEDs %02x)",
                      (unsigned long long)red_at, (unsigned)m.led_o);
        fail = b;
    } else if (stop_at) {
        std::snprintf(b, sizeof b, "expected no core stopped and no controller error, LED3..5 lit at cycle %llu "
                      "(LEDs %02x)", (unsigned long long)stop_at, (unsigned)m.led_o);
        fail = b;
    } else if (toggles[0] < 2 || toggles[1] < 2) {
        std::snprintf(b, sizeof b, "expected both heartbeats to change at least twice in %llu cycles, got "
                      "sensor %llu, actuator %llu", (unsigned long long)cycles, (unsigned long long)toggles[0],
                      (unsigned long long)toggles[1]);
        fail = b;
    }
    if (expect_error) {
        if (red_at) {
            std::printf("fpga-soc: pass: negative test: the red LED lit at cycle %llu, as expected (LEDs %02x)\n",
                        (unsigned long long)red_at, (unsigned)m.led_o);
            return 0;
        }
        std::printf("fpga-soc: FAIL: negative test: expected the red LED to light, it did not (%s)\n",
                    fail.empty() ? "the run looked healthy" : fail.c_str());
        return 1;
    }
    JsonReport r;
    r.num("cycles", double(cycles)).num("sensor_heartbeat_changes", double(toggles[0]))
     .num("actuator_heartbeat_changes", double(toggles[1])).num("sensor_first_change", double(first_beat[0]))
     .num("actuator_first_change", double(first_beat[1])).str("verdict", fail.empty() ? "pass" : "fail");
    if (!report.empty() && !r.write(report)) return 1;
    if (!fail.empty()) { std::printf("fpga-soc: FAIL: %s\n", fail.c_str()); return 1; }
    std::printf("fpga-soc: pass (heartbeat changes: sensor %llu, actuator %llu in %llu cycles)\n",
                (unsigned long long)toggles[0], (unsigned long long)toggles[1], (unsigned long long)cycles);
    return 0;
}
