// system_freshness.cpp -- SystemChecker::tick, the freshness check
// (system_checker.h): the paper's actuality judged at the destinations.
// A copy channel's newest source value v, published (its producer's Actual
// store) at cycle P and still the newest (no later Actual store), must have
// reached every destination -- a publication there (its Actual store) of v
// or a newer value -- by P + the channel's bound.  Judged in the first clock
// past P + bound (the bound of the mode in force then, with modes), whether
// or not anything was published: a value withheld for good (a producer that
// stops, its last value never taken) fails here, where the latency check,
// which measures at a publication, sees nothing.  Fault-free runs only (the
// bound is the fault-free one), values published from latency_from() on.
#include "system_checker.h"
#include <cstdio>

void SystemChecker::tick(uint64_t cycle)
{
    if (!latency_checked_) return;
    for (size_t i = 0; i < src_.size(); ++i) {
        const PlanChannel &c = plan_.channels[i];
        const SourceState &s = src_[i];
        if (!c.copy() || c.dests.empty() || s.publish_cycle.size() < 2) continue;
        const uint64_t v = s.publish_cycle.size() - 1, P = s.publish_cycle[v];
        // Measured from the controller's first cycle; a later Actual store
        // (its Export not yet returned) makes v not the newest.
        if (P < latency_from_ || s.pending_publish > P) continue;
        for (size_t k = 0; k < c.dests.size(); ++k) {
            DestState &d = dst_[i][k];
            if (d.fresh_seq != v) {
                d.fresh_seq = v;
                d.fresh_due = P + c.latency + 1;
                d.fresh_done = false;
            }
            if (d.fresh_done || cycle < d.fresh_due) continue;
            uint64_t bound = c.latency, bound_retry = c.latency_retry;
            if (bound_fn_ && !bound_fn_(static_cast<int>(i), P, cycle, bound, bound_retry)) {
                d.fresh_due = cycle + 16;   // a mode without the channel: not judged now
                continue;
            }
            if (cycle - P <= bound) {       // a switch since: the bound grew
                d.fresh_due = P + bound + 1;
                continue;
            }
            d.fresh_done = true;
            DestStats &st = stats[i].dests[k];
            ++st.fresh_judged;
            if (d.reached >= v) continue;
            ++st.fresh_late;
            char m[300];
            std::snprintf(m, sizeof m, "%s to board %d: value %llu, its source's newest since its publication at "
                          "cycle %llu, had not reached the destination by cycle %llu (the newest there: value %llu): "
                          "expected it (or a newer one) published there within the bound %llu",
                          c.name.c_str(), c.dests[k].board, static_cast<unsigned long long>(v),
                          static_cast<unsigned long long>(P), static_cast<unsigned long long>(cycle),
                          static_cast<unsigned long long>(d.reached), static_cast<unsigned long long>(bound));
            violation(FRESHNESS, m);
        }
    }
}
