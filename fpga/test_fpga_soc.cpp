// test_fpga_soc.cpp -- Verilator harness of a board top (fpga/*_top.v): the
// FPGA demonstration as it runs on the board, with its block-RAM images
// (build/fpga/duo/), its power-on reset and the reset button released.  The
// top is chosen when the model is built: -DTOP_ICEBREAKER (default),
// -DTOP_ULX3S or -DTOP_ARTY; each top's LEDs are decoded below as the
// top's comment says.  The ULX3S top's PLL is fpga/EHXPLLL.v: the clock
// this harness drives is its 50 MHz CPU clock, and its 25 MHz bus clock
// runs at half that rate, as on the board, or with +pll_drift=SEED wanders
// unrelated to it (see that file); N below counts CPU clocks.
//
//   test_fpga_soc [--cycles N] [--report FILE] [--expect-error | --expect-fail TEXT]
//                 [+rom=FILE] [+pll_drift=SEED]
//
// Watches the LEDs for N clocks (default 30,000,000) and passes when both
// heartbeats (the sensor's, every 256 Exports; the actuator's, every 256 New
// Imports) changed at least twice, no core stopped and the controller
// flagged no error, the error LED never lit, and the top's other pins are
// right (iCEBreaker: the green LED always follows the actuator's
// heartbeat; ULX3S: wifi_gpio0 is always high, the reset LED off at the
// end; Arty: the RGB LED is never green and red at once, and green at the
// end).  --expect-error (negative test: run with a corrupted
// image, for example +rom=FILE, which the controller's simulation model
// reads instead of ROM_FILE) inverts the verdict: it passes only if the
// error LED lit.  --expect-fail TEXT (negative test of the checks: a model
// of a broken top) passes only if the run fails with a message that
// contains TEXT.  Exit status 0 = pass, 1 = fail, 2 = usage.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "verilated.h"
#include "report.h"

// What every top shows, decoded from its pins.
struct Leds {
    unsigned beat;   // bit b: board b's heartbeat LED
    bool stopped;    // a core stopped, or the controller flagged an error
    bool error;      // the error LED
    unsigned raw;    // the LED pins, for messages
};

#if defined(TOP_ULX3S)
#include "Vulx3s_top.h"
typedef Vulx3s_top Top;
static const char *const kTop = "ulx3s_top";
// led = {rst, ctrl_err, |trap, |err, done[1], done[0], beat[1], beat[0]}
static Leds decode(const Top &m) { unsigned l = m.led_o; return {l & 3u, (l & 0x4cu) != 0, (l & 0x70u) != 0, l}; }
static std::string pins(const Top &m, bool end)
{
    if (m.wifi_gpio0_o != 1) return "expected wifi_gpio0 high (the ESP32 must leave the FPGA alone), it is low";
    if (end && (m.led_o & 0x80u)) return "expected the reset LED (led[7]) off after reset, it is on";
    return "";
}
#elif defined(TOP_ARTY)
#include "Varty_top.h"
typedef Varty_top Top;
static const char *const kTop = "arty_top";
// led = {done[1], done[0], beat[1], beat[0]}; RGB LD0 red = error, green = running
static Leds decode(const Top &m) { unsigned l = m.led_o; return {l & 3u, (l & 0xcu) != 0, m.led0_r_o != 0, l}; }
static std::string pins(const Top &m, bool end)
{
    if (m.led0_g_o && m.led0_r_o) return "expected the RGB LED green or red, it is both";
    if (end && m.led0_g_o != 1) return "expected the RGB LED green (running) at the end, it is not";
    return "";
}
#else
#include "Vicebreaker_top.h"
typedef Vicebreaker_top Top;
static const char *const kTop = "icebreaker_top";
// led = {ctrl_err, done[1], done[0], beat[1], beat[0]}; LEDR_N error, LEDG_N actuator heartbeat
static Leds decode(const Top &m) { unsigned l = m.led_o; return {l & 3u, (l & 0x1cu) != 0, m.led_r_n_o == 0, l}; }
static std::string pins(const Top &m, bool)
{
    if (m.led_g_n_o != ((m.led_o >> 1) & 1u ? 0 : 1))
        return "expected the green LED (active low) to show the actuator's heartbeat, it does not";
    return "";
}
#endif

