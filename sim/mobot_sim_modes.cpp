// mobot_sim_modes.cpp -- schedule modes in sim/mobot_sim.cpp: the
// controller's running mode over time (the probe mode_o of sim/pico_boards.v),
// each switch's latency from the request that caused it against the
// compiler's switch_latency, and the age bound in force (docs/robot.md
// "Modes").
// The bound at controller time t: outside the settling window of a switch,
// the bound of the mode in force (none if it does not carry the channel).
// Within the window [S, S + C + b) after a switch at S to a mode of cycle C
// and bound b, the age can only have grown since S: bound_old + (t - S), where
// bound_old is the bound of the mode before.  A channel that comes back (the
// mode before did not carry it) is judged in its window by the bound in force
// just before S1, the end of the last stay in a mode that carried it, plus
// t - S1: the consumer's newest value then was within that bound, and what it
// imports later is that value or a newer one (a value in fragments cut by
// the switch at S1 goes on after the return, taken_at from its first
// fragment before S1: newer than the consumer's newest at S1, so within the
// same bound).  A channel no earlier mode carried is not judged in its window.
#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>
#include "mobot_sim.h"

void ModeTrack::observe(int m, uint64_t now, uint64_t cycle)
{
    if (m == mode || plan->modes.empty()) return;
    ModeSwitch s;
    s.time = now;
    s.cycle = cycle;
    s.from = mode;
    s.to = m;
    s.requested = request_seen;
    s.latency = request_seen ? now - request_time : 0;
    s.bound = mode < int(plan->modes.size()) ? plan->modes[mode].switch_latency : 0;
    switches.push_back(s);
    mode = m;
    request_seen = false;
}

void ModeTrack::request(uint64_t now)
{
    request_seen = true;
    request_time = now;
}

void ModeTrack::published(int m, uint32_t since)
{
    ++mode_events;
    // the start-up mode (its since: the first cycle, before any switch), also
    // when imported after a switch (published before it: a Mode published
    // once in many minor cycles, or delayed by faults, reaches a board late)
    if (m == 0 && (switches.empty() || since < uint32_t(switches[0].time))) return;
    for (ModeSwitch &s : switches)
        if (s.to == m && uint32_t(s.time) == since) {
            s.published = true;
            s.since = since;
            return;
        }
    ++bad_since;
}

bool ModeTrack::bound_at(const PlanChannel &c, uint64_t gap, uint64_t t, uint64_t &bound, int *how) const
{
    if (how) *how = 0;
    const uint64_t extra = c.copy() ? gap : 0;
    if (plan->modes.empty()) {
        bound = c.latency_retry + extra;
        return true;
    }
    auto in = [&](int m, uint64_t &b) {
        if (m >= int(plan->modes.size()) || !plan->modes[m].carries(c.id)) return false;
        b = plan->modes[m].bound[c.id] + extra;
        return true;
    };
    // the last switch at or before t
    const ModeSwitch *last = nullptr;
    for (const ModeSwitch &s : switches) {
        if (s.time > t) break;
        last = &s;
    }
    uint64_t b_now = 0;
    if (!in(last ? last->to : 0, b_now)) return false;
    if (!last || t >= last->time + plan->modes[last->to].cycle + b_now) {
        bound = b_now;
        return true;
    }
    uint64_t b_old = 0;
    if (in(last->from, b_old)) {
        bound = b_old + (t - last->time);
        if (how) *how = 1;
        return true;
    }
    // The channel comes back: the end S1 of the last stay in a mode that carried it.
    for (size_t k = size_t(last - switches.data()) + 1; k-- > 0;) {
        const ModeSwitch &s = switches[k];
        if (!in(s.from, b_old)) continue;
        if (s.time == 0 || !bound_at(c, gap, s.time - 1, b_old)) return false;
        bound = b_old + (t - s.time);
        if (how) *how = 2;
        return true;
    }
    return false;
}

bool ModeTrack::absent_during(int id, uint64_t t0, uint64_t t1) const
{
    if (plan->modes.empty()) return false;
    for (size_t k = 0; k <= switches.size(); ++k) {
        const uint64_t from = k ? switches[k - 1].time : 0, to = k < switches.size() ? switches[k].time : ~0ull;
        const int m = k ? switches[k - 1].to : 0;
        if (from <= t1 && to >= t0 && !(m < int(plan->modes.size()) && plan->modes[m].carries(id))) return true;
    }
    return false;
}

std::string ModeTrack::report(const std::string &indent) const
{
    std::string j = "[";
    char b[320];
    auto name = [&](int m) { return m < int(plan->modes.size()) ? plan->modes[m].name : "mode" + std::to_string(m); };
    for (size_t k = 0; k < switches.size(); ++k) {
        const ModeSwitch &s = switches[k];
        std::snprintf(b, sizeof b,
                      "%s\n%s{\"time\": %llu, \"cycle\": %llu, \"from\": \"%s\", \"to\": \"%s\", \"requested\": %s, "
                      "\"latency\": %llu, \"bound\": %llu, \"published\": %s}",
                      k ? "," : "", indent.c_str(), (unsigned long long)s.time, (unsigned long long)s.cycle,
                      name(s.from).c_str(), name(s.to).c_str(), s.requested ? "true" : "false",
                      (unsigned long long)s.latency, (unsigned long long)s.bound, s.published ? "true" : "false");
        j += b;
    }
    return j + "]";
}

