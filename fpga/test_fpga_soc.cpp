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
//   test_fpga_soc [--cycles N] [--report FILE] [--expect-error | --expect-fail TEXT[|TEXT...]]
//                 [--gt-base W --gt-words Wd [--import-bound B] [--watchdog N]]
//                 [+rom=FILE] [+pll_drift=SEED]
//
// The sensor imports GlobalTime after every Export (a four-slot channel,
// fpga/firmware/duo_sensor.c).  The harness counts the accesses of its core
// to that channel's instance at the sensor's DPRAM port A (duo_system's
// public mon_*; --gt-base W, the instance's first word, --gt-words Wd, the
// payload words with taken_at): an Import ends with the load of the last
// payload word of a buffer, so the accesses since the previous such load are
// that Import's (the first Import's count also holds the set-up's loads of
// the control word: it is reported, not checked).  The run fails if one Import took more than B accesses
// (--import-bound, the bound of the generated sensor.h; 0 = not checked), if
// no Import ended for N clocks (--watchdog, default 1,000,000: an Import
// overtaken without end) or if none ended.  Imports done and the most
// accesses of one go to the report.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
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
#include "Vulx3s_top___024root.h"
#define DUO(sig) (m.rootp->ulx3s_top__DOT__u_duo__DOT__##sig)
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
#include "Varty_top___024root.h"
#define DUO(sig) (m.rootp->arty_top__DOT__u_duo__DOT__##sig)
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
#include "Vicebreaker_top___024root.h"
#define DUO(sig) (m.rootp->icebreaker_top__DOT__u_duo__DOT__##sig)
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
    uint64_t bound = 0, watchdog = 1000000;
    uint32_t gt_base = 0, gt_words = 0;    // 0 words: no GlobalTime checks
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--cycles") && i + 1 < argc) cycles = std::strtoull(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--expect-error")) expect_error = true;
        else if (!std::strcmp(argv[i], "--expect-fail") && i + 1 < argc) expect_fail = argv[++i];
        else if (!std::strcmp(argv[i], "--import-bound") && i + 1 < argc) bound = std::strtoull(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--watchdog") && i + 1 < argc) watchdog = std::strtoull(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--gt-base") && i + 1 < argc) gt_base = std::strtoul(argv[++i], nullptr, 0);
        else if (!std::strcmp(argv[i], "--gt-words") && i + 1 < argc) gt_words = std::strtoul(argv[++i], nullptr, 0);
        else if (argv[i][0] == '+') continue;                 // a plusarg for the model
        else {
            std::fprintf(stderr, "usage: test_fpga_soc [--cycles N] [--report FILE] [--expect-error | "
                         "--expect-fail TEXT] [--gt-base W --gt-words Wd [--import-bound B] [--watchdog N]] "
                         "[+rom=FILE] [+pll_drift=SEED]\n");
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
    // The sensor's GlobalTime Imports: done, the accesses of the current one,
    // the most of one; the last cycle one ended, the longest wait for the next.
    uint64_t gt_done = 0, gt_acc = 0, gt_worst = 0, gt_changed = 0, gt_longest = 0, starved_at = 0;
    uint64_t gt_first = 0, gt_worst_at = 0;
    const uint32_t gt_end = gt_base + 1 + 4 * gt_words;   // four buffers (three: a subset)
    // One DPRAM clock cycle's port-A access of the sensor, sampled once per
    // cycle at the DPRAM clock's falling edge (on the ULX3S that clock is not
    // the one driven here).
    bool mon_clk_was = false;
    auto watch = [&](uint64_t c) {
        const bool clk = DUO(mon_clk) != 0;
        const bool fall = mon_clk_was && !clk;
        mon_clk_was = clk;
        if (!gt_words || !fall || !(DUO(mon_ack) & 1u)) return;   // board 0 = sensor, port A
        const uint32_t a = DUO(mon_adr) & 0xffu;                  // ADDR_WIDTH 8
        if (a < gt_base || a >= gt_end) return;
        ++gt_acc;
        const uint32_t off = a - gt_base - 1;                     // word in the buffers
        if (a > gt_base && !(DUO(mon_we) & 1u) && off % gt_words == gt_words - 1) {
            if (gt_done == 0) gt_first = gt_acc;                  // with the set-up's loads
            else if (gt_acc > gt_worst) gt_worst = gt_acc, gt_worst_at = gt_done + 1;
            gt_longest = std::max(gt_longest, c - gt_changed);
            ++gt_done, gt_acc = 0, gt_changed = c;
        }
    };
    Leds prev = decode(m);
    for (uint64_t c = 1; c <= cycles; ++c) {
        m.clk_i = 1; m.eval(); watch(c);
        m.clk_i = 0; m.eval(); watch(c);
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
        // A negative test stops once its verdict is settled: the pins' failure
        // is then the message (no error or stop before it, both heartbeats
        // seen twice), and nothing later can turn it into a pass.
        if (!expect_fail.empty() && pins_at && !error_at && !stop_at && toggles[0] >= 2 && toggles[1] >= 2 &&
            !gt_words) {
            std::printf("  cycle %llu: the pins' failure is settled; the negative test stops here\n",
                        (unsigned long long)c);
            cycles = c;
            break;
        }
        if (gt_words && !starved_at && watchdog && c - gt_changed > watchdog) starved_at = c;
        if (c % (cycles / 10) == 0)
            std::printf("  [%3llu%%] cycle %llu: heartbeat changes sensor %llu, actuator %llu, LEDs %02x\n",
                        (unsigned long long)(100 * c / cycles), (unsigned long long)c,
                        (unsigned long long)toggles[0], (unsigned long long)toggles[1], now.raw);
    }
    std::string fail;
    char b[320];
    if (gt_words && bound && gt_worst > bound) {
        std::snprintf(b, sizeof b, "the sensor's GlobalTime Import exceeded its bound: %llu accesses in one Import, "
                      "the bound is %llu (Import %llu of %llu)", (unsigned long long)gt_worst,
                      (unsigned long long)bound, (unsigned long long)gt_worst_at, (unsigned long long)gt_done);
        fail = b;
    }
    std::string gt_fail;
    if (starved_at) {
        std::snprintf(b, sizeof b, "the sensor's GlobalTime Import starved: no Import ended for %llu cycles "
                      "(cycle %llu to %llu; %llu Imports done, %llu accesses into the one running; the watchdog "
                      "is %llu)", (unsigned long long)(starved_at - gt_changed), (unsigned long long)gt_changed,
                      (unsigned long long)starved_at, (unsigned long long)gt_done, (unsigned long long)gt_acc,
                      (unsigned long long)watchdog);
        gt_fail = b;
    } else if (gt_words && gt_done == 0) {
        gt_fail = "expected the sensor to finish GlobalTime Imports, it finished none";
    }
    if (!fail.empty()) {
        // an Import over its bound: that is the message
    } else if (error_at) {
        const uint64_t code = DUO(code);
        std::snprintf(b, sizeof b, "expected the error LED off, it lit at cycle %llu (LEDs %02x; exit codes "
                      "sensor %#x, actuator %#x)", (unsigned long long)error_at, prev.raw,
                      unsigned(code & 0xffffffffu), unsigned(code >> 32));
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
    if (!gt_fail.empty()) fail = fail.empty() ? gt_fail : fail + "; " + gt_fail;
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
        // TEXT may list alternatives separated by '|': any one of them counts.
        bool said = false;
        for (size_t at = 0; !fail.empty() && at <= expect_fail.size();) {
            const size_t bar = std::min(expect_fail.find('|', at), expect_fail.size());
            said = said || fail.find(expect_fail.substr(at, bar - at)) != std::string::npos;
            at = bar + 1;
        }
        if (said) {
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
     .num("actuator_first_change", double(first_beat[1]))
     .num("sensor_globaltime_imports", double(gt_done)).num("sensor_globaltime_worst_accesses", double(gt_worst))
     .num("sensor_globaltime_bound_accesses", double(bound))
     .num("sensor_globaltime_first_accesses_with_setup", double(gt_first))
     .num("sensor_globaltime_longest_gap_cycles", double(gt_longest))
     .str("verdict", fail.empty() ? "pass" : "fail");
    if (!report.empty() && !r.write(report)) return 1;
    if (!fail.empty()) { std::printf("fpga-soc: FAIL: %s: %s\n", kTop, fail.c_str()); return 1; }
    std::printf("fpga-soc: pass: %s (heartbeat changes: sensor %llu, actuator %llu in %llu cycles; sensor "
                "GlobalTime Imports %llu, worst %llu accesses per Import, bound %llu)\n", kTop,
                (unsigned long long)toggles[0], (unsigned long long)toggles[1], (unsigned long long)cycles,
                (unsigned long long)gt_done, (unsigned long long)gt_worst, (unsigned long long)bound);
    return 0;
}