int main(int argc, char **argv)
{
    uint64_t cycles = 30000000;
    std::string report;
    bool expect_error = false;
    std::string expect_fail;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--cycles") && i + 1 < argc) cycles = std::strtoull(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-error")) expect_error = true;
        else if (!std::strcmp(argv[i], "--expect-fail") && i + 1 < argc) expect_fail = argv[++i];
        else if (argv[i][0] == '+') continue;                 // a plusarg for the model
        else {
            std::fprintf(stderr, "usage: test_fpga_soc [--cycles N] [--report FILE] [--expect-error | "
                         "--expect-fail TEXT] [+rom=FILE] [+pll_drift=SEED]\n");
            return 2;
        }
    }
    if (cycles < 10) { std::fprintf(stderr, "test_fpga_soc: --cycles must be at least 10\n"); return 2; }
    Verilated::commandArgs(argc, argv);
    Top m;
    m.clk_i = 0;
    m.btn_n_i = 1;
    m.eval();
    uint64_t toggles[2] = {0, 0}, error_at = 0, stop_at = 0, pins_at = 0, first_beat[2] = {0, 0};
    std::string pins_fail;
    Leds prev = decode(m);
    for (uint64_t c = 1; c <= cycles; ++c) {
        m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval();
        const Leds now = decode(m);
        for (int b = 0; b < 2; ++b)
            if (((now.beat ^ prev.beat) >> b) & 1u) {
                if (!toggles[b]) first_beat[b] = c;
                ++toggles[b];
            }
        if (now.error && !error_at) error_at = c;
        if (now.stopped && !stop_at) stop_at = c;
        if (!pins_at && !(pins_fail = pins(m, false)).empty()) pins_at = c;
        prev = now;
        if (c % (cycles / 10) == 0)
            std::printf("  [%3llu%%] cycle %llu: heartbeat changes sensor %llu, actuator %llu, LEDs %02x\n",
                        (unsigned long long)(100 * c / cycles), (unsigned long long)c,
                        (unsigned long long)toggles[0], (unsigned long long)toggles[1], now.raw);
    }
    std::string fail;
    char b[256];
    if (error_at) {
        std::snprintf(b, sizeof b, "expected the error LED off, it lit at cycle %llu (LEDs %02x)",
                      (unsigned long long)error_at, prev.raw);
        fail = b;
    } else if (stop_at) {
        std::snprintf(b, sizeof b, "expected no core stopped and no controller error, their LEDs lit at cycle %llu "
                      "(LEDs %02x)", (unsigned long long)stop_at, prev.raw);
        fail = b;
    } else if (toggles[0] < 2 || toggles[1] < 2) {
        std::snprintf(b, sizeof b, "expected both heartbeats to change at least twice in %llu cycles, got "
                      "sensor %llu, actuator %llu", (unsigned long long)cycles, (unsigned long long)toggles[0],
                      (unsigned long long)toggles[1]);
        fail = b;
    } else if (pins_at) {
        std::snprintf(b, sizeof b, " (from cycle %llu)", (unsigned long long)pins_at);
        fail = pins_fail + b;
    } else {
        fail = pins(m, true);
    }
    if (expect_error) {
        if (error_at) {
            std::printf("fpga-soc: pass: %s negative test: the error LED lit at cycle %llu, as expected (LEDs %02x)\n",
                        kTop, (unsigned long long)error_at, prev.raw);
            return 0;
        }
        std::printf("fpga-soc: FAIL: %s negative test: expected the error LED to light, it did not (%s)\n",
                    kTop, fail.empty() ? "the run looked healthy" : fail.c_str());
        return 1;
    }
    if (!expect_fail.empty()) {
        if (!fail.empty() && fail.find(expect_fail) != std::string::npos) {
            std::printf("fpga-soc: pass: %s negative test: caught, as expected: %s\n", kTop, fail.c_str());
            return 0;
        }
        std::printf("fpga-soc: FAIL: %s negative test: expected a failure that says \"%s\", got %s\n", kTop,
                    expect_fail.c_str(), fail.empty() ? "a pass" : fail.c_str());
        return 1;
    }
    JsonReport r;
    r.str("top", kTop).num("cycles", double(cycles)).num("sensor_heartbeat_changes", double(toggles[0]))
     .num("actuator_heartbeat_changes", double(toggles[1])).num("sensor_first_change", double(first_beat[0]))
     .num("actuator_first_change", double(first_beat[1])).str("verdict", fail.empty() ? "pass" : "fail");
    if (!report.empty() && !r.write(report)) return 1;
    if (!fail.empty()) { std::printf("fpga-soc: FAIL: %s: %s\n", kTop, fail.c_str()); return 1; }
    std::printf("fpga-soc: pass: %s (heartbeat changes: sensor %llu, actuator %llu in %llu cycles)\n", kTop,
                (unsigned long long)toggles[0], (unsigned long long)toggles[1], (unsigned long long)cycles);
    return 0;
}
