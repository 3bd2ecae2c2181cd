// bench_pico.cpp -- Verilator harness of tb/pico/pico_bench.v: one PicoRV32
// core runs tb/pico/firmware/bench.c (the real driver) against an albatross_dpram
// whose other port is idle, and reports cycles per call as board EVENTs
// (key = size << 16 | metric << 8 | field, ARG = the figure; see bench.c).
//
//   bench_pico +fw0=BENCH.hex [--max-cycles N] [--report FILE] [--label L] [--cpu TEXT] [--kind K]
//
// Prints the table (cycles per call, means over the calls; the rdcycle pair
// already subtracted on the core) and writes the JSON report with the exact
// integer sums, minima and maxima.  Fails if the core traps, touches an
// unmapped address, exits with a code other than 0, does not finish within N
// cycles, or a figure is missing.  Exit status 0 = pass.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include "Vpico_bench.h"
#include "verilated.h"
#include "report.h"

static const uint32_t SIZES[] = {4, 16, 64, 256};
static const char *METRIC[] = {"export", "import_new", "import_old", "copy_to_dpram", "copy_from_dpram"};
static const char *FIELD[] = {"sum", "min", "max"};
static const uint32_t K_OVERHEAD = 0xFFFF0000u, K_REPS = 0xFFFF0001u;

