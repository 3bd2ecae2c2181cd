// tb_system.cpp -- the multi-board system under test: one simulated CPU per
// board runs the real C driver (producing and consuming its channels through
// port A of its dual-ported RAM), the RTL communication controller moves the
// channels between the boards over the bus, and the bus fault injector
// disturbs it.  Every access and value is checked (system_checker.h).
//
//   tb_system --plan DIR [--cycles N] [--seed S]
//             [--fault-rate R] [--burst L]        probability that a controller access (a
//                                                 new request to a live board) fails; mean
//                                                 run of faulted accesses (default: independent
//                                                 accesses), tb/common/fault_model.h
//             [--fault-clocking clock]            negative test: the old, wrong driving (one
//                                                 draw per clock); the rate check must fail
//             [--land-actual P]                   negative test: each store of a destination's
//                                                 Actual is performed and its answer lost
//                                                 (kind 3) with probability P, outside the rate
//             [--land-kind 3|1|13]                the forced kind: 3 answer lost, 1 err after
//                                                 performing, 13 alternately 3 and 1
//             [--require-landed-same 1]           fail unless a later slot carried the value a
//                                                 destination holds from a landed store whose
//                                                 answer was lost, after its consumer read it
//             [--require-late-publication CH]     fail unless the controller published a value of
//                                                 four-slot channel CH with an Actual store in a
//                                                 later slot than the Slot store that completed it
//             [--require-fragments N|plan]        fail unless N values were published after two or
//                                                 more runs (plan: N from the plan; multirate_scenario.h)
//             [--bounds-at-target FILE]           fail if a consumer's largest latency / age exceeds
//                                                 its bound at the fault hypothesis' target
//                                                 (lines "at_target CH BOARD CLOCKS", bounds_at_target.py)
//             [--require-cut-fragments N]         fail unless N runs of E7.frag != 0 entries were cut
//                                                 short by faults (fragment_checker.h)
//             [--require-skipped CH]              fail unless a value of channel CH was skipped
//                                                 (never published at a destination) and its
//                                                 latency measured when a newer one arrived
//             [--producer-interval CH:CLOCKS[:BURST]]  channel CH's producer exports every CLOCKS
//                                                 clocks (slower than its slots: later slots
//                                                 carry the same source value), BURST values
//                                                 back to back (default 1)
//             [--producer-stop CH|all:CYCLE]      CH's producer (all: every copy channel's) exports
//                                                 nothing from CYCLE on (fresh_scenario.h)
//             [--stretch-export CH:CLOCKS]        CH's producer idles CLOCKS before each value's
//                                                 completing store; fail unless 3 Exports were
//                                                 overtaken by a take
//             [--stretch-import CH:BOARD:CLOCKS]  the consumer of channel CH on BOARD idles
//                                                 CLOCKS before each buffer load of a value but
//                                                 the first (a slow CPU); fail unless at least
//                                                 three of its Imports were overtaken by four or
//                                                 more publications
//             [--dead-board B --dead-at C]        board B's link fails for good at cycle C
//             [--corrupt-entry K]                 a run-time upset: flip a bit of schedule ROM
//                                                 entry K's reserved word E6 at time 20000
//                                                 (the background CRC check must find it)
//             [--corrupt-actual CH:C]             channel CH's producer stores Actual = 7 at cycle C
//             [--flip-rom-bit WORD:BIT]           the ROM image with that bit flipped before start-up:
//                                                 the start-up CRC must refuse it (rom_scenario.h)
//             [--rom FILE] [--report FILE] [--label NAME]
//             [--handoff-watchdog S]              CPU seconds a simulated CPU may run without
//                                                 handing control back (default 10, 1..3600)
//             [--cpu-start C]                     the simulated CPUs start at cycle C (a late
//                                                 boot: the controller may publish first)
//             [--ages FILE]                       every measured latency / age as CSV
//                                                 (channel,board,cycle,age; tools/fault_rates.py)
//             [--latency-scale F] [--expect-caught-by CHECKER]...   negative tests
//             [--expect-failure TEXT]...          ... or a scenario failure containing TEXT
//             [--trace-bus FROM:TO]      print the controller's accesses in that window
//
// DIR holds the compiler's output: rom.hex and tb_plan.txt.  Exit status 0:
// no violation, and the scenario's own expectations held.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>
#include "plan.h"
#include "report.h"
#include "system_checker.h"
#include "system_sim.h"
#include "board_program.h"
#include "system_modes.h"
#include "fresh_scenario.h"
#include "rom_scenario.h"
#include "fragment_checker.h"
#include "multirate_scenario.h"

using namespace tbsys;

