// mobot_sim_modes.cpp -- schedule modes in sim/mobot_sim.cpp: the
// controller's running mode over time (the probe mode_o of sim/pico_boards.v),
// each switch's latency from the request that caused it against the
// compiler's switch_latency, and the age bound in force (docs/robot.md
// "Modes").
// The bound at controller time t: outside the settling window of a switch,
// the bound of the mode in force (none if it does not carry the channel).
// Within the window [S, S + C + b) after a switch at S to a mode of cycle C
// and bound b, the age can only have grown since S: bound_old + (t - S), where
// bound_old is the bound of the mode before (none if that mode did not carry
// the channel: a channel that comes back is judged once its window ends).
#include <algorithm>
#include <cstdio>
#include <string>
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
    if (m == 0 && switches.empty()) return;  // the start-up mode (its since: the first cycle)
    for (ModeSwitch &s : switches)
        if (s.to == m && uint32_t(s.time) == since) {
            s.published = true;
            s.since = since;
            return;
        }
    ++bad_since;
}

bool ModeTrack::bound_at(const PlanChannel &c, uint64_t gap, uint64_t t, uint64_t &bound) const
{
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
    if (!in(last->from, b_old)) return false;
    bound = b_old + (t - last->time);
    return true;
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
