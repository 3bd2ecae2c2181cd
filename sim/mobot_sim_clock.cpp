// mobot_sim_clock.cpp -- local time in the robot simulation (sim/mobot_sim.cpp,
// docs/robot.md "Local time between updates"): each board's alb_clock
// estimates (MOBOT_EV_CLOCK, sim/firmware/mobot_check.h) against the
// controller's time in the clock of the estimate's own TIMER read (the
// board's last one before the event, sim/pico_boards.v timer_rd_o), the
// bounds and verdict of the check "clock", and the report.
// Rules: the error is signed, estimate - controller time, in controller
// clocks; only estimates made with the rate known (alb_clock_state RATE)
// are judged; a board that reported no estimate (firmware without the
// clock) is not judged; one that reported some but none with the rate by
// kClockSyncCycles fails.
// Bounds, per board (A the time channel's age bound, the compiler's latency
// with retries from taken_at to the Import's final load of Actual; I the
// board's longest GlobalTime Import, measured; T its longest gap between two
// New GlobalTime values, measured):
//   lag  = controller - estimate <= A + I + kClockTail + kClockRho * T
//   lead = estimate - controller <= kClockRho * (2 * kClockWindow + T)
// Each sample lags by at most A + I + kClockTail (the sync reads TIMER right
// after the Import and its event); the estimate is lifted to every sample
// above it and otherwise drifts by the rate residual kClockRho; every anchor
// is a sample (a lower bound) at most two windows and one gap old, so the
// estimate leads only through the rate residual.  kClockRho is the rate
// tolerance that tb/clock/test_clock.c checks the estimator against.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>
#include "mobot_sim.h"

namespace {
const double kClockRho = 250e-6;     // rate residual (global per local tick - 1), tolerated
const double kClockWindow = 65536;   // ALB_CLOCK_WINDOW, local ticks
const double kClockTail = 64;        // clocks from the Import's event to the sync's TIMER read
const uint64_t kClockSyncCycles = 4 * 65536;  // the rate must be known by then
}  // namespace

void LocalClock::read(uint64_t now, uint32_t value, uint64_t cycle)
{
    last_read_time = now;
    last_read_value = value;
    if (!reads++) { first_read_cycle = cycle; first_read_value = value; }
    last_read_cycle = cycle;
}

void LocalClock::new_time(uint64_t cycle)
{
    if (last_new_time) max_new_gap = std::max(max_new_gap, cycle - last_new_time);
    last_new_time = cycle;
}

void LocalClock::estimate(uint32_t state, uint32_t cyc, uint32_t arg, uint64_t cycle)
{
    const int64_t err = int64_t(int32_t(arg - uint32_t(last_read_time)));
    const int64_t mag = err < 0 ? -err : err;
    ++estimates;
    now_cycles.add(cyc & 0xfffu);
    if (cyc >> 12) sync_cycles.add(cyc >> 12);
    if (state >= 2) {  // ALB_CLOCK_RATE
        if (!synced++) { first_synced_cycle = cycle; err_min = err_max = err; }
        err_min = std::min(err_min, err);
        err_max = std::max(err_max, err);
        err_sum += double(err);
        abs_sum += double(mag);
    } else {
        ++warmup;
        if (mag > (warm_worst < 0 ? -warm_worst : warm_worst)) warm_worst = err;
    }
}

void clock_bounds(LocalClock clocks[NB], const std::vector<Series> &series, const Plan &plan)
{
    const PlanChannel *t = nullptr;
    for (const PlanChannel &ch : plan.channels)
        if (ch.kind == "time") t = &ch;
    for (int c = 0; c < NB; ++c) {
        LocalClock &k = clocks[c];
        double import_max = 0;
        for (const Series &s : series)
            if (t && s.ch == t && s.board == c) import_max = double(s.import_cycles.max);
        k.lag_bound = t ? double(t->latency_retry) + import_max + kClockTail + kClockRho * double(k.max_new_gap) : 0;
        k.lead_bound = kClockRho * (2 * kClockWindow + double(k.max_new_gap));
    }
}

