// system_modes.cpp -- see system_modes.h.
#include "system_modes.h"
#include <algorithm>
#include <cstdio>
extern "C" {
#include "albatross_layout.h"
}

namespace tbsys {

ModeWatch *g_modes = nullptr;

namespace {
std::string name_of(const Plan &plan, int m)
{
    return m >= 0 && m < static_cast<int>(plan.modes.size()) ? plan.modes[m].name : "undeclared mode " + std::to_string(m);
}
}  // namespace

ModeWatch::ModeWatch(const Plan &plan, SystemSim &sim) : plan_(plan), sim_(sim)
{
    for (const PlanMode &m : plan.modes) c_max_ = std::max(c_max_, m.cycle);
    for (const PlanChannel &c : plan.channels)
        if (c.id == plan.mode_request) {
            req_board_ = c.src_board;
            req_actual_ = c.src_base + ALB_OFF_ACTUAL;
        }
    if (active()) last_actual_ = sim_.ref[req_board_].byte(req_actual_);
}

uint32_t ModeWatch::pick(std::mt19937_64 &rng)
{
    const uint32_t n = static_cast<uint32_t>(plan_.modes.size()), r = static_cast<uint32_t>(rng() % 16);
    return r == 0 ? 15u - static_cast<uint32_t>(rng() % (16 - n)) : r % n;   // 1 in 16: undeclared
}

uint64_t ModeWatch::interval(std::mt19937_64 &rng) const
{
    return 2 * c_max_ + rng() % (8 * c_max_);   // at least two cycles: every request is read
}

void ModeWatch::tick()
{
    if (!active()) return;
    const uint8_t a = sim_.ref[req_board_].byte(req_actual_);
    if (a != last_actual_) {   // the producer's Actual store: the request is there
        last_actual_ = a;
        stores_.push_back({pending_, sim_.time()});
        if (pending_ >= plan_.modes.size()) ++undeclared;
    }
    const int m = static_cast<int>(sim_.mode());
    if (m == mode_) return;
    Switch s;
    s.cycle = sim_.cycle();
    s.time = sim_.time();
    s.from = mode_;
    s.to = m;
    for (auto it = stores_.rbegin(); it != stores_.rend(); ++it)
        if (it->mode == static_cast<uint32_t>(m)) {
            s.requested = true;
            s.request = it->time;
            break;
        }
    s.bound = mode_ < static_cast<int>(plan_.modes.size()) ? plan_.modes[mode_].switch_latency : 0;
    s.bound_at_target = mode_ < static_cast<int>(plan_.modes.size()) ? plan_.modes[mode_].switch_latency_at_target : 0;
    switches_.push_back(s);
    stores_.clear();   // a request is acted on once
    pending_switch_ = false;
    mode_ = m;
}

void ModeWatch::mode_imported(int board, uint32_t mode, uint32_t since)
{
    ++mode_values_;
    bool ok = false;
    if (mode == 0 && (switches_.empty() || since < switches_[0].time)) {
        if (!have_t0_) have_t0_ = true, t0_ = since;
        ok = since == t0_;
    }
    for (const Switch &s : switches_) ok = ok || (s.to == static_cast<int>(mode) && s.time == since);
    if (!ok && !bad_values_++) {
        char b[200];
        std::snprintf(b, sizeof b, "modes: board %d imported Mode {%u, %u}, which names no switch (%zu so far)", board,
                      mode, since, switches_.size());
        first_bad_ = b;
    }
}

void ModeWatch::taken(int chan, uint8_t b, uint32_t t)
{
    const PlanChannel &c = plan_.channels[chan];
    if (!active() || c.id != plan_.mode_request) return;
    // Word 0 of the buffer taken; the controller offers its low 4 bits (15
    // if a higher bit is set) as the mode.
    const uint32_t at = c.src_base + ALB_OFF_BUFFER(static_cast<uint32_t>(b), c.size);
    uint32_t w = 0;
    for (uint32_t k = 0; k < 4; ++k) w |= static_cast<uint32_t>(sim_.ref[c.src_board].byte(at + k)) << (8 * k);
    const uint32_t m = w > 15 ? 15 : w;
    if (pending_switch_ || m == static_cast<uint32_t>(mode_)) return;   // ignored
    if (m >= plan_.modes.size()) rejected_.push_back(t);
    else pending_switch_ = true;
}

void ModeWatch::status_read(uint32_t taken_at, uint64_t corrupt)
{
    if (status_seen_ && taken_at <= status_taken_) return;
    status_seen_ = true;
    status_taken_ = taken_at;
    status_corrupt_ = corrupt;
}

bool ModeWatch::bound(int chan, uint64_t from, uint64_t to, uint64_t &b, uint64_t &b_retry) const
{
    const int id = plan_.channels[chan].id;
    int m = 0;                       // the mode in force at 'to'
    uint64_t last = 0;               // the last switch in (from, to] (0: none)
    for (const Switch &s : switches_) {
        if (s.cycle > to) break;
        m = s.to;
        if (s.cycle > from) last = s.cycle;
    }
    if (m >= static_cast<int>(plan_.modes.size()) || !plan_.modes[m].carries(id)) return ++unjudged_, false;
    // Across switches: the value had not arrived by the last one, S; the mode
    // that starts its first cycle at S carries the channel, so it arrives by S
    // + that mode's bound.
    const uint64_t wait = last ? last - from : 0;
    if (last) ++judged_across_;
    b = wait + plan_.modes[m].bound_ff[id];
    b_retry = wait + plan_.modes[m].bound[id];
    return true;
}

void ModeWatch::settle()
{
    for (Switch &s : switches_)
        if (s.requested) s.latency = s.time - (have_t0_ && t0_ > s.request ? t0_ : s.request);
}

void ModeWatch::finish(bool judge_latency, uint64_t status_corrupt, std::vector<std::string> &failures) const
{
    char b[400];
    uint32_t prev = t0_;
    for (size_t k = 0; k < switches_.size(); ++k) {
        const Switch &s = switches_[k];
        const uint64_t c = s.from < static_cast<int>(plan_.modes.size()) ? plan_.modes[s.from].cycle : 1;
        if (!plan_.sync_mode && (k || have_t0_) && (s.time - prev) % c != 0) {
            std::snprintf(b, sizeof b, "modes: expected the switch to %s at time %u on a cycle boundary of %s "
                          "(%u + a multiple of %llu), it is %llu clocks into a cycle",
                          name_of(plan_, s.to).c_str(), s.time, name_of(plan_, s.from).c_str(), prev,
                          static_cast<unsigned long long>(c), static_cast<unsigned long long>((s.time - prev) % c));
            failures.push_back(b);
        }
        prev = s.time;
        if (!s.requested) {
            std::snprintf(b, sizeof b, "modes: expected the switch to %s at time %u to follow a request for it, none "
                          "was stored", name_of(plan_, s.to).c_str(), s.time);
            failures.push_back(b);
        } else if (judge_latency ? s.latency > s.bound : s.bound_at_target && s.latency > s.bound_at_target) {
            std::snprintf(b, sizeof b, "modes: expected the switch to %s at time %u within the compiler's "
                          "switch_latency%s %llu of the request, it took %llu clocks", name_of(plan_, s.to).c_str(),
                          s.time, judge_latency ? "" : " at its fault hypothesis' target",
                          static_cast<unsigned long long>(judge_latency ? s.bound : s.bound_at_target),
                          static_cast<unsigned long long>(s.latency));
            failures.push_back(b);
        }
    }
    if (bad_values_) failures.push_back(first_bad_);
    if (mode_values_ == 0) failures.push_back("modes: no board imported a Mode value");
    if (status_corrupt > undeclared) {
        std::snprintf(b, sizeof b, "modes: STATUS counts %llu corrupt values, expected at most one per request for an "
                      "undeclared mode (%llu)", static_cast<unsigned long long>(status_corrupt),
                      static_cast<unsigned long long>(undeclared));
        failures.push_back(b);
    }
    // Exact on a fault-free bus: the rejections before the last STATUS read's slot.
    uint64_t before = 0;
    for (uint32_t t : rejected_) before += t < status_taken_;
    if (judge_latency && status_seen_ && status_corrupt_ != before) {
        std::snprintf(b, sizeof b, "modes: STATUS taken at time %u counts %llu corrupt values, expected exactly the "
                      "%llu requests for undeclared modes the controller took (and rejected) before it "
                      "(%zu in the run, %llu stored)", status_taken_, static_cast<unsigned long long>(status_corrupt_),
                      static_cast<unsigned long long>(before), rejected_.size(), static_cast<unsigned long long>(undeclared));
        failures.push_back(b);
    }
    if (judge_latency && !status_seen_) failures.push_back("modes: no CPU read a STATUS value");
}

std::string ModeWatch::json() const
{
    uint64_t worst = 0, worst_bound = 0;   // the switch nearest its bound
    for (const Switch &s : switches_)
        if (s.requested && s.latency * std::max<uint64_t>(worst_bound, 1) >= worst * std::max<uint64_t>(s.bound, 1))
            worst = s.latency, worst_bound = s.bound;
    std::string j = "{\"switches\": [";
    char b[400];
    for (size_t k = 0; k < switches_.size(); ++k) {
        const Switch &s = switches_[k];
        std::snprintf(b, sizeof b, "%s{\"time\": %u, \"from\": \"%s\", \"to\": \"%s\", \"latency\": %llu, \"bound\": %llu, "
                      "\"bound_at_target\": %llu}",
                      k ? ", " : "", s.time, name_of(plan_, s.from).c_str(), name_of(plan_, s.to).c_str(),
                      static_cast<unsigned long long>(s.latency), static_cast<unsigned long long>(s.bound),
                      static_cast<unsigned long long>(s.bound_at_target));
        j += b;
    }
    std::snprintf(b, sizeof b, "], \"switch_latency_worst\": %llu, \"switch_latency_bound\": %llu, "
                  "\"undeclared_requests\": %llu, \"mode_values_imported\": %llu, \"judged_across_a_switch\": %llu, "
                  "\"not_judged\": %llu, \"rejected\": %zu, \"status_corrupt\": %llu}",
                  static_cast<unsigned long long>(worst), static_cast<unsigned long long>(worst_bound),
                  static_cast<unsigned long long>(undeclared), static_cast<unsigned long long>(mode_values_),
                  static_cast<unsigned long long>(judged_across_), static_cast<unsigned long long>(unjudged_),
                  rejected_.size(), static_cast<unsigned long long>(status_corrupt_));
    return j + b;
}

}  // namespace tbsys
