// board_program.h -- the side of tb_system that is not the main loop: its
// command line, each board's CPU program (the real C driver exporting and
// importing its channels), the bus fault model and the transfer meter.
#pragma once
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>
#include "fault_model.h"
#include "plan.h"
#include "system_checker.h"
#include "system_sim.h"
extern "C" {
#include "albatross.h"
}

namespace tbsys {

struct Options {
    std::string plan_dir, rom, report, label = "system";
    std::string ages;                            // --ages FILE: every measured latency/age (CSV)
    uint64_t cycles = 400000, seed = 1, dead_at = 0;
    uint64_t cpu_start = 0;                      // --cpu-start C: the simulated CPUs start at cycle C
    unsigned handoff_watchdog_s = 10;            // --handoff-watchdog S: CPU seconds a simulated CPU
                                                 // may run without handing control back
    double fault_rate = 0, burst = 0, latency_scale = 1;   // burst 0: independent accesses
    bool fault_per_clock = false;                // negative test: the old injector, one draw per clock
    double land_actual = 0;                      // negative test: a destination Actual store is performed
                                                 // and its answer lost (kind 3) with this probability
    int land_kind = 3;                           // the forced kind: 3 (answer lost), 1 (err after
                                                 // performing), 13 (alternately 3 and 1)
    bool require_landed_same = false;            // fail unless a later slot carried a landed value
    std::string require_late;                    // --require-late-publication CH: fail unless CH's
                                                 // controller published a four-slot value in a later
                                                 // slot than the Slot store that completed it
    std::string bounds_at_target;                // --bounds-at-target FILE: each consumer's latency / age
                                                 // bound at the fault hypothesis' target (bounds_at_target.py)
    uint64_t require_cut = 0;                    // --require-cut-fragments N: fail unless N runs of values in
                                                 // fragments were cut (a fault: re-run, or dropped destinations)
    uint64_t require_fragments = 0;              // --require-fragments N: fail unless N values were published
                                                 // after two or more fragments, each judged (fragment_checker.h)
    bool require_fragments_plan = false;         // --require-fragments plan: N from the plan (multirate_scenario.h)
    std::vector<std::string> require_skipped;    // --require-skipped CH...: fail unless a value of CH was
                                                 // skipped and its latency measured (a later one arrived)
    std::string slow_channel;                    // --producer-interval CH:CLOCKS[:BURST]: channel CH's
    uint64_t slow_interval = 0;                  // producer exports every CLOCKS clocks
    uint64_t slow_burst = 1;                     // ... BURST values back to back
    std::string stop_channel;                    // --producer-stop CH:CYCLE: CH's producer (or "all")
    uint64_t stop_at = 0;                        // exports nothing from CYCLE on (fresh_scenario.h)
    std::string stretch_export_channel;          // --stretch-export CH:CLOCKS: CH's producer idles CLOCKS
    uint64_t stretch_export_clocks = 0;          // before each value's completing store
    std::string stretch_channel;                 // --stretch-import CH:BOARD:CLOCKS: the consumer of
    int stretch_board = -1;                      // channel CH on BOARD idles CLOCKS before every
    uint64_t stretch_clocks = 0;                 // buffer load of a value but its first
    std::vector<std::string> expect_caught_by;   // a negative test: these checkers must fire
    std::vector<std::string> expect_failure;     // ... or scenario failures containing these
    uint64_t trace_from = 1, trace_to = 0;       // print the controller's accesses in this window
    int dead_board = -1, corrupt_entry = -1;
    int flip_word = -1, flip_bit = 0;            // --flip-rom-bit WORD:BIT (rom_scenario.h)
    int corrupt_channel = -1;                    // a faulty producer stores Actual = 7 ...
    uint64_t corrupt_at = 0;                     // ... once, at this cycle
};

// Parses the command line into o: -1 on success, else the exit status
// (the usage message has been printed).
int parse_options(int argc, char **argv, Options &o);

// The run's verdict, printed, as main's exit status: an expected failure
// (o.expect_failure), a negative test (o.expect_caught_by), or PASSED/FAILED
// (tb_system_verdict.cpp).
int system_verdict(const Options &o, const std::vector<std::string> &failures, const SystemChecker &chk);

// Shared with board_program (set up by main before the CPUs start).
extern SystemSim *g_sim;
extern const Options *g_opts;
extern bool g_corrupted;
extern SystemChecker *g_chk;
extern const Plan *g_plan;

// One channel role of one board's CPU.
struct Role {
    int chan = 0;              // plan channel index
    int dest = -1;             // -1: producer of the source instance
    alb_channel_t ch{};
    uint64_t seq = 0, next_due = 0, interval_lo = 1, interval_hi = 1;
    uint64_t burst = 1, burst_done = 0;        // Exports back to back, and how many of them so far
    bool time_channel = false, status_channel = false;
};

// The controller's counters as a CPU reads them from the STATUS channel:
// word 0 = {rom_errors, cycles}, then per channel {transfers, retries},
// {abandoned, corrupt}.  The largest totals seen.
struct StatusSeen {
    uint64_t imports = 0, transfers = 0, retries = 0, abandoned = 0, corrupt = 0, rom_errors = 0;
};
extern StatusSeen g_status;

struct BoardCtx {
    int board = 0;
    std::vector<Role> roles;
    uint32_t global_time = 0;   // the newest GlobalTime this CPU has imported ...
    uint64_t global_at = 0;     // ... and its local clock then: a local timer
                                // synchronised to the global time (the paper, section 3.4.1)
    std::mt19937_64 rng;
    int attach_errors = 0;
};

void board_program(SimCpu &cpu);

// Bus cycles of every COPY transfer that publishes a new value to a channel
// with one destination: from the start of its first access (the load of the
// source Actual) to the end of its last (the store of the destination
// Actual), against the protocol's minimum: W loads, W + 1 stores and 5
// control accesses, each access_cycles long.
struct TransferMeter {
    const PlanChannel *c = nullptr;
    bool active = false, published = false;
    uint64_t start = 0, accesses = 0, busy = 0;
    uint64_t n = 0, sum = 0, min = ~0ull, max = 0, idle_sum = 0, accesses_last = 0;