bool clock_verdict(const LocalClock &k, int board, const Options &o, const Plan &plan, uint64_t cycle, std::string &msg)
{
    char b[400];
    const double lag = o.clock_scale * k.lag_bound, lead = o.clock_scale * k.lead_bound;
    if (!k.estimates || k.lag_bound == 0) return true;
    if (k.synced && (double(-k.err_min) > lag || double(k.err_max) > lead)) {
        std::snprintf(b, sizeof b, "expected every local-time estimate of %s within [-%.0f, +%.0f] clocks of the "
                      "controller's time, got %lld..%lld over %llu estimates (drift %ld ppm)",
                      plan.board_names[board].c_str(), lag, lead, (long long)k.err_min, (long long)k.err_max,
                      (unsigned long long)k.synced, o.drift_ppm[board]);
        msg = b;
        return false;
    }
    if (!k.synced && cycle >= kClockSyncCycles) {
        std::snprintf(b, sizeof b, "expected %s's local clock to have its rate after %llu cycles, it reported "
                      "%llu estimates, none with it", plan.board_names[board].c_str(), (unsigned long long)cycle,
                      (unsigned long long)k.estimates);
        msg = b;
        return false;
    }
    return true;
}

std::string clock_report(const LocalClock clocks[NB], const Options &o, const Plan &plan)
{
    std::printf("  %-11s %8s %9s %9s %8s %9s %9s %9s %9s %9s %7s %8s %9s %13s\n", "local time", "drift", "measured",
                "estimates", "synced", "err min", "err mean", "err max", "|err| max", "|err| mean", "lag bnd",
                "lead bnd", "warm-up", "cyc now/sync");
    std::string js = "[";
    for (int c = 0; c < NB; ++c) {
        const LocalClock &k = clocks[c];
        const double span = double(k.last_read_cycle - k.first_read_cycle);
        const double measured = span > 0 ? (double(uint32_t(k.last_read_value - k.first_read_value)) / span - 1) * 1e6 : 0;
        const int64_t worst = std::max(-k.err_min, k.err_max);
        const double mean = k.synced ? k.err_sum / double(k.synced) : 0, amean = k.synced ? k.abs_sum / double(k.synced) : 0;
        std::printf("  %-11s %+8ld %+9.1f %9llu %8llu %9lld %9.1f %9lld %9lld %9.1f %7.0f %8.0f %9lld %6.0f/%6.0f\n",
                    plan.board_names[c].c_str(), o.drift_ppm[c], measured, (unsigned long long)k.estimates,
                    (unsigned long long)k.synced, (long long)k.err_min, mean, (long long)k.err_max, (long long)worst,
                    amean, o.clock_scale * k.lag_bound, o.clock_scale * k.lead_bound, (long long)k.warm_worst,
                    k.now_cycles.mean(), k.sync_cycles.mean());
        JsonReport e;
        e.str("board", plan.board_names[c]).num("drift_ppm", double(o.drift_ppm[c])).num("measured_ppm", measured)
         .num("timer_reads", double(k.reads)).num("estimates", double(k.estimates)).num("synced", double(k.synced))
         .num("first_synced_cycle", double(k.first_synced_cycle)).num("err_min", double(k.err_min))
         .num("err_mean", mean).num("err_max", double(k.err_max)).num("abs_err_max", double(worst))
         .num("abs_err_mean", amean).num("lag_bound", k.lag_bound).num("lead_bound", k.lead_bound)
         .num("max_sync_gap", double(k.max_new_gap)).num("clock_scale", o.clock_scale)
         .num("warmup_estimates", double(k.warmup)).num("warmup_worst_err", double(k.warm_worst))
         .raw("now_cycles", k.now_cycles.json()).raw("sync_cycles", k.sync_cycles.json());
        std::string t = e.text();
        js += (js.size() > 1 ? ",\n  " : "\n  ") + t.substr(0, t.size() - 1);
    }
    return js + "]";
}
