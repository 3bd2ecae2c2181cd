// mobot_sim.h -- what sim/mobot_sim.cpp shares with sim/mobot_sim_options.cpp,
// sim/mobot_sim_ages.cpp and sim/mobot_sim_clock.cpp: the checks' names, the
// options, the statistics, the option parsing, the ages CSV, Import
// termination and local time.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>
#include "plan.h"
#include "report.h"

const int NB = 4;
const int DP_MAX_WORDS = 4096;  // the largest DPRAM the harness tracks (pico_boards' ADDR_WIDTH <= 12)
enum : uint32_t { EV_NEW = 1, EV_OLD, EV_ERROR, EV_BEGIN, EV_EXPORT, EV_STALE, EV_FRESH, EV_STATUS, EV_CLOCK, EV_MODE };
const char *const kChecks[] = {"cpu", "liveness", "age", "staleness", "faults", "clock", "termination", "mode",
                               "freshness"};

struct Options {
    std::string age_samples;  // --age-samples FILE: every imported age (CSV, tools/fault_rates.py)
    std::string plan, report, ages, trace, label = "mobot-sim", expect, crash_arg, hang_arg, drift_arg, mute_arg;
    uint64_t cycles = 2000000, seed = 1, stall = 0, trace_from = 0, trace_cycles = 20000, progress = 10;
    double fault_rate = 0, age_scale = 1, burst = 0;   // burst 0: independent accesses (tb/common/fault_model.h)
    int crash_board = -1, hang_board = -1;
    int mute_board = -1, mute_word = -1;  // --mute: the destination control word whose stores are lost
    bool require_done = false;
    uint64_t min_switches = 0;          // --min-switches N: fail on fewer mode switches (check mode)
    double switch_scale = 1;            // --switch-scale: check switch latencies against X times the bound
    bool fault_per_clock = false;       // --fault-clocking clock: the old, wrong injector (negative test)
    uint64_t crash_at = 0, hang_at = 0;
    long drift_ppm[NB] = {0, 0, 0, 0};  // --drift-ppm: each board's clock against the controller's
    double clock_scale = 1;             // --clock-scale: check the local-time error against X times its bound
    double term_scale = 1;              // --termination-scale: check passes/accesses against X times the bound
};

struct Stat {  // min / mean / max of a series of integers
    uint64_t n = 0, min = 0, max = 0;
    double sum = 0;
    void add(uint64_t v) {
        min = n ? std::min(min, v) : v;
        max = n ? std::max(max, v) : v;
        sum += double(v);
        ++n;
    }
    double mean() const { return n ? sum / double(n) : 0; }
    std::string json() const {
        JsonReport r;
        r.num("n", double(n)).num("min", double(min)).num("mean", mean()).num("max", double(max));
        std::string t = r.text();
        return t.substr(0, t.size() - 1);
    }
};

struct Termination {  // one series' Imports against the compiler's termination bound
    bool known = false;                                 // the compiler bounded it (report.txt)
    uint64_t D = 0, T = 0, V = 0, max_passes = 0, max_accesses = 0;  // compiler's figures (controller clocks)
    // the Import in progress: accesses of the core to the instance since its last event
    uint32_t passes = 0, accesses = 0, loads = 0;
    uint64_t last_load = 0, first_gap = 0, max_gap = 0;
    // over the run (the core's first Import, whose window holds the attach, is left out)
    Stat passes_all, accesses_all;                       // every Import
    std::vector<uint64_t> hist;                          // passes per Import: count of 0, 1, 2, ...
    uint64_t judged = 0, outside = 0, over = 0;          // Imports within T and V; beyond them; over the bound
    uint64_t worst_passes = 0, worst_accesses = 0;       // worst of the judged Imports
    uint64_t t_max = 0, v_max = 0;                       // measured loop gaps (clocks), every Import
    uint64_t worst_over_passes = 0, worst_over_accesses = 0, worst_over_cycle = 0;
    uint64_t unfinished = 0, worst_beyond_passes = 0;    // an Import over the bound at the end; passes beyond T, V
    void access(bool write, bool control, uint32_t sel, uint64_t cycle);  // one acked access to the instance
    // its Import's event: judge (every Import with judge_all, else those within T and V) and count
    void import_done(double scale, uint64_t cycle, bool judge_all);
    void finish(double scale, uint64_t cycle, bool judge_all);  // the end of the run: the Import in progress
    void reset() { passes = accesses = loads = 0; first_gap = max_gap = 0; }
};

