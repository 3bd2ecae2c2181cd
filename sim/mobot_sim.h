// mobot_sim.h -- what sim/mobot_sim.cpp shares with sim/mobot_sim_options.cpp,
// sim/mobot_sim_ages.cpp and sim/mobot_sim_clock.cpp: the checks' names, the
// options, the statistics, the option parsing, the ages CSV and local time.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>
#include "plan.h"
#include "report.h"

const int NB = 4;
enum : uint32_t { EV_NEW = 1, EV_OLD, EV_ERROR, EV_BEGIN, EV_EXPORT, EV_STALE, EV_FRESH, EV_STATUS, EV_CLOCK };
const char *const kChecks[] = {"cpu", "liveness", "age", "staleness", "faults", "clock"};

struct Options {
    std::string plan, report, ages, trace, label = "mobot-sim", expect, crash_arg, hang_arg, drift_arg;
    uint64_t cycles = 2000000, seed = 1, stall = 0, trace_from = 0, trace_cycles = 20000, progress = 10;
    double fault_rate = 0, age_scale = 1;
    int crash_board = -1, hang_board = -1;
    bool require_done = false;
    uint64_t crash_at = 0, hang_at = 0;
    long drift_ppm[NB] = {0, 0, 0, 0};  // --drift-ppm: each board's clock against the controller's
    double clock_scale = 1;             // --clock-scale: check the local-time error against X times its bound
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

struct Series {  // one channel at one consumer
    const PlanChannel *ch = nullptr;
    int board = 0;
    uint32_t base = 0;  // byte offset of the instance in the consumer's RAM
    Stat age, import_cycles;
    uint64_t news = 0, olds = 0, news_after_crash = 0, over_bound = 0, bound = 0;
    std::vector<uint64_t> bucket_max;  // worst age per time bucket (picture)
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
// The --ages CSV (sim/mobot_sim_ages.cpp); false if it cannot be written.
bool write_ages(const std::string &path, const std::vector<Series> &series, const Plan &plan, uint64_t n_buckets,
                uint64_t bucket_len, uint64_t cycle, uint64_t crash_cycle, uint64_t first_stale);
