// tb_dpram.cpp -- two simulated CPUs run the real C driver (c-driver/) against
// the RTL dual-ported RAM, under adversarial timing, with the paper's four
// proof points checked on every Import (protocol_checker.h) and byte
// atomicity and access time checked on every RAM access (ram_bus.h).
//
//   tb_dpram exhaustive [--payload N] [--max-schedules N] [--expect-violation]
//       every interleaving of 2 Exports against 2 Imports, same-cycle
//       collisions on one byte in both slot orders, from 6 start states
//   tb_dpram random [--imports N] [--seed S] [--expect-violation]
//       drifting speed ratios 1:100..100:1, random stalls, payload sizes,
//       alignments and port assignment
//   tb_dpram crash [--seed S]
//       one side frozen or reset at every access point of Import and Export
//   tb_dpram bench [--imports N]
//       simulated-CPU access rate and cycles per second of wall time
//   tb_dpram ratio [--imports N] [--ratios LOG10,...]
//       accesses per Import at fixed writer:reader speed ratios (the figure)
//
// --kind four_slot runs every mode on the four-slot channel kind
// (docs/four_slot.md) instead of the paper's three-buffer one.
//
// Every mode ends on its own: watchdogs in simulated cycles and RAM accesses
// bound each Import and Export, each run (a channel's segment, a schedule, a
// crash run) and each search (schedules, the crash point), and a wall-clock
// hand-off watchdog (sim_cpu.h) catches C code that loops without touching
// the RAM.  A watchdog that fires is the checker "watchdog", and its message
// names the call or run, what it had done and what was expected; a failing
// run ends with one line "FAIL: ..." naming the first fault.
//
// --trace FILE.vcd writes a wave of the first --trace-cycles cycles (binary
// built with Verilator --trace: build/tb/albatross-trace/).
// --report FILE writes the figures as JSON.  Exit status 0 means: no
// violation (or, with --expect-violation, at least one: a negative test).
#include "tb_dpram_random.h"

namespace tbd {

// -------------------------------------------------------------------- bench
int mode_bench(const Options &o)
{
    // Idle RTL: the RAM clocked with no CPU, the upper bound of the harness.
    const uint64_t idle_cycles = 20000000;
    auto t0 = std::chrono::steady_clock::now();
    for (uint64_t i = 0; i < idle_cycles; ++i) g_bus->tick();
    double idle_sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    RandomStats st;
    t0 = std::chrono::steady_clock::now();
    run_random(o.imports, o.seed, st, false, false);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double acc_rate = st.accesses / sec, cyc_rate = st.cycles / sec, idle_rate = idle_cycles / idle_sec;
    std::printf("bench: %llu RAM accesses by simulated CPUs in %.2f s: %.2f M accesses/s of wall time\n",
                static_cast<unsigned long long>(st.accesses), sec, acc_rate / 1e6);
    std::printf("bench: %.2f M simulated cycles/s with CPUs, %.2f M cycles/s idle RTL (ratio %.2f)\n",
                cyc_rate / 1e6, idle_rate / 1e6, cyc_rate / idle_rate);
    if (!o.report.empty()) {
        JsonReport rep;
        rep.num("accesses", st.accesses).num("seconds", sec).num("accesses_per_second", acc_rate)
            .num("cycles_per_second", cyc_rate).num("idle_rtl_cycles_per_second", idle_rate)
            .num("with_cpus_over_idle", cyc_rate / idle_rate).num("imports", st.imports);
        rep.write(o.report);
    }
    if (st.verdict.total()) {
        st.verdict.print();
        return verdict_status(o, st.verdict, "Imports", st.imports);
    }
    return 0;
}

int usage()
{
    std::fprintf(stderr,
                 "usage: tb_dpram exhaustive|random|crash|bench|ratio [--kind three_buffer|four_slot] [--imports N] [--seed S] [--payload N]\n"
                 "                [--ratios LOG10,LOG10,...] (ratio mode: fixed writer:reader speed ratios)\n"
                 "                [--expect-violation] [--expect-caught-by CHECKER]... [--ignore CHECKER]... [--report FILE] [--variant NAME]\n"
                 "                [--trace FILE.vcd [--trace-cycles N]] [--max-schedules N]\n"
                 "checkers: mutual_exclusion definite_results actuality termination ownership\n"
                 "          driver_error byte_atomicity access_time in_channel watchdog\n");
    return 2;
}

bool parse_u64(const char *s, uint64_t &out)
{
    char *end = nullptr;
    unsigned long long v = std::strtoull(s, &end, 10);
    if (!*s || *end) return false;
    out = v;
    return true;
}

}  // namespace tbd