struct Series {  // one channel at one consumer
    const PlanChannel *ch = nullptr;
    int board = 0;
    uint32_t base = 0;  // byte offset of the instance in the consumer's RAM
    Stat age, import_cycles;
    uint64_t news = 0, olds = 0, news_after_crash = 0, over_bound = 0, bound = 0;
    uint64_t worst_over = 0, worst_over_bound = 0;  // the sample furthest over its bound: age, bound
    uint64_t unjudged = 0;             // samples no bound applies to (a mode without the channel, settling)
    Stat judged_age;                   // the samples judged against a bound (the console row; age: all samples)
    uint64_t worst_pm = 0;             // the worst judged age / bound, per mille
    uint64_t worst_pm_age = 0, worst_pm_bound = 0;  // ... that sample's age and bound in force
    uint64_t settling = 0, comeback = 0;  // samples judged in a window after a switch (how 1, how 2 of bound_at)
    Stat comeback_age;                 // the ages judged after the channel came back (how 2)
    uint64_t comeback_pm = 0, comeback_pm_age = 0, comeback_pm_bound = 0;  // their worst age / bound
    uint64_t fresh_judged = 0, fresh_late = 0;  // check freshness: Imports judged, those that returned older
    std::string fresh_first;           // ... the first of those
    uint64_t last_import = 0, max_import_gap = 0;  // the consumer's Imports of it: the longest gap (cycles)
    std::vector<uint64_t> bucket_max;  // worst age per time bucket (picture)
    std::vector<uint64_t> bucket_bound;  // the largest bound a sample in the bucket was judged by (0: none)
    Termination term;
    // One judged age sample (time bucket k) against the bound in force;
    // a crashed producer's channel counts toward no verdict (its ages grow).
    // comeback: judged after the channel came back (bound_at's how 2): kept
    // out of the row's figures (judged_age, worst_pm), in comeback_age and
    // comeback_pm, and judged like any sample.
    void judge(uint64_t age, uint64_t bound, uint64_t k, double scale, bool crashed, bool comeback = false);
};

struct LocalClock {  // one board's local time (alb_clock): its estimates against the controller's time
    uint64_t reads = 0, estimates = 0, synced = 0, warmup = 0, first_synced_cycle = 0;
    uint64_t last_read_time = 0, first_read_cycle = 0, last_read_cycle = 0;
    uint32_t last_read_value = 0, first_read_value = 0;
    int64_t err_min = 0, err_max = 0, warm_worst = 0;  // signed: estimate - controller time (with the rate)
    double err_sum = 0, abs_sum = 0;
    double lag_bound = 0, lead_bound = 0;          // clock_bounds
    Stat now_cycles, sync_cycles;  // rdcycle counts of alb_clock_now and of the last alb_clock_sync
    uint64_t last_new_time = 0, max_new_gap = 0;  // New GlobalTime Imports: the longest gap (clocks)
    void read(uint64_t now, uint32_t value, uint64_t cycle);  // a TIMER read completed at controller time now
    void new_time(uint64_t cycle);                              // a New GlobalTime Import (a sync)
    void estimate(uint32_t state, uint32_t cyc, uint32_t arg, uint64_t cycle);  // MOBOT_EV_CLOCK
};

struct Producer {  // a copy channel's producer
    const PlanChannel *ch = nullptr;
    Stat export_cycles;
    uint64_t exports = 0, stores = 0, last_store = 0, max_gap = 0;
    uint64_t first_store = 0;  // the cycle of its first store (the gap from reset)
    std::vector<uint64_t> store_times;  // the controller's time of each Actual store (check freshness)
    // The longest gap between its Actual stores up to cycle, the one still
    // open and the one from reset to the first included: a gap that holds a
    // value's age.
    uint64_t gap_so_far(uint64_t cycle) const { return std::max({max_gap, first_store, cycle - last_store}); }
};

// Schedule modes (sim/mobot_sim_modes.cpp): the controller's running mode
// over time (its probe mode_o), each switch with the request that caused it,
// the Mode values the boards imported, and the age bound in force.
struct ModeSwitch {
    uint64_t time = 0, cycle = 0;      // controller time and run cycle of the first clock in the new mode
    int from = 0, to = 0;
    bool requested = false;            // a ModeRequest store came before it (since the switch before)
    uint64_t latency = 0, bound = 0;   // its last store -> time; the compiler's switch_latency of 'from'
    bool published = false;            // a board imported Mode {to, since} ...
    uint64_t since = 0;                // ... with this since
};
struct ModeTrack {
    const Plan *plan = nullptr;
    int mode = 0;                          // the mode in force now
    std::vector<ModeSwitch> switches;
    bool request_seen = false;             // a ModeRequest store since the last switch
    uint64_t request_time = 0;             // controller time of its last one
    uint64_t mode_events = 0, bad_since = 0;  // Mode values imported; those naming no switch
    void observe(int m, uint64_t now, uint64_t cycle);       // every clock: the probe
    void request(uint64_t now);                              // ModeRequest's producer stored Actual
    void published(int m, uint32_t since);                   // MOBOT_EV_MODE
    // The age bound at controller time t of channel id (a copy's producer gap
    // added); false: not judged (the mode in force, or the one before within
    // its settling, carries no such channel).
    // how (if given): 0 the bound of the mode in force, 1 in the window after
    // a switch from a mode that carries it (that mode's bound + t - S), 2 in
    // the window after it comes back (the bound before S1 + t - S1).
    bool bound_at(const PlanChannel &c, uint64_t gap, uint64_t t, uint64_t &bound, int *how = nullptr) const;
    // Some mode in force during [t0, t1] carries no channel id.
    bool absent_during(int id, uint64_t t0, uint64_t t1) const;
    std::string report(const std::string &indent) const;    // the JSON array of switches
    // The failures (check, message) of check "mode" and of the modes' part of
    // "staleness" at the end of a run; judge_latency: a fault-free run;
    // crash_cycle: a producer crashed then (0: none); long_run: a stay without
    // RadarMap longer than this must see navigation report it stale.
    std::vector<std::pair<std::string, std::string>> verdict(const Options &o, uint64_t cycle, uint64_t time_now,
                                                             bool judge_latency, bool cpu_failed,
                                                             uint64_t stale_in_mode, uint64_t crash_cycle,
                                                             uint64_t long_run) const;
    // The console lines; the switch nearest its bound (latency, bound).
    void summary(uint64_t stale_in_mode, uint64_t &worst, uint64_t &worst_bound) const;
};

