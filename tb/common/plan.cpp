// plan.cpp -- see plan.h.
#include "plan.h"
#include <fstream>
#include <sstream>

bool Plan::load(const std::string &path, std::string &error)
{
    std::ifstream in(path);
    if (!in) {
        error = "cannot read " + path + " (run the schedule compiler first)";
        return false;
    }
    std::string line;
    int n = 0;
    bool have_system = false;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        std::string what;
        s >> what;
        bool ok = true;
        if (what == "system") {
            std::string mode;
            ok = static_cast<bool>(s >> boards >> cycle >> mode >> n_chan >> ram_bytes) &&
                 (mode == "rigid" || mode == "sync");
            sync_mode = mode == "sync";
            have_system = ok;
        } else if (what == "clock") {
            ok = static_cast<bool>(s >> clock_hz) && clock_hz > 0;
        } else if (what == "board") {
            int index = -1;
            std::string name;
            ok = static_cast<bool>(s >> index >> name) && index == static_cast<int>(board_names.size());
            if (ok) board_names.push_back(name);
        } else if (what == "channel") {
            PlanChannel c;
            int sync = 0;
            ok = static_cast<bool>(s >> c.id >> c.name >> c.kind >> c.size >> c.words >> c.src_board >>
                                   c.src_base >> c.period >> c.latency >> c.latency_retry >> sync >> c.slots);
            c.sync = sync != 0;
            int four = 0;  // optional last field: 1 = a four-slot channel
            if (ok && (s >> four)) c.four_slot = four != 0;
            ok = ok && (c.kind == "copy" || c.kind == "time" || c.kind == "status");
            if (ok) channels.push_back(c);
        } else if (what == "dest") {
            int id = 0, index = 0;
            PlanDest d;
            ok = static_cast<bool>(s >> id >> index >> d.board >> d.base);
            PlanChannel *c = nullptr;
            for (PlanChannel &x : channels)
                if (x.id == id) c = &x;
            ok = ok && c && index == static_cast<int>(c->dests.size());
            if (ok) c->dests.push_back(d);
        } else if (what == "mode") {
            int index = -1;
            PlanMode m;
            ok = static_cast<bool>(s >> index >> m.name >> m.cycle >> m.switch_latency) &&
                 index == static_cast<int>(modes.size()) && m.cycle > 0;
            uint64_t at_target = 0;  // optional
            if (ok && (s >> at_target)) m.switch_latency_at_target = at_target;
            if (ok) modes.push_back(m);
        } else if (what == "mode_request") {
            ok = static_cast<bool>(s >> mode_request) && mode_request >= 0;
        } else if (what == "mode_info") {
            ok = static_cast<bool>(s >> mode_info) && mode_info >= 0;
        } else if (what == "mode_channel") {
            int index = -1, id = -1;
            uint64_t period = 0, bound_ff = 0, bound = 0;
            ok = static_cast<bool>(s >> index >> id >> period >> bound_ff >> bound) && index >= 0 &&
                 index < static_cast<int>(modes.size()) && id >= 0 && id < 64 && bound > 0 && bound_ff > 0;
            if (ok) {
                PlanMode &m = modes[index];
                if (m.bound.size() <= static_cast<size_t>(id)) m.bound.resize(id + 1, 0), m.bound_ff.resize(id + 1, 0);
                m.bound[id] = bound;
                m.bound_ff[id] = bound_ff;
            }
        } else {
            ok = false;
        }
        if (!ok) {
            error = path + ":" + std::to_string(n) + ": cannot read \"" + line + "\"";
            return false;
        }
    }
    if (!have_system || channels.empty()) {
        error = path + ": no system line or no channel";
        return false;
    }
    return true;
}

const PlanChannel *Plan::by_name(const std::string &name) const
{
    for (const PlanChannel &c : channels)
        if (c.name == name) return &c;
    return nullptr;
}