    bool in(int board, uint32_t base, uint32_t size, const SystemSim::BusEvent &e) const {
        return e.board == board && e.addr >= base && e.addr < base + instance_bytes(*c, size);
    }
    void on(const SystemSim::BusEvent &e) {
        const bool src = in(c->src_board, c->src_base, c->size, e);
        const bool dst = in(c->dests[0].board, c->dests[0].base, c->dest_size(), e);
        if (!src && !dst) { active = false; return; }       // another entry: an Old transfer ends
        const bool src_actual = src && !e.we && e.addr == c->src_base;
        if (src_actual && (!active || published)) {
            active = true;
            published = false;
            start = e.start;
            accesses = busy = 0;
        }
        if (!active) return;
        if (!e.ok) { active = false; return; }               // only fault-free transfers
        ++accesses;
        busy += e.end - e.start;
        if (dst && e.we && e.addr == c->dests[0].base) {      // the store of Actual: published
            uint64_t cycles = e.end - start;
            ++n;
            sum += cycles;
            min = std::min(min, cycles);
            max = std::max(max, cycles);
            idle_sum += cycles - busy;
            accesses_last = accesses;
            published = true;
            active = false;
        }
    }
};

// The RAM image of every channel instance (four-slot: four buffers, Slot0 =
// Slot1 = 0): Actual = ReadLocked = Buffer1,
// Buffer1 holds value 0 (sources) or zeros (destinations).
void load_images(const Plan &plan);

// The ROM image holds entry k (its header's entry count is above k).
bool entry_exists(const std::string &rom, int k);

}  // namespace tbsys
