// fresh_scenario.cpp -- see fresh_scenario.h.
#include "fresh_scenario.h"
#include <cstdio>

namespace tbsys {

namespace {
// --stretch-export: the producer's control word and its idle clocks.
struct ExportStretch {
    int board = -1, chan = -1;
    uint32_t base = 0;
    unsigned clocks = 0;
    bool loaded = false;   // the Export's control-word load came, its completing store not yet
} g_xs;

unsigned export_hook(SimCpu &cpu, uint32_t word, bool we)
{
    if (cpu.id != g_xs.board || word != g_xs.base) return 0;
    if (!we) {
        g_xs.loaded = true;
        return 0;
    }
    if (!g_xs.loaded) return 0;
    g_xs.loaded = false;   // the first store to the control word after the load completes the value
    return g_xs.clocks;
}

bool stops(const Plan &plan, const Options &o, const PlanChannel &c)
{
    if (o.stop_channel.empty() || !c.copy() || c.dests.empty()) return false;
    return o.stop_channel == "all" ? c.id != plan.mode_request : c.name == o.stop_channel;
}
}  // namespace

bool fresh_setup(const Plan &plan, const Options &o, SystemSim &sim, std::string &err)
{
    if (!o.stop_channel.empty() && o.stop_channel != "all" && !plan.by_name(o.stop_channel)) {
        err = "--producer-stop: no channel " + o.stop_channel + " in the plan";
        return false;
    }
    if (o.stretch_export_channel.empty()) return true;
    const PlanChannel *c = plan.by_name(o.stretch_export_channel);
    if (!c || !c->copy()) {
        err = "--stretch-export: no copy channel " + o.stretch_export_channel + " in the plan";
        return false;
    }
    if (sim.cpu[c->src_board].stall_hook) {
        err = "--stretch-export: board " + std::to_string(c->src_board) + " is stretched already (--stretch-import)";
        return false;
    }
    g_xs.board = c->src_board;
    g_xs.base = c->src_base;
    g_xs.clocks = static_cast<unsigned>(o.stretch_export_clocks);
    for (size_t i = 0; i < plan.channels.size(); ++i)
        if (&plan.channels[i] == c) g_xs.chan = static_cast<int>(i);
    sim.cpu[c->src_board].stall_hook = export_hook;
    std::printf("  stretched: %s's producer on board %d idles %u clocks before the store that completes each value\n",
                c->name.c_str(), c->src_board, g_xs.clocks);
    return true;
}

bool producer_stopped(const Plan &plan, const Options &o, const PlanChannel &c, uint64_t now)
{
    return now >= o.stop_at && stops(plan, o, c);
}

void fresh_report(const Plan &plan, const Options &o, const SystemChecker &chk, bool judged,
                  std::vector<std::string> &failures, std::string &json)
{
    char m[300];
    json = "[";
    uint64_t n_judged = 0, n_late = 0;
    for (size_t i = 0; i < plan.channels.size(); ++i) {
        const PlanChannel &c = plan.channels[i];
        if (!c.copy() || c.dests.empty()) continue;
        const SystemChecker::ChannelStats &cs = chk.stats[i];
        for (size_t d = 0; d < c.dests.size(); ++d) {
            const SystemChecker::DestStats &ds = cs.dests[d];
            n_judged += ds.fresh_judged;
            n_late += ds.fresh_late;
            std::snprintf(m, sizeof m, "%s{\"channel\": \"%s\", \"to_board\": %d, \"judged\": %llu, \"late\": %llu, "
                          "\"exports_overtaken\": %llu}", json.size() > 1 ? ", " : "", c.name.c_str(),
                          c.dests[d].board, static_cast<unsigned long long>(ds.fresh_judged),
                          static_cast<unsigned long long>(ds.fresh_late),
                          static_cast<unsigned long long>(cs.exports_overtaken));
            json += m;
            if (judged && stops(plan, o, c) && ds.fresh_judged == 0) {
                std::snprintf(m, sizeof m, "freshness: %s's producer stopped at cycle %llu, yet no value of it was "
                              "judged at board %d (the run ended within the bound %llu of its last publication?)",
                              c.name.c_str(), static_cast<unsigned long long>(o.stop_at), c.dests[d].board,
                              static_cast<unsigned long long>(c.latency));
                failures.push_back(m);
            }
        }
        if (static_cast<int>(i) == g_xs.chan) {
            std::printf("  stretched Exports: %llu of %llu Exports of %s overtaken by a take\n",
                        static_cast<unsigned long long>(cs.exports_overtaken),
                        static_cast<unsigned long long>(cs.exports), c.name.c_str());
            if (cs.exports_overtaken < 3) {
                std::snprintf(m, sizeof m, "stretched Exports: expected at least 3 Exports of %s overtaken by a take "
                              "(a ReadLocked store during the Export), got %llu", c.name.c_str(),
                              static_cast<unsigned long long>(cs.exports_overtaken));
                failures.push_back(m);
            }
        }
    }
    json += "]";
    std::printf("  freshness: %llu source values stayed the newest for longer than their bound, %llu of them late%s\n",
                static_cast<unsigned long long>(n_judged), static_cast<unsigned long long>(n_late),
                judged ? "" : " (not judged: faults)");
}

}  // namespace tbsys
