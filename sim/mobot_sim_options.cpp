// mobot_sim_options.cpp -- the command line of sim/mobot_sim.cpp (the run and
// its checks: that file's head comment) and the text of a core's failure code.
//
//   mobot_sim --plan tb_plan.txt +fw0..3=FILE +ram0..3=FILE +rom=FILE
//             [--cycles N] [--seed S] [--stall P] [--fault-rate R] [--burst L]
//             [--fault-clocking access|clock]
//             [--crash BOARD@CYCLE] [--hang BOARD@CYCLE]
//             [--trace FILE.vcd [--trace-from N] [--trace-cycles N]]
//             [--report FILE] [--ages FILE.csv] [--label NAME] [--progress K]
//             [--age-samples FILE.csv]  every imported age (channel,board,cycle,age,producer_gap)
//             [--age-scale X] [--require-done] [--expect-caught-by CHECK]
//             [--drift-ppm BOARD=PPM[,/BOARD=PPM...]|random:MAX] [--clock-scale X]
//             [--termination-scale X] [--min-switches N] [--switch-scale X]
//
//   --burst L       faults come in runs of mean length L accesses
//   --fault-clocking clock  the fault process advances every clock instead
//                   of every access (the old injector; negative test of the
//                   rate check)
//   --stall P       every core's local RAM is held in random bursts (each
//                   free cycle starts one with probability 1/P, 1..1024
//                   cycles; 0 = none, the default), so cores drift
//   --crash B@C     board B crashes in the middle of its first Export that
//                   begins at or after cycle C of its first data channel (by
//                   id: the radar's RadarMap): once half the value's words
//                   are stored, the core is frozen for good (its Actual is
//                   never stored).  The checks expect it: the ages of every
//                   channel B produces count toward no verdict.
//   --hang B@C      board B freezes at cycle C without telling the checks
//                   (the negative test of the liveness check)
//   --age-scale X   check ages against X times the bound (negative test)
//   --min-switches N  a description with schedule modes: fail (check mode)
//                   on fewer than N switches
//   --switch-scale X  check switch latencies against X times the compiler's
//                   switch_latency (negative test)
//   --mute CH@B     every controller store to the control word of channel
//                   CH's destination on board B is lost (sim/pico_boards.v
//                   +mute_board/+mute_word): that destination is never
//                   published, and its consumer keeps the RAM image's value
//                   (taken_at 0); the negative test of the age check after
//                   start-up
//   --drift-ppm S   the boards' clocks drift against the controller's: the
//                   named boards' TIMERs run PPM parts per million fast (> 0)
//                   or slow (board_memmap +drift<c>=PPM); random:MAX draws
//                   each board's from the seed in [-MAX, MAX]
//   --clock-scale X check local-time errors against X times their bounds
//   --termination-scale X  check each Import's passes and accesses against X
//                   times the compiler's bound (negative test)
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>
#include "fault_model.h"
#include "mobot_sim.h"

namespace {

bool parse_u64(const char *s, uint64_t &v)
{
    char *end = nullptr;
    if (!s || !*s) return false;
    v = std::strtoull(s, &end, 0);
    return *end == '\0';
}

bool parse_board_at(const std::string &s, const Plan &plan, int &board, uint64_t &at)
{
    const size_t p = s.find('@');
    if (p == std::string::npos) return false;
    const std::string name = s.substr(0, p);
    board = -1;
    for (size_t b = 0; b < plan.board_names.size(); ++b)
        if (plan.board_names[b] == name) board = int(b);
    return board >= 0 && parse_u64(s.substr(p + 1).c_str(), at);
}
// --mute CHANNEL@BOARD: the control word of CHANNEL's destination on BOARD.
bool parse_mute(const std::string &s, const Plan &plan, Options &o)
{
    const size_t p = s.find('@');
    if (p == std::string::npos) return false;
    const std::string chan = s.substr(0, p), board = s.substr(p + 1);
    for (const PlanChannel &c : plan.channels)
        if (c.name == chan)
            for (const PlanDest &d : c.dests)
                if (d.board >= 0 && size_t(d.board) < plan.board_names.size() && plan.board_names[d.board] == board) {
                    o.mute_board = d.board;
                    o.mute_word = int(d.base / 4);
                    return true;
                }
    return false;
}
// --drift-ppm: BOARD=PPM[,BOARD=PPM...] (or / between them) or random:MAX (each board's PPM drawn
// from the seed, uniform in [-MAX, MAX]).
bool parse_drift(const std::string &s, const Plan &plan, Options &o)
{
    const long limit = 100000;  // 10 %
    if (s.rfind("random:", 0) == 0) {
        char *end = nullptr;
        const long max = std::strtol(s.c_str() + 7, &end, 0);
        if (*end || max < 0 || max >= limit) return false;
        uint64_t r = o.seed * 0xD1B54A32D192ED03ull + 0x2545F4914F6CDD1Dull;
        for (int b = 0; b < NB; ++b) {
            r ^= r << 13; r ^= r >> 7; r ^= r << 17;
            o.drift_ppm[b] = long(r % uint64_t(2 * max + 1)) - max;
        }
        return true;
    }
    for (size_t p = 0; p < s.size();) {
        const size_t q = std::min(s.find_first_of(",/", p), s.size()), e = s.find('=', p);
        if (e == std::string::npos || e > q) return false;
        const std::string name = s.substr(p, e - p), val = s.substr(e + 1, q - e - 1);
        int board = -1;
        for (size_t b = 0; b < plan.board_names.size(); ++b)
            if (plan.board_names[b] == name) board = int(b);
        char *end = nullptr;
        const long ppm = std::strtol(val.c_str(), &end, 0);
        if (board < 0 || val.empty() || *end || ppm <= -limit || ppm >= limit) return false;
        o.drift_ppm[board] = ppm;
        p = q + 1;
    }
    return true;
}
}  // namespace