using namespace tbd;


int main(int argc, char **argv)
{
    if (argc < 2) return usage();
    Options o;
    o.mode = argv[1];
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i];
        uint64_t v = 0;
        auto need = [&](const char *what) -> const char * {
            if (i + 1 >= argc) { std::fprintf(stderr, "%s needs a value\n", what); std::exit(2); }
            return argv[++i];
        };
        if (a == "--imports") { if (!parse_u64(need("--imports"), v) || v == 0) { std::fprintf(stderr, "--imports: expected a positive integer\n"); return 2; } o.imports = v; }
        else if (a == "--seed") { if (!parse_u64(need("--seed"), v)) { std::fprintf(stderr, "--seed: expected an integer\n"); return 2; } o.seed = v; }
        else if (a == "--payload") { if (!parse_u64(need("--payload"), v)) { std::fprintf(stderr, "--payload: expected an integer\n"); return 2; } o.payload = static_cast<uint32_t>(v); }
        else if (a == "--report") o.report = need("--report");
        else if (a == "--max-schedules") { if (!parse_u64(need("--max-schedules"), v) || v == 0) { std::fprintf(stderr, "--max-schedules: expected a positive integer\n"); return 2; } g_limits.schedules = v; }
        else if (a == "--trace") o.trace = need("--trace");
        else if (a == "--trace-cycles") { if (!parse_u64(need("--trace-cycles"), v) || v == 0) { std::fprintf(stderr, "--trace-cycles: expected a positive integer\n"); return 2; } o.trace_cycles = v; }
        else if (a == "--variant") o.variant = need("--variant");
        else if (a == "--kind") {
            std::string k = need("--kind");
            if (k == "three_buffer") g_kind = ALB_THREE_BUFFER;
            else if (k == "four_slot") g_kind = ALB_FOUR_SLOT;
            else { std::fprintf(stderr, "--kind: expected three_buffer or four_slot, got %s\n", k.c_str()); return 2; }
        }
        else if (a == "--ratios") o.ratios = need("--ratios");
        else if (a == "--expect-violation") o.expect_violation = true;
        else if (a == "--expect-caught-by") {
            std::string n = need("--expect-caught-by");
            int k = 0;
            while (k < IGN_COUNT && n != ignorable_name(k)) ++k;
            if (k == IGN_COUNT) { std::fprintf(stderr, "--expect-caught-by: unknown checker %s\n", n.c_str()); return 2; }
            o.expect_violation = true;
            o.expect_caught_by.push_back(n);
        }
        else if (a == "--ignore") {
            std::string n = need("--ignore");
            int k = 0;
            while (k < IGN_COUNT && n != ignorable_name(k)) ++k;
            if (k == IGN_COUNT) { std::fprintf(stderr, "--ignore: unknown checker %s\n", n.c_str()); return 2; }
            g_ignored |= 1u << k;
        }
        else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return usage(); }
    }
    g_opts = &o;
    SimCpu::arm_handoff_watchdog(10);
    RamBus bus;
    g_bus = &bus;
    if (!o.trace.empty()) {
        if (!bus.trace(o.trace.c_str(), o.trace_cycles)) {
            std::fprintf(stderr, "--trace: cannot write %s (is this binary built with --trace?)\n", o.trace.c_str());
            return 2;
        }
        std::printf("wave: %s, the first %llu cycles\n", o.trace.c_str(), static_cast<unsigned long long>(o.trace_cycles));
    }
    if (o.mode == "exhaustive") return mode_exhaustive(o);
    if (o.mode == "random") return mode_random(o);
    if (o.mode == "crash") return mode_crash(o);
    if (o.mode == "bench") return mode_bench(o);
    if (o.mode == "ratio") return mode_ratio(o);
    return usage();
}