// The command line (sim/mobot_sim_options.cpp): fills o, loads plan, splits
// --expect-caught-by into expect.  Returns -1 to run, else the exit status.
int parse_options(int argc, char **argv, Options &o, Plan &plan, std::vector<std::string> &expect);
int usage(const char *msg);
std::string code_text(uint32_t code, const Plan &plan);
// Local time (sim/mobot_sim_clock.cpp): each board's lag and lead bounds,
// the verdict of the check "clock" (false with msg), the console table and
// the report's local_time array.
void clock_bounds(LocalClock clocks[NB], const std::vector<Series> &series, const Plan &plan);
bool clock_verdict(const LocalClock &k, int board, const Options &o, const Plan &plan, uint64_t cycle, std::string &msg);
std::string clock_report(const LocalClock clocks[NB], const Options &o, const Plan &plan);
// Import termination (sim/mobot_sim_ages.cpp): the compiler's bounds from
// report.txt beside the plan (returns how many series got one), the console
// table and the series' JSON object.
int load_termination(const std::string &plan_path, std::vector<Series> &series, const Plan &plan);
void print_termination(const std::vector<Series> &series, const Plan &plan, const Options &o);
// The end of a run (sim/mobot_sim_ages.cpp): the failures of check
// "termination" (every judged Import within the compiler's bound; without
// --stall every loop within its T and V; the Import in progress judged by
// its passes so far) and of check "age" (each series' samples over their bound).
std::vector<std::string> termination_failures(std::vector<Series> &series, const Plan &plan, const Options &o,
                                              uint64_t cycle, const bool seen_event[NB]);
std::vector<std::string> age_failures(const std::vector<Series> &series, const Plan &plan, const Options &o);
std::string termination_json(const Termination &t);
// The end of a run (sim/mobot_sim_report.cpp): the series' and the producers'
// console tables, each returning its JSON array, and the verdict ("pass" or
// "fail") from the failed checks (check -> first failure) and, for a negative
// test (positive false), the checks that must fail; last is the closing line,
// lines the failures to print.
// The boards' state at the end of a run, and the failures (check, message)
// of checks "cpu" and "liveness" it shows; cpu_failed: a core failed its own
// check (its consumers starve: their liveness is left to cpu).
struct BoardsAtEnd {
    uint32_t done, trap, bus_err;  // a bit per board
    uint32_t code[NB];             // exit codes (TOHOST)
    bool error;                    // the controller's error_o ...
    unsigned rom_errors;           // ... and its rom_errors_o
    uint64_t last_event[NB];       // each board's last event (cycle)
};
std::vector<std::pair<std::string, std::string>> board_failures(const BoardsAtEnd &e, const Plan &plan, const Options &o,
                                                                uint64_t cycle, bool &cpu_failed);
std::string series_report(const std::vector<Series> &series, const Plan &plan);
std::string producers_report(const std::map<int, Producer> &producers, const Plan &plan);
// The checks as a JSON object, each "pass" or "fail" (sim/mobot_sim_report.cpp).
std::string checks_report(const std::map<std::string, std::string> &failed);
std::string judge(const std::map<std::string, std::string> &failed, const std::vector<std::string> &expect,
                  bool positive, std::string &last, std::vector<std::string> &lines);
// Check freshness (sim/mobot_sim_ages.cpp), at a consumer's Import of a copy
// channel that began (its first load of the control word) at controller time
// t_start and returned a value taken at taken_at: the producer's newest value
// that stayed its newest for longer than the bound in force (modes: the age
// bound at t_start, without the producer's gap) and whose bound had run out
// by t_start, published from 'from' on, must be what it returned or older
// than it: taken_at at or after that value's Actual store.
void judge_fresh(Series &s, const Producer &p, const ModeTrack &modes, const std::string &consumer, uint64_t t_start,
                 uint64_t taken_at, uint64_t from);
// The --ages CSV (sim/mobot_sim_ages.cpp); false if it cannot be written.
bool write_ages(const std::string &path, const std::vector<Series> &series, const Plan &plan, uint64_t n_buckets,
                uint64_t bucket_len, uint64_t cycle, uint64_t crash_cycle, uint64_t first_stale);