int main(int argc, char **argv)
{
    uint64_t max_cycles = 5000000;
    std::string report, label = "bench-pico", cpu = "PicoRV32 rv32i (tb/pico/pico_bench.v), firmware -Os",
                kind = "three_buffer";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--max-cycles") && i + 1 < argc) max_cycles = std::strtoull(argv[++i], 0, 0);
        else if (!std::strcmp(argv[i], "--report") && i + 1 < argc) report = argv[++i];
        else if (!std::strcmp(argv[i], "--label") && i + 1 < argc) label = argv[++i];
        else if (!std::strcmp(argv[i], "--cpu") && i + 1 < argc) cpu = argv[++i];
        else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind = argv[++i];
        else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return 2; }
    }
    Verilated::commandArgs(argc, argv);
    Vpico_bench m;

    // Every clock low before the first edge (TOOLCHAIN.md), then reset.
    m.clk_i = 0;
    m.rst_i = 1;
    m.eval();
    uint64_t cycle = 0;
    std::map<uint32_t, uint32_t> ev;
    auto tick = [&]() {
        m.clk_i = 1; m.eval(); m.clk_i = 0; m.eval(); ++cycle;
        if (m.ev_valid_o) ev[m.ev_data_o] = m.ev_arg_o;
    };
    for (int i = 0; i < 8; ++i) tick();
    m.rst_i = 0;
    cycle = 0;
    while (!m.done_o && !m.trap_o && !m.bus_err_o && cycle < max_cycles) tick();

    const char *fail = nullptr;
    static char buf[256];
    if (m.trap_o) fail = "expected no trap, the core trapped";
    else if (m.bus_err_o) fail = "expected no unmapped access, the core made one";
    else if (!m.done_o) {
        std::snprintf(buf, sizeof buf, "expected the bench to finish within %llu cycles",
                      static_cast<unsigned long long>(max_cycles));
        fail = buf;
    } else if (m.code_o != 0) {
        std::snprintf(buf, sizeof buf, "expected exit code 0, got 0x%x (0x4k: driver error, 0x5k: wrong "
                      "imported value, at size index k)", m.code_o);
        fail = buf;
    }
    auto key = [](uint32_t size, int metric, int field) { return size << 16 | uint32_t(metric) << 8 | uint32_t(field); };
    if (!fail) {
        const uint32_t need[] = {K_OVERHEAD, K_REPS};
        for (uint32_t k : need) if (!ev.count(k)) fail = "expected the overhead and call-count events, got none";
        for (uint32_t s : SIZES)
            for (int mt = 0; mt < 5; ++mt)
                for (int f = 0; f < 3; ++f)
                    if (!ev.count(key(s, mt, f))) fail = "expected every figure as an event, one is missing";
    }
    if (fail) {
        std::printf("bench-pico: %llu cycles, FAIL: %s\n", static_cast<unsigned long long>(cycle), fail);
        return 1;
    }

    const uint32_t reps = ev[K_REPS];
    auto mean = [&](uint32_t s, int mt) { return double(ev[key(s, mt, 0)]) / reps; };
    std::printf("%s: %s, undisturbed DPRAM port, %u calls per figure, cycle-counter pair (%u cycles) "
                "subtracted; mean cycles per call\n", label.c_str(), cpu.c_str(), reps, ev[K_OVERHEAD]);
    std::printf("  %5s %8s %10s %10s %8s %8s %10s %10s\n", "bytes", "export", "import-new", "import-old",
                "copy-to", "copy-fr", "exp/copy", "imp/copy");
    std::string sizes = "[";
    for (uint32_t s : SIZES) {
        const double ex = mean(s, 0), in = mean(s, 1), io = mean(s, 2), ct = mean(s, 3), cf = mean(s, 4);
        std::printf("  %5u %8.1f %10.1f %10.1f %8.1f %8.1f %10.3f %10.3f\n", s, ex, in, io, ct, cf, ex / ct, in / cf);
        JsonReport e;
        e.num("bytes", s);
        for (int mt = 0; mt < 5; ++mt) {
            JsonReport f;
            for (int fl = 0; fl < 3; ++fl) f.num(FIELD[fl], ev[key(s, mt, fl)]);
            f.num("mean", mean(s, mt));
            std::string t = f.text();
            e.raw(METRIC[mt], t.substr(0, t.size() - 1));
        }
        e.num("export_over_copy", ex / ct).num("import_new_over_copy", in / cf)
         .num("import_old_over_copy", io / cf)
         .num("export_minus_copy", ex - ct).num("import_new_minus_copy", in - cf)
         .num("import_old_minus_copy", io - cf);
        std::string t = e.text();
        sizes += (sizes.size() > 1 ? ", " : "") + t.substr(0, t.size() - 1);
    }
    sizes += "]";
    // Per-word cost (slope from 4 to 256 bytes) and the fixed part of each call.
    const uint32_t lo = SIZES[0], hi = SIZES[3];
    const double words = (hi - lo) / 4.0;
    JsonReport slope;
    std::printf("  per payload word (slope 4..256 B) and fixed part (at 4 B, less one word):\n");
    for (int mt = 0; mt < 5; ++mt) {
        const double w = (mean(hi, mt) - mean(lo, mt)) / words, fixed = mean(lo, mt) - w;
        std::printf("    %-16s %6.2f cycles/word, fixed %7.1f cycles\n", METRIC[mt], w, fixed);
        JsonReport f;
        f.num("cycles_per_word", w).num("fixed_cycles", fixed);
        std::string t = f.text();
        slope.raw(METRIC[mt], t.substr(0, t.size() - 1));
    }
    std::string st = slope.text();
    JsonReport r;
    r.str("label", label).str("cpu", cpu).str("channel_kind", kind)
     .num("calls_per_figure", reps).num("rdcycle_overhead", ev[K_OVERHEAD])
     .num("cycles", static_cast<double>(cycle))
     .str("note", "cycles per call with rdcycle around the call, the empty rdcycle pair subtracted; "
          "sum/min/max over calls_per_figure calls; copy_* is a plain volatile 32-bit word loop")
     .raw("sizes", sizes).raw("per_word", st.substr(0, st.size() - 1)).str("verdict", "pass");
    if (!report.empty() && !r.write(report)) return 1;
    std::printf("%s: pass, %llu cycles%s%s\n", label.c_str(), static_cast<unsigned long long>(cycle),
                report.empty() ? "" : ", wrote ", report.c_str());
    return 0;
}