int usage(const char *msg)
{
    std::fprintf(stderr, "mobot_sim: %s\n"
                 "usage: mobot_sim --plan tb_plan.txt +fw0..3=FILE +ram0..3=FILE +rom=FILE [--cycles N]\n"
                 "                 [--seed S] [--stall P] [--fault-rate R] [--burst L] [--fault-clocking access|clock]\n"
                 "                 [--crash BOARD@CYCLE] [--hang BOARD@CYCLE] [--mute CHANNEL@BOARD]\n"
                 "                 [--trace FILE.vcd [--trace-from N] [--trace-cycles N]] [--report FILE]\n"
                 "                 [--ages FILE.csv] [--age-samples FILE.csv] [--label NAME] [--progress K] [--age-scale X] [--require-done]\n"
                 "                 [--termination-scale X] [--min-switches N] [--switch-scale X]\n"
                 "                 [--drift-ppm BOARD=PPM[,BOARD=PPM...]|random:MAX] [--clock-scale X]\n"
                 "                 [--expect-caught-by cpu|liveness|age|staleness|faults|clock|termination|mode]\n", msg);
    return 2;
}

std::string code_text(uint32_t code, const Plan &plan)
{
    static const char *what[8] = {"pass", "alb_import error", "attach error", "checksum wrong",
                                  "sequence number went back", "New without a newer value",
                                  "Old with a newer value", "export error"};
    if (code == 0) return "pass";
    const uint32_t chk = code & 0xfu, id = (code >> 4) & 0xfu, seq = code >> 12;
    const PlanChannel *ch = nullptr;
    for (const PlanChannel &c : plan.channels)
        if (uint32_t(c.id) == id) ch = &c;
    char b[160];
    std::snprintf(b, sizeof b, "%s, channel %s, sequence %u", chk < 8 ? what[chk] : "unknown code",
                  ch ? ch->name.c_str() : "-", seq);
    return b;
}

