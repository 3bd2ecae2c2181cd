// multirate_scenario.cpp -- see multirate_scenario.h.
#include "multirate_scenario.h"
#include <cstdio>
#include <fstream>
#include <sstream>

namespace tbsys {

void multirate_verdict(const Plan &plan, const Options &o, const SystemChecker &chk, const FragmentChecker *frag,
                       std::vector<std::string> &failures)
{
    char m[300];
    if (frag) std::printf("  minor cycles and fragments: %s\n", frag->json().c_str());
    if (frag && !frag->by_channel().empty())
        std::printf("  minor cycles and fragments, violations by check and channel: %s\n", frag->by_channel().c_str());
    if (o.require_cut && (!frag || frag->cut_fragments < o.require_cut)) {
        std::snprintf(m, sizeof m, "fragments: expected at least %llu runs of values in fragments cut by faults, got %llu%s",
                      static_cast<unsigned long long>(o.require_cut), static_cast<unsigned long long>(frag ? frag->cut_fragments : 0),
                      frag ? "" : " (not judged)");
        failures.push_back(m);
    }
    if (!o.bounds_at_target.empty()) {   // every latency / age against the report's bound at the target
        std::ifstream bf(o.bounds_at_target);
        std::string line;
        int judged = 0;
        while (std::getline(bf, line)) {
            std::istringstream ls(line);
            std::string tag, ch;
            int board = -1;
            unsigned long long bound = 0;
            if (!(ls >> tag >> ch >> board >> bound) || tag != "at_target") continue;
            bound = static_cast<unsigned long long>(static_cast<double>(bound) * o.latency_scale);   // (a negative test's)
            for (size_t i = 0; i < plan.channels.size(); ++i)
                for (size_t d = 0; d < plan.channels[i].dests.size(); ++d) {
                    if (plan.channels[i].name != ch || plan.channels[i].dests[d].board != board) continue;
                    const SystemChecker::DestStats &ds = chk.stats[i].dests[d];
                    ++judged;
                    std::printf("  at the target: %-12s board %d: largest %s %llu of %llu values, bound %llu\n", ch.c_str(), board,
                                plan.channels[i].copy() ? "latency" : "age", static_cast<unsigned long long>(ds.latency_max),
                                static_cast<unsigned long long>(ds.latency_n), bound);
                    if (ds.latency_max > bound) {
                        std::snprintf(m, sizeof m, "at the target: %s to board %d: a %s of %llu clocks, expected at most the "
                                      "report's bound at the fault hypothesis' target, %llu", ch.c_str(), board,
                                      plan.channels[i].copy() ? "latency" : "age",
                                      static_cast<unsigned long long>(ds.latency_max), bound);
                        failures.push_back(m);
                    }
                }
        }
        if (judged == 0) failures.push_back("at the target: no bound in " + o.bounds_at_target + " names a consumer of the plan");
    }
    uint64_t need = o.require_fragments;
    std::string why;
    if (o.require_fragments_plan && frag) {
        need = frag->values_over_runs(plan, o.cycles, why);
        std::printf("  values the plan publishes over two or more runs in %llu clocks: %llu (%s)\n",
                    static_cast<unsigned long long>(o.cycles), static_cast<unsigned long long>(need),
                    why.empty() ? "no channel" : why.c_str());
        if (need == 0) failures.push_back("fragments: the plan has no channel whose values go over two or more runs");
    }
    if ((need || o.require_fragments_plan) && (!frag || frag->fragmented_publications < need)) {
        std::snprintf(m, sizeof m, "fragments: expected at least %llu values published after two or more runs%s, got %llu%s",
                      static_cast<unsigned long long>(need), o.require_fragments_plan ? " (the plan's)" : "",
                      static_cast<unsigned long long>(frag ? frag->fragmented_publications : 0), frag ? "" : " (not judged)");
        failures.push_back(m);
    }
}

}  // namespace tbsys