namespace {
// addr is the control word of one of the plan's destination instances on board.
bool is_dest_control(const Plan &plan, int board, uint32_t addr)
{
    for (const PlanChannel &c : plan.channels)
        for (const PlanDest &d : c.dests)
            if (d.board == board && d.base == addr) return true;
    return false;
}

// --stretch-import: the one destination instance whose Imports are stretched.
struct Stretch {
    int board = -1, chan = -1, dest = -1;
    uint32_t first = 0, end = 0, stride = 1;   // its buffers' bytes [first, end), one buffer per stride
    unsigned clocks = 0;
} g_stretch;
unsigned stretch_hook(SimCpu &cpu, uint32_t addr, bool we)
{
    if (we || cpu.id != g_stretch.board || addr < g_stretch.first || addr >= g_stretch.end) return 0;
    return (addr - g_stretch.first) % g_stretch.stride ? g_stretch.clocks : 0;
}
}  // namespace

int main(int argc, char **argv)
{
    Options o;
    if (int rc = parse_options(argc, argv, o); rc >= 0) return rc;
    Plan plan;
    std::string err;
    if (!plan.load(o.plan_dir + "/tb_plan.txt", err)) { std::fprintf(stderr, "tb_system: %s\n", err.c_str()); return 2; }
    for (PlanChannel &c : plan.channels)   // a negative test's deliberately wrong bounds
        c.latency = static_cast<uint64_t>(static_cast<double>(c.latency) * o.latency_scale);
    for (PlanMode &m : plan.modes)
        for (uint64_t &b : m.bound_ff) b = static_cast<uint64_t>(static_cast<double>(b) * o.latency_scale);
    if (plan.boards > SystemSim::kBoards || plan.ram_bytes != SystemSim::kRamBytes) {
        std::fprintf(stderr, "tb_system: the plan has %d boards of %u bytes; this build simulates %d boards of %u bytes\n",
                     plan.boards, plan.ram_bytes, SystemSim::kBoards, SystemSim::kRamBytes);
        return 2;
    }
    std::string rom = o.rom.empty() ? o.plan_dir + "/rom.hex" : o.rom;
    if (o.flip_word >= 0 && (rom = flip_rom_bit(rom, o.flip_word, o.flip_bit, err)).empty()) {   // rom_scenario.h
        std::fprintf(stderr, "tb_system: %s\n", err.c_str());
        return 2;
    }
    // A ROM upset after start-up (the start-up CRC would refuse a corrupted
    // image outright): entry K's E6, a reserved word, so that the entry does the
    // same until the background check finds it and skips it from then on.
    std::vector<std::string> plusargs;
    if (o.corrupt_entry >= 0) {
        if (!entry_exists(rom, o.corrupt_entry)) {
            std::fprintf(stderr, "tb_system: cannot corrupt entry %d\n", o.corrupt_entry);
            return 2;
        }
        plusargs.push_back("+rom_upset_word=" + std::to_string(4 + 8 * o.corrupt_entry + 6));
        plusargs.push_back("+rom_upset_at=20000");
    }
    FaultModel faults(o.fault_rate, o.burst, o.seed ^ 0xFA17ull);
    char burst_txt[80];
    if (o.burst > 0) std::snprintf(burst_txt, sizeof burst_txt, "bursts of %.3g accesses", faults.mean_burst());
    else std::snprintf(burst_txt, sizeof burst_txt, "independent");
    std::printf("%s: %d boards, %zu channels, cycle %llu clocks (%s), %llu clocks, fault rate %.3g per access (%s%s)%s\n",
                o.label.c_str(), plan.boards, plan.channels.size(), static_cast<unsigned long long>(plan.cycle),
                plan.sync_mode ? "position-synchronised" : "time-rigid", static_cast<unsigned long long>(o.cycles),
                o.fault_rate, burst_txt, o.fault_per_clock ? ", drawn per CLOCK: the old, wrong injector" : "",
                o.dead_board >= 0 ? ", one board dies" : "");
    std::fflush(stdout);

    SystemSim sim(rom, plusargs);
    g_sim = &sim;
    g_opts = &o;
    g_plan = &plan;
    load_images(plan);
    sim.reset();                               // the controller starts on the image
    const uint64_t time_offset = sim.cycle() - sim.time();
    SystemChecker chk(plan, sim, time_offset);
    g_chk = &chk;
    sim.observer = &chk;
    // Minor cycles and fragments on the controller's bus (fragment_checker.h):
    // not on an image the start-up check refuses or one upset while it runs.
    FragmentChecker frag(rom, plan, chk);
    const bool frag_on = frag.active() && o.flip_word < 0 && o.corrupt_entry < 0;
    std::printf("  minor cycles and fragments: %s\n", frag_on ? "judged (due_cycle, fragment_publish, source_lock, fragment_word)"
                : frag.active() ? "not judged (a corrupted ROM image)" : ("not judged: " + frag.why_inactive()).c_str());
    std::FILE *ages = nullptr;
    if (!o.ages.empty()) {
        ages = std::fopen(o.ages.c_str(), "w");
        if (!ages) { std::fprintf(stderr, "tb_system: cannot write %s\n", o.ages.c_str()); return 2; }
        std::fprintf(ages, "channel,board,cycle,age\n");
        chk.set_ages_file(ages);
    }
    const bool fault_free = o.fault_rate == 0 && o.land_actual == 0 && o.dead_board < 0 && o.corrupt_entry < 0 &&
                            o.corrupt_channel < 0;
    chk.set_latency_is_checked(fault_free);
    // Schedule modes: requests at random times, every switch judged (system_modes.h).
    ModeWatch modes(plan, sim);
    g_modes = &modes;
    if (modes.active())   // the requests the controller takes: acted on, rejected or ignored
        chk.set_take_fn([&modes](int chan, uint8_t b, uint32_t t) { modes.taken(chan, b, t); });
    if (modes.active())
        chk.set_bound_fn([&modes](int chan, uint64_t from, uint64_t to, uint64_t &b, uint64_t &br) {
            return modes.bound(chan, from, to, b, br);
        });

    std::mt19937_64 rng(o.seed);
    std::vector<BoardCtx> boards(SystemSim::kBoards);
    for (int b = 0; b < SystemSim::kBoards; ++b) {
        boards[b].board = b;
        boards[b].rng.seed(o.seed * 31 + b);
    }
    for (size_t i = 0; i < plan.channels.size(); ++i) {
        const PlanChannel &c = plan.channels[i];
        uint64_t p = std::max<uint64_t>(c.period, 64);
        if (c.copy()) {
            Role r;
            r.chan = static_cast<int>(i);
            r.interval_lo = c.sync ? p / 2 : 1;     // positions come about once a cycle
            r.interval_hi = c.sync ? p : p / 2;     // others many times, at random phases
            if (c.name == o.slow_channel) r.interval_lo = r.interval_hi = o.slow_interval, r.burst = o.slow_burst;
            boards[c.src_board].roles.push_back(r);
        }
        for (size_t d = 0; d < c.dests.size(); ++d) {
            Role r;
            r.chan = static_cast<int>(i);
            r.dest = static_cast<int>(d);
            r.time_channel = c.kind == "time";
            r.status_channel = c.kind == "status" && c.id != plan.mode_info;
            boards[c.dests[d].board].roles.push_back(r);
        }
    }
    double period[SystemSim::kBoards];
    for (int b = 0; b < SystemSim::kBoards; ++b) {
        period[b] = 1 + static_cast<double>(rng() % 4);   // RAM clocks per CPU clock
        sim.cpu[b].window_lo = 0;
        sim.cpu[b].window_hi = SystemSim::kRamBytes;
        sim.cpu[b].context = &boards[b];
        if (!boards[b].roles.empty()) sim.cpu[b].start(board_program);
    }
    if (o.stretch_board >= 0) {
        for (size_t i = 0; i < plan.channels.size(); ++i)
            for (size_t d = 0; d < plan.channels[i].dests.size(); ++d)
                if (plan.channels[i].name == o.stretch_channel && plan.channels[i].dests[d].board == o.stretch_board) {
                    const PlanChannel &c = plan.channels[i];
                    g_stretch.board = o.stretch_board;
                    g_stretch.chan = static_cast<int>(i);
                    g_stretch.dest = static_cast<int>(d);
                    g_stretch.first = c.dests[d].base + ALB_OFF_BUFFER(1u, c.dest_size());
                    g_stretch.end = c.dests[d].base + instance_bytes(c, c.dest_size());
                    g_stretch.stride = ALB_OFF_BUFFER(2u, c.dest_size()) - ALB_OFF_BUFFER(1u, c.dest_size());
                    g_stretch.clocks = static_cast<unsigned>(o.stretch_clocks);
                }
        if (g_stretch.chan < 0) {
            std::fprintf(stderr, "tb_system: --stretch-import: board %d has no destination of channel %s\n",
                         o.stretch_board, o.stretch_channel.c_str());
            return 2;
        }
        sim.cpu[o.stretch_board].stall_hook = stretch_hook;
        std::printf("  stretched: %s's consumer on board %d idles %u clocks before each buffer load but a value's first\n",
                    o.stretch_channel.c_str(), o.stretch_board, g_stretch.clocks);
    }

    if (!fresh_setup(plan, o, sim, err)) {   // --producer-stop, --stretch-export (fresh_scenario.h)
        std::fprintf(stderr, "tb_system: %s\n", err.c_str());
        return 2;
    }

    std::vector<TransferMeter> meters;
    for (const PlanChannel &c : plan.channels)
        if (c.copy() && c.dests.size() == 1) { TransferMeter t; t.c = &c; meters.push_back(t); }
    // A CPU whose C code loops without a RAM access never hands control back
    // to this loop, so no bound in simulated cycles can stop it: the CPU-time
    // hand-off watchdog ends the run with a message naming the CPU.
    SimCpu::arm_handoff_watchdog(o.handoff_watchdog_s);
    uint64_t wait[SystemSim::kBoards] = {};
    std::mt19937_64 land_rng(o.seed ^ 0x1A4Dull);
    sim.fault_accesses = sim.fault_injected = sim.dead_accesses = 0;
    sim.set_fault(faults.next());              // the kind of the first access
    const uint64_t start = sim.cycle(), report_every = o.cycles / 10;
    auto t0 = std::chrono::steady_clock::now();
    bool time_monotonic = true, controller_started = false;
    uint32_t last_time = sim.time();
    for (uint64_t n = 0; n < o.cycles; ++n) {
        if (o.dead_board >= 0 && sim.cycle() - start == o.dead_at) sim.set_dead(1u << o.dead_board);
        for (int b = 0; b < SystemSim::kBoards; ++b) {
            SimCpu &c = sim.cpu[b];
            if (boards[b].roles.empty() || sim.busy(b) || c.faulted || n < o.cpu_start) continue;
            if (wait[b]) { --wait[b]; continue; }
            if (!c.has_request) c.resume();
            if (c.has_request) sim.issue(b);
        }
        if (o.land_actual > 0) {
            int rb = 0;
            uint32_t ra = 0;
            bool rwe = false;
            uint8_t rsel = 0;
            if (sim.next_request(rb, ra, rwe, rsel) && rwe && (rsel & (1u << ALB_OFF_ACTUAL)) && is_dest_control(plan, rb, ra) &&
                std::uniform_real_distribution<double>(0, 1)(land_rng) < o.land_actual)
                sim.force_fault(o.land_kind == 13 ? (sim.forced_faults % 2 ? 1u : 3u) : static_cast<unsigned>(o.land_kind));
        }
        // The controller's new request, for fragment_checker.h's faults
        // (the injector's counters tell, after the edge, whether it was faulted).
        int fq_board = -1;
        uint32_t fq_addr = 0;
        bool fq_we = false;
        uint8_t fq_sel = 0;
        const bool fq_told = frag_on && sim.next_request(fq_board, fq_addr, fq_we, fq_sel);
        const uint64_t fq_faults = sim.fault_injected + sim.forced_faults + sim.dead_accesses;
        unsigned done = sim.tick();
        modes.tick();
        chk.tick(sim.cycle());
        if (frag_on) frag.tick(sim.cycle(), sim.cycle_start());
        // One draw per access begun (per clock: the old injector's driving).
        if (sim.fault_drawn || o.fault_per_clock) sim.set_fault(faults.next());
        if (sim.bus_event.done && sim.cycle() >= o.trace_from && sim.cycle() <= o.trace_to) {
            const SystemSim::BusEvent &e = sim.bus_event;
            std::printf("  bus %8llu..%-8llu %s %-5s board %d addr 0x%03x  time %u\n",
                        static_cast<unsigned long long>(e.start), static_cast<unsigned long long>(e.end),
                        e.ok ? "ok  " : "FAIL", e.we ? "write" : "read", e.board, e.addr, sim.time());
        }
        if (sim.bus_event.done) {
            if (!controller_started) {          // its first cycle has begun
                controller_started = true;
                chk.set_latency_from(sim.bus_event.start + plan.cycle);
            }
            for (TransferMeter &t : meters) t.on(sim.bus_event);
            chk.on_bus(sim.bus_event);
            if (frag_on) frag.on_bus(sim.bus_event);
        }
        if (frag_on && sim.fault_injected + sim.forced_faults + sim.dead_accesses != fq_faults)
            frag.on_fault(sim.cycle(), fq_told, fq_board, fq_addr, fq_we);
        for (int b = 0; b < SystemSim::kBoards; ++b)
            if (done & (1u << b)) wait[b] = static_cast<uint64_t>((rng() % 3) * period[b]);
        if (sim.time() < last_time) time_monotonic = false;
        last_time = sim.time();
        if (report_every && (n + 1) % report_every == 0) {
            std::printf("  %3.0f%%  cycle %llu, %llu violations\n", 100.0 * (n + 1) / o.cycles,
                        static_cast<unsigned long long>(n + 1), static_cast<unsigned long long>(chk.total()));
            std::fflush(stdout);
        }
    }
    chk.end_of_run();
    if (ages) { chk.set_ages_file(nullptr); std::fclose(ages); }
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // ---- scenario expectations beyond the checkers
    std::vector<std::string> failures;
    char m[300];
    for (int b = 0; b < SystemSim::kBoards; ++b) {
        if (sim.cpu[b].faulted) failures.push_back("CPU " + std::to_string(b) + ": " + sim.cpu[b].fault);
        if (boards[b].attach_errors) failures.push_back("board " + std::to_string(b) + ": attach failed on a valid image");
    }
    if (sim.cpu_latency_violations) failures.push_back(sim.first_cpu_latency_violation);
    for (int b = 0; b < SystemSim::kBoards; ++b)
        if (sim.ref[b].violations) failures.push_back("board " + std::to_string(b) + ": " + sim.ref[b].first_violation);
    if (!time_monotonic) failures.push_back("global time went backwards");
    // The injected rate, measured over the accesses to live boards, against
    // the nominal one (tb/common/fault_model.h derives the tolerance).
    const double rate_measured = sim.fault_accesses ? static_cast<double>(sim.fault_injected) / sim.fault_accesses : 0;
    const double rate_tol = faults.tolerance(sim.fault_accesses);
    const bool rate_ok = std::fabs(rate_measured - o.fault_rate) <= rate_tol;
    if (sim.forced_faults)
        std::printf("  forced: %llu destination Actual stores performed with their answer lost (--land-actual %.2f)\n",
                    static_cast<unsigned long long>(sim.forced_faults), o.land_actual);
    std::printf("  fault rate per access: nominal %.4f, measured %.4f (%llu of %llu accesses to live boards; "
                "mean burst %.3g; tolerance +-%.4f, %.0f sigma)%s\n", o.fault_rate, rate_measured,
                static_cast<unsigned long long>(sim.fault_injected), static_cast<unsigned long long>(sim.fault_accesses),
                faults.mean_burst(), rate_tol, FaultModel::kSigmas, rate_ok ? "" : ": OUT OF TOLERANCE");
    if (!rate_ok) {
        std::snprintf(m, sizeof m, "fault rate: expected %.4f +- %.4f per access, got %.4f (%llu of %llu accesses faulted)",
                      o.fault_rate, rate_tol, rate_measured, static_cast<unsigned long long>(sim.fault_injected),
                      static_cast<unsigned long long>(sim.fault_accesses));
        failures.push_back(m);
    }
    if (sim.error()) failures.push_back("the controller flagged its ROM header as invalid");
    // The scenario a test asked for happened (and how often).
    uint64_t same_later = 0, same_read = 0;
    for (const SystemChecker::ChannelStats &cs : chk.stats)
        for (const SystemChecker::DestStats &ds : cs.dests) { same_later += ds.landed_same_later; same_read += ds.landed_same_read; }
    if (o.land_actual > 0)
        std::printf("  landed stores: %llu later slots carried the value a destination held from a store whose answer "
                    "was lost, %llu of them after its consumer had read it New\n",
                    static_cast<unsigned long long>(same_later), static_cast<unsigned long long>(same_read));
    if (o.require_landed_same && (same_later == 0 || same_read == 0)) {
        std::snprintf(m, sizeof m, "landed stores: expected a later slot carrying the value of a landed, unanswered "
                      "store after its consumer read it New, got %llu such slots (%llu after a New read)",
                      static_cast<unsigned long long>(same_later), static_cast<unsigned long long>(same_read));
        failures.push_back(m);
    }
    // --require-late-publication / --require-skipped: the scenario happened on channel CH.
    auto require = [&](const std::string &ch, uint64_t SystemChecker::DestStats::*field, const char *what) {
        if (ch.empty()) return;
        uint64_t n = 0;
        bool known = false;
        for (size_t i = 0; i < plan.channels.size(); ++i) {
            if (plan.channels[i].name != ch) continue;
            known = true;
            for (const SystemChecker::DestStats &ds : chk.stats[i].dests) n += ds.*field;
        }
        std::printf("  %s: %s: %llu\n", ch.c_str(), what, static_cast<unsigned long long>(n));
        if (!known || n == 0) {
            std::snprintf(m, sizeof m, "%s: expected at least one %s, got %s", ch.c_str(), what,
                          known ? "none" : "no such channel in the plan");
            failures.push_back(m);
        }
    };
    require(o.require_late, &SystemChecker::DestStats::late_publications,
            "late publication (an Actual store of a value completed by a Slot store in an earlier slot)");
    for (const std::string &ch : o.require_skipped)
        require(ch, &SystemChecker::DestStats::latency_skipped,
                "skipped value (never published at a destination) whose latency was measured");
    std::string fresh_json;   // freshness scenarios (fresh_scenario.h)
    fresh_report(plan, o, chk, fault_free, failures, fresh_json);
    if (g_stretch.chan >= 0) {
        const SystemChecker::DestStats &ds = chk.stats[g_stretch.chan].dests[g_stretch.dest];
        std::printf("  stretched Imports: %llu of %llu Imports overtaken by 4 or more publications, at most %llu\n",
                    static_cast<unsigned long long>(ds.imports_overtaken4), static_cast<unsigned long long>(ds.imports),
                    static_cast<unsigned long long>(ds.max_overtakes));
        if (ds.imports_overtaken4 < 3) {
            std::snprintf(m, sizeof m, "stretched Imports: expected at least 3 Imports overtaken by 4 or more "
                          "publications, got %llu (at most %llu publications during one Import)",
                          static_cast<unsigned long long>(ds.imports_overtaken4), static_cast<unsigned long long>(ds.max_overtakes));
            failures.push_back(m);
        }
    }
    // The counters, as a CPU read them from the STATUS channel.
    bool has_status = false;
    for (const PlanChannel &c : plan.channels) has_status = has_status || c.kind == "status";
    if (has_status) {
        std::printf("%s: STATUS as read by a CPU: %llu imports, transfers %llu, retries %llu, abandoned %llu, "
                    "corrupt %llu, rom_errors %llu\n", o.label.c_str(), static_cast<unsigned long long>(g_status.imports),
                    static_cast<unsigned long long>(g_status.transfers), static_cast<unsigned long long>(g_status.retries),
                    static_cast<unsigned long long>(g_status.abandoned), static_cast<unsigned long long>(g_status.corrupt),
                    static_cast<unsigned long long>(g_status.rom_errors));
        bool faulty = o.fault_rate > 0 || o.land_actual > 0 || o.dead_board >= 0;
        if (g_status.transfers == 0) failures.push_back("STATUS: no transfer counted");
        if (faulty && g_status.retries == 0) failures.push_back("STATUS: faults were injected, yet no retry was counted");
        if (!faulty && (g_status.retries || g_status.abandoned))
            failures.push_back("STATUS: retries or abandoned transfers counted without any fault");
        if (o.dead_board >= 0 && g_status.abandoned == 0) failures.push_back("STATUS: a board is dead, yet nothing was abandoned");
        if (o.corrupt_entry >= 0 && g_status.rom_errors == 0)
            failures.push_back("STATUS: the corrupted ROM entry was not counted in rom_errors");
        if (o.corrupt_channel >= 0 && g_status.corrupt == 0)
            failures.push_back("STATUS: the out-of-range Actual was not counted as corrupt");
        if (o.corrupt_channel < 0 && g_status.corrupt && !modes.active())   // (modes: rejected requests, below)
            failures.push_back("STATUS: corrupt control bytes counted where none were written");
    }
    if (modes.active()) {
        modes.settle();
        modes.finish(fault_free, g_status.corrupt, failures);
        std::printf("  modes: %s\n", modes.json().c_str());
    }
    multirate_verdict(plan, o, chk, frag_on ? &frag : nullptr, failures);   // multirate_scenario.h
    if (o.corrupt_channel >= 0 && !g_corrupted) failures.push_back("the faulty producer never ran");
    if (o.corrupt_entry >= 0 && sim.rom_errors() == 0)
        failures.push_back("a corrupted ROM entry was not counted in rom_errors");
    if (o.corrupt_entry < 0 && sim.rom_errors() != 0) {
        std::snprintf(m, sizeof m, "rom_errors = %u with an intact ROM, expected 0", sim.rom_errors());
        failures.push_back(m);
    }

    // ---- report
    std::printf("%s: %llu clocks in %.1f s (%.2f M clocks/s), controller bus busy %.1f%%, %llu accesses, %llu failed\n",
                o.label.c_str(), static_cast<unsigned long long>(o.cycles), sec, o.cycles / sec / 1e6,
                100.0 * sim.bus_busy_cycles / (sim.cycle() - start + 1e-9),
                static_cast<unsigned long long>(sim.bus_accesses), static_cast<unsigned long long>(sim.bus_failures));
    std::printf("  %-12s %-7s %8s %8s %9s %9s %9s %7s %9s %9s\n", "channel", "to", "exports", "publ.", "imports",
                "lat max", "bound", "ratio", "over", "age seen");
    std::string chans = "[";
    for (size_t i = 0; i < plan.channels.size(); ++i) {
        const PlanChannel &c = plan.channels[i];
        const SystemChecker::ChannelStats &cs = chk.stats[i];
        for (size_t d = 0; d < c.dests.size(); ++d) {
            const SystemChecker::DestStats &ds = cs.dests[d];
            double ratio = c.latency ? static_cast<double>(ds.latency_max) / c.latency : 0;
            std::printf("  %-12s board %d %8llu %8llu %9llu %9llu %9llu %7.3f %9llu %9llu\n", c.name.c_str(),
                        c.dests[d].board, static_cast<unsigned long long>(cs.exports),
                        static_cast<unsigned long long>(ds.publications), static_cast<unsigned long long>(ds.imports),
                        static_cast<unsigned long long>(ds.latency_max), static_cast<unsigned long long>(c.latency), ratio,
                        static_cast<unsigned long long>(ds.latency_over), static_cast<unsigned long long>(ds.last_age_seen));
            char b[1100];
            std::snprintf(b, sizeof b,
                          "%s{\"channel\": \"%s\", \"kind\": \"%s\", \"to_board\": %d, \"exports\": %llu, \"publications\": %llu, "
                          "\"imports\": %llu, \"imports_new\": %llu, \"latency_max\": %llu, \"latency_mean\": %.1f, "
                          "\"latency_bound\": %llu, \"max_over_bound\": %.4f, \"latency_samples\": %llu, \"over_bound\": %llu, "
                          "\"delivered_within_bound\": %.5f, \"last_age_seen\": %llu, \"max_age_seen\": %llu, "
                          "\"max_taken_minus_published\": %llu, \"period_bound\": %llu, \"landed_unanswered\": %llu, "
                          "\"landed_same_later\": %llu, \"landed_same_read\": %llu, \"max_overtakes\": %llu, "
                          "\"imports_overtaken4\": %llu, \"late_publications\": %llu, \"latency_skipped\": %llu}",
                          chans.size() > 1 ? ", " : "", c.name.c_str(), c.kind.c_str(), c.dests[d].board,
                          static_cast<unsigned long long>(cs.exports), static_cast<unsigned long long>(ds.publications),
                          static_cast<unsigned long long>(ds.imports), static_cast<unsigned long long>(ds.imports_new),
                          static_cast<unsigned long long>(ds.latency_max),
                          ds.latency_n ? static_cast<double>(ds.latency_sum) / ds.latency_n : 0.0,
                          static_cast<unsigned long long>(c.latency), ratio, static_cast<unsigned long long>(ds.latency_n),
                          static_cast<unsigned long long>(ds.latency_over),
                          ds.latency_n ? 1.0 - static_cast<double>(ds.latency_over) / ds.latency_n : 0.0,
                          static_cast<unsigned long long>(ds.last_age_seen), static_cast<unsigned long long>(ds.max_age_seen),
                          static_cast<unsigned long long>(ds.max_taken_minus_publish), static_cast<unsigned long long>(c.period),
                          static_cast<unsigned long long>(ds.landed_unanswered),
                          static_cast<unsigned long long>(ds.landed_same_later),
                          static_cast<unsigned long long>(ds.landed_same_read),
                          static_cast<unsigned long long>(ds.max_overtakes),
                          static_cast<unsigned long long>(ds.imports_overtaken4),
                          static_cast<unsigned long long>(ds.late_publications),
                          static_cast<unsigned long long>(ds.latency_skipped));
            chans += b;
            // A dead board: consumers of its channels must see the age grow;
            // channels that do not involve it keep their fault-free bound, live
            // destinations of an entry that does involve it the with-retries
            // bound (the dead board's accesses fail before it is dropped).
            bool involves = false;
            for (const PlanDest &x : c.dests) involves = involves || x.board == o.dead_board;
            involves = o.dead_board >= 0 && (involves || c.src_board == o.dead_board);
            bool touches = o.dead_board >= 0 && (c.src_board == o.dead_board || c.dests[d].board == o.dead_board);
            if (o.dead_board >= 0 && c.copy() && c.src_board == o.dead_board && c.dests[d].board != o.dead_board &&
                ds.last_age_seen < 3 * std::max<uint64_t>(c.period, plan.cycle)) {
                std::snprintf(m, sizeof m, "%s from the dead board %d: its consumer on board %d last saw age %llu, "
                              "expected more than 3 periods (%llu): staleness not visible",
                              c.name.c_str(), o.dead_board, c.dests[d].board, static_cast<unsigned long long>(ds.last_age_seen),
                              static_cast<unsigned long long>(3 * std::max<uint64_t>(c.period, plan.cycle)));
                failures.push_back(m);
            }
            if (o.dead_board >= 0 && !involves && ds.latency_over) {
                std::snprintf(m, sizeof m, "%s to board %d does not involve the dead board, yet %llu values exceeded the fault-free bound",
                              c.name.c_str(), c.dests[d].board, static_cast<unsigned long long>(ds.latency_over));
                failures.push_back(m);
            }
            if (o.dead_board >= 0 && involves && !touches && ds.over_retry_bound) {
                std::snprintf(m, sizeof m, "%s to the live board %d: %llu values exceeded the with-retries bound %llu",
                              c.name.c_str(), c.dests[d].board, static_cast<unsigned long long>(ds.over_retry_bound),
                              static_cast<unsigned long long>(c.latency_retry));
                failures.push_back(m);
            }
            if (!touches && ds.publications == 0) {
                std::snprintf(m, sizeof m, "%s to board %d: no value was ever published", c.name.c_str(), c.dests[d].board);
                failures.push_back(m);
            }
        }
    }
    chans += "]";
    std::string transfers = "[";
    if (!meters.empty())
        std::printf("  %-12s %6s %9s %9s %9s %9s %9s %10s %9s\n", "transfer", "words", "measured", "mean clk",
                    "min clk", "max clk", "minimum", "efficiency", "idle clk");
    for (const TransferMeter &t : meters) {
        const uint64_t w = t.c->words, minimum = 2 * (w + (w + 1) + 5);
        const double mean = t.n ? static_cast<double>(t.sum) / t.n : 0;
        const double eff = mean > 0 ? 2.0 * (2 * w + 1) / mean : 0;
        std::printf("  %-12s %6llu %9llu %9.1f %9llu %9llu %9llu %10.3f %9.2f\n", t.c->name.c_str(),
                    static_cast<unsigned long long>(w), static_cast<unsigned long long>(t.n), mean,
                    static_cast<unsigned long long>(t.n ? t.min : 0), static_cast<unsigned long long>(t.max),
                    static_cast<unsigned long long>(minimum), eff, t.n ? static_cast<double>(t.idle_sum) / t.n : 0.0);
        char b[400];
        std::snprintf(b, sizeof b,
                      "%s{\"channel\": \"%s\", \"bytes\": %u, \"words\": %llu, \"transfers\": %llu, \"mean_cycles\": %.2f, "
                      "\"min_cycles\": %llu, \"max_cycles\": %llu, \"minimum_cycles\": %llu, \"accesses\": %llu, "
                      "\"efficiency\": %.4f, \"mean_idle_cycles\": %.3f}",
                      transfers.size() > 1 ? ", " : "", t.c->name.c_str(), t.c->size, static_cast<unsigned long long>(w),
                      static_cast<unsigned long long>(t.n), mean, static_cast<unsigned long long>(t.n ? t.min : 0),
                      static_cast<unsigned long long>(t.max), static_cast<unsigned long long>(minimum),
                      static_cast<unsigned long long>(t.accesses_last), eff,
                      t.n ? static_cast<double>(t.idle_sum) / t.n : 0.0);
        transfers += b;
    }
    transfers += "]";
    for (int k = 0; k < SystemChecker::KINDS; ++k)
        std::printf("  %-18s %llu violations%s%s\n", SystemChecker::kind_name(k),
                    static_cast<unsigned long long>(chk.violations[k]), chk.violations[k] ? ": " : "",
                    chk.first_message[k].c_str());
    if (o.flip_word >= 0) rom_refused_verdict(plan, chk, sim, failures);   // a refused image (rom_scenario.h)
    for (const std::string &f : failures) std::printf("  FAIL: %s\n", f.c_str());
    std::string viol = "{";
    for (int k = 0; k < SystemChecker::KINDS; ++k) {
        char b[80];
        std::snprintf(b, sizeof b, "%s\"%s\": %llu", k ? ", " : "", SystemChecker::kind_name(k),
                      static_cast<unsigned long long>(chk.violations[k]));
        viol += b;
    }
    viol += "}";
    if (!o.report.empty()) {
        JsonReport rep;
        rep.str("label", o.label).str("mode", plan.sync_mode ? "position-synchronised" : "time-rigid")
            .num("cycle_clocks", static_cast<double>(plan.cycle)).num("clocks", static_cast<double>(o.cycles))
            .num("measured_from", static_cast<double>(chk.latency_from()))
            .num("fault_rate", o.fault_rate).num("burst", o.burst).num("fault_mean_burst", faults.mean_burst())
            .str("fault_clocking", o.fault_per_clock ? "clock" : "access")
            .num("fault_rate_measured", rate_measured).num("fault_rate_tolerance", rate_tol)
            .num("fault_accesses", static_cast<double>(sim.fault_accesses))
            .num("faults_injected", static_cast<double>(sim.fault_injected))
            .num("dead_accesses", static_cast<double>(sim.dead_accesses))
            .num("forced_landed_stores", static_cast<double>(sim.forced_faults)).num("fault_rate_ok", rate_ok ? 1 : 0)
            .num("dead_board", o.dead_board)
            .num("corrupt_entry", o.corrupt_entry).num("rom_errors", sim.rom_errors())
            .num("bus_busy_cycles", static_cast<double>(sim.bus_busy_cycles))
            .num("bus_accesses", static_cast<double>(sim.bus_accesses))
            .num("bus_failures", static_cast<double>(sim.bus_failures))
            .num("violations_total", static_cast<double>(chk.total())).raw("violations", viol)
            .num("scenario_failures", static_cast<double>(failures.size())).raw("channels", chans)
            .raw("transfers", transfers).raw("freshness", fresh_json)
            .raw("modes", modes.active() ? modes.json() : "null")
            .raw("fragments", frag_on ? frag.json() : "null")
            .num("seconds", sec);
        rep.write(o.report);
    }
    return system_verdict(o, failures, chk);
}