// A mode without RadarMap long enough for navigation's threshold
// (MOBOT_RADAR_SCAN_CLOCKS and the latency, about 20,500 clocks; long_run), entered
// before any crash, is seen stale; every switch came from a request within the compiler's
// switch_latency of the mode it left, and reached the boards as Mode with
// its time.
std::vector<std::pair<std::string, std::string>> ModeTrack::verdict(const Options &o, uint64_t cycle, uint64_t time_now,
                                                                    bool judge_latency, bool cpu_failed,
                                                                    uint64_t stale_in_mode, uint64_t crash_cycle,
                                                                    uint64_t long_run) const
{
    std::vector<std::pair<std::string, std::string>> out;
    char b[512];
    auto name = [&](int m) { return m < int(plan->modes.size()) ? plan->modes[m].name : "mode" + std::to_string(m); };
    uint64_t long_absences = 0;
    if (const PlanChannel *radar = plan->by_name("RadarMap"); radar && !plan->modes.empty())
        for (size_t k = 0; k < switches.size(); ++k) {
            const ModeSwitch &sw = switches[k];
            const uint64_t end = k + 1 < switches.size() ? switches[k + 1].time : time_now;
            // (after a crash of its producer the map is stale already: no new report)
            if (!(sw.to < int(plan->modes.size()) && plan->modes[sw.to].carries(radar->id)) && end - sw.time > long_run &&
                !(crash_cycle && sw.cycle >= crash_cycle))
                ++long_absences;
        }
    if (long_absences && stale_in_mode < long_absences && !cpu_failed) {
        std::snprintf(b, sizeof b, "expected navigation to report RadarMap stale in each of the %llu long runs of a mode "
                      "without it, it did %llu times", (unsigned long long)long_absences, (unsigned long long)stale_in_mode);
        out.emplace_back("staleness", b);
    }
    if (switches.size() < o.min_switches) {
        std::snprintf(b, sizeof b, "expected at least %llu mode switches, got %zu", (unsigned long long)o.min_switches,
                      switches.size());
        out.emplace_back("mode", b);
    }
    for (const ModeSwitch &sw : switches) {
        const bool near_end = sw.cycle + 4 * plan->cycle > cycle;  // its Mode may not be imported yet
        if (!sw.requested)
            std::snprintf(b, sizeof b, "expected each mode switch to follow a request, the one to %s at time %llu "
                          "did not", name(sw.to).c_str(), (unsigned long long)sw.time);
        else if (judge_latency && double(sw.latency) > o.switch_scale * double(sw.bound))
            std::snprintf(b, sizeof b, "expected each switch within %.4g x the compiler's switch_latency, the one to "
                          "%s at time %llu took %llu clocks from the request against %llu", o.switch_scale,
                          name(sw.to).c_str(), (unsigned long long)sw.time, (unsigned long long)sw.latency,
                          (unsigned long long)sw.bound);
        else if (!sw.published && !near_end && !cpu_failed)
            std::snprintf(b, sizeof b, "expected navigation to import Mode {%s, %llu} after the switch, it did not",
                          name(sw.to).c_str(), (unsigned long long)sw.time);
        else
            continue;
        out.emplace_back("mode", b);
    }
    if (bad_since) {
        std::snprintf(b, sizeof b, "expected every Mode value imported to name a switch (mode and its time), %llu did not",
                      (unsigned long long)bad_since);
        out.emplace_back("mode", b);
    }
    return out;
}

void ModeTrack::summary(uint64_t stale_in_mode, uint64_t &worst, uint64_t &worst_bound) const
{
    worst = worst_bound = 0;
    for (const ModeSwitch &sw : switches)
        if (sw.requested && sw.latency * std::max<uint64_t>(worst_bound, 1) >= worst * std::max<uint64_t>(sw.bound, 1))
            worst = sw.latency, worst_bound = sw.bound;
    std::printf("  modes: %zu switches", switches.size());
    for (const ModeSwitch &sw : switches)
        std::printf("%s %s at %.3f ms (%llu clocks after the request, bound %llu)", &sw == &switches[0] ? ":" : ",",
                    sw.to < int(plan->modes.size()) ? plan->modes[sw.to].name.c_str() : "?",
                    1e3 * double(sw.time) / plan->clock_hz, (unsigned long long)sw.latency, (unsigned long long)sw.bound);
    std::printf("\n  modes: worst switch latency %llu clocks against the bound %llu (%.2f); RadarMap stale %llu "
                "times in a mode without it\n", (unsigned long long)worst, (unsigned long long)worst_bound,
                worst_bound ? double(worst) / double(worst_bound) : 0.0, (unsigned long long)stale_in_mode);
}