int parse_options(int argc, char **argv, Options &o, Plan &plan, std::vector<std::string> &expect)
{
    std::string &crash_arg = o.crash_arg, &hang_arg = o.hang_arg;  // as given, for the report
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a[0] == '+') continue;  // plusargs: the RTL reads them
        if (a == "--help" || a == "-h") { usage("the whole-system simulation (sim/mobot_sim.cpp)"); return 0; }
        if (a == "--require-done") { o.require_done = true; continue; }
        if (i + 1 >= argc) return usage((a + " needs a value").c_str());
        const char *v = argv[++i];
        uint64_t n = 0;
        if (a == "--plan") o.plan = v;
        else if (a == "--report") o.report = v;
        else if (a == "--ages") o.ages = v;
        else if (a == "--age-samples") o.age_samples = v;
        else if (a == "--trace") o.trace = v;
        else if (a == "--label") o.label = v;
        else if (a == "--expect-caught-by") o.expect = v;
        else if (a == "--crash") crash_arg = v;
        else if (a == "--hang") hang_arg = v;
        else if (a == "--drift-ppm") o.drift_arg = v;
        else if (a == "--mute") o.mute_arg = v;
        else if (a == "--clock-scale") {
            char *end = nullptr;
            o.clock_scale = std::strtod(v, &end);
            if (*end || !(o.clock_scale > 0)) return usage("--clock-scale: expected a number > 0");
        } else if (a == "--switch-scale") {
            char *end = nullptr;
            o.switch_scale = std::strtod(v, &end);
            if (*end || !(o.switch_scale > 0)) return usage("--switch-scale: expected a number > 0");
        } else if (a == "--termination-scale") {
            char *end = nullptr;
            o.term_scale = std::strtod(v, &end);
            if (*end || !(o.term_scale > 0)) return usage("--termination-scale: expected a number > 0");
        } else if (a == "--fault-clocking") {
            if (std::string(v) != "access" && std::string(v) != "clock") return usage("--fault-clocking: access or clock");
            o.fault_per_clock = std::string(v) == "clock";
        } else if (a == "--burst") {
            char *end = nullptr;
            o.burst = std::strtod(v, &end);
            if (*end || !(o.burst >= 1)) return usage("--burst: expected a mean run of faulted accesses >= 1");
        } else if (a == "--fault-rate" || a == "--age-scale") {
            char *end = nullptr;
            const double x = std::strtod(v, &end);
            if (*end || !(x >= 0) || (a == "--fault-rate" && x >= 1))
                return usage((a + ": expected a number" + (a == "--fault-rate" ? " in [0, 1)" : " >= 0")).c_str());
            (a == "--fault-rate" ? o.fault_rate : o.age_scale) = x;
        } else if (parse_u64(v, n)) {
            if (a == "--cycles" && n > 0) o.cycles = n;
            else if (a == "--seed") o.seed = n;
            else if (a == "--stall") o.stall = n;
            else if (a == "--min-switches") o.min_switches = n;
            else if (a == "--trace-from") o.trace_from = n;
            else if (a == "--trace-cycles" && n > 0) o.trace_cycles = n;
            else if (a == "--progress" && n <= 100) o.progress = n;
            else return usage(("unknown option or bad value: " + a + " " + v).c_str());
        } else {
            return usage(("unknown option or bad value: " + a + " " + v).c_str());
        }
    }
    if (o.plan.empty()) return usage("--plan is required");
    const std::string bad_faults = FaultModel::invalid(o.fault_rate, o.burst);
    if (!bad_faults.empty()) return usage(bad_faults.c_str());
    for (size_t p = 0; !o.expect.empty() && p <= o.expect.size();) {
        const size_t q = std::min(o.expect.find(',', p), o.expect.size());
        expect.push_back(o.expect.substr(p, q - p));
        if (std::find(std::begin(kChecks), std::end(kChecks), expect.back()) == std::end(kChecks))
            return usage(("--expect-caught-by: no check named " + expect.back()).c_str());
        p = q + 1;
    }
    std::string err;
    if (!plan.load(o.plan, err)) return usage(err.c_str());
    if (plan.boards != NB || int(plan.board_names.size()) != NB)
        return usage("the plan must have 4 boards (sim/pico_boards.v has NB = 4)");
    if (!crash_arg.empty() && !parse_board_at(crash_arg, plan, o.crash_board, o.crash_at))
        return usage(("--crash: expected BOARD@CYCLE with a board of the plan, got " + crash_arg).c_str());
    if (!hang_arg.empty() && !parse_board_at(hang_arg, plan, o.hang_board, o.hang_at))
        return usage(("--hang: expected BOARD@CYCLE with a board of the plan, got " + hang_arg).c_str());
    if (!o.mute_arg.empty() && !parse_mute(o.mute_arg, plan, o))
        return usage(("--mute: expected CHANNEL@BOARD, a channel of the plan and one of its destination boards, got " +
                      o.mute_arg).c_str());
    if (!o.drift_arg.empty() && !parse_drift(o.drift_arg, plan, o))
        return usage(("--drift-ppm: expected BOARD=PPM[,BOARD=PPM...] with boards of the plan and |PPM| < 100000, "
                      "or random:MAX (each board drawn from the seed in [-MAX, MAX]), got " + o.drift_arg).c_str());
#if !VM_TRACE
    if (!o.trace.empty()) return usage("--trace needs the model built with Verilator --trace (make sim TRACE=1)");
#endif
    return -1;
}
