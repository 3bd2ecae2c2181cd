// mobot_sim_report.cpp -- the end of a robot run (sim/mobot_sim.cpp): the
// console tables of the series (channel at consumer) and of the producers,
// each returning its JSON array for the report, and the run's verdict from
// the checks that failed and the checks a negative test expects to fail.
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>
#include "mobot_sim.h"

// Appends one JSON object (a report's text without its closing newline) to an array being built.
static void append(std::string &js, const JsonReport &e)
{
    const std::string t = e.text();
    js += (js.size() > 1 ? ",\n  " : "\n  ") + t.substr(0, t.size() - 1);
}

// The row's ages are those judged against a bound; the others (a mode without
// the channel or settling after a switch; a producer that crashes in the run) get a
// line of their own below it, so that their age is never read against the bound.
std::string series_report(const std::vector<Series> &series, const Plan &plan)
{
    std::printf("  %-11s %-11s %7s %7s %9s %9s %9s %9s %6s %11s\n", "channel", "consumer", "New", "Old",
                "age min", "age mean", "age max", "bound", "ratio", "cyc/Import");
    std::string js = "[";
    for (const Series &s : series) {
        const Stat &a = s.judged_age;
        char lo[24] = "-", mean[24] = "-", hi[24] = "-";  // no age judged: "-"
        if (a.n) {
            std::snprintf(lo, sizeof lo, "%llu", (unsigned long long)a.min);
            std::snprintf(mean, sizeof mean, "%.0f", a.mean());
            std::snprintf(hi, sizeof hi, "%llu", (unsigned long long)a.max);
        }
        std::printf("  %-11s %-11s %7llu %7llu %9s %9s %9s %9llu %6.3f %11.0f\n", s.ch->name.c_str(),
                    plan.board_names[s.board].c_str(), (unsigned long long)s.news, (unsigned long long)s.olds,
                    lo, mean, hi, (unsigned long long)s.bound, double(s.worst_pm) / 1000.0, s.import_cycles.mean());
        const uint64_t crashed = s.age.n - a.n - s.unjudged - s.comeback_age.n;
        if (s.age.n > a.n + s.comeback_age.n) {
            std::string without;  // the modes that do not carry the channel
            for (const PlanMode &m : plan.modes)
                if (!m.carries(s.ch->id)) without += (without.empty() ? "" : ", ") + m.name;
            std::printf("  %-23s + %llu ages not judged", "", (unsigned long long)(s.age.n - a.n - s.comeback_age.n));
            if (s.age.max > a.max) std::printf(", up to %llu", (unsigned long long)s.age.max);
            const bool both = s.unjudged && crashed;
            if (s.unjudged)
                // (a channel the start-up mode carries is judged after every switch back to it)
                std::printf(": %s%s, which carries no %s%s", both ?
                            (std::to_string(s.unjudged) + " in ").c_str() : "in ",
                            without.empty() ? "a mode" : without.c_str(), s.ch->name.c_str(),
                            plan.modes.empty() || plan.modes[0].carries(s.ch->id) ? "" :
                            ", or settling after the switch to a mode that first carries it");
            if (crashed)
                std::printf("%s from a producer that crashes in this run", both ? ("; " + std::to_string(crashed)).c_str() : ":");
            std::printf("\n");
        }
        if (s.comeback_age.n)
            std::printf("  %-23s + %llu ages judged after the channel came back, by the bound in force when it was "
                        "last carried + the time since: up to %llu, worst %llu against %llu (%.3f)\n", "",
                        (unsigned long long)s.comeback_age.n, (unsigned long long)s.comeback_age.max,
                        (unsigned long long)s.comeback_pm_age, (unsigned long long)s.comeback_pm_bound,
                        double(s.comeback_pm) / 1000.0);
        JsonReport e;
        e.str("channel", s.ch->name).str("kind", s.ch->kind).str("consumer", plan.board_names[s.board])
         .num("new", double(s.news)).num("old", double(s.olds)).num("bound", double(s.bound))
         .num("latency_bound", double(s.ch->latency_retry)).num("period", double(s.ch->period))
         .num("over_bound_samples", double(s.over_bound))
         .num("worst_ratio", double(s.worst_pm) / 1000.0).num("worst_ratio_age", double(s.worst_pm_age))
         .num("worst_ratio_bound", double(s.worst_pm_bound)).num("settling_samples", double(s.settling))
         .num("comeback_samples", double(s.comeback)).raw("comeback_age", s.comeback_age.json())
         .num("comeback_worst_ratio", double(s.comeback_pm) / 1000.0).num("comeback_worst_age", double(s.comeback_pm_age))
         .num("comeback_worst_bound", double(s.comeback_pm_bound)).num("unjudged_samples", double(s.unjudged)).num("new_after_crash", double(s.news_after_crash))
         .num("freshness_judged", double(s.fresh_judged)).num("freshness_late", double(s.fresh_late)).raw("age", s.age.json()).raw("judged_age", s.judged_age.json())
         .raw("import_cycles", s.import_cycles.json()).raw("termination", termination_json(s.term));
        append(js, e);
    }
    // The slow channels (a guaranteed period of 1 ms or more), in ms: the
    // worst judged age against the bound in force at that Import.
    const double ms = 1e3 / plan.clock_hz;
    for (const Series &s : series) {
        if (double(s.ch->period) < plan.clock_hz / 1000) continue;
        std::printf("  slow channel %s at %s: period %.2f ms, latency bound %.2f ms; %llu New, %llu ages judged",
                    s.ch->name.c_str(), plan.board_names[s.board].c_str(), double(s.ch->period) * ms,
                    double(s.ch->latency_retry) * ms, (unsigned long long)s.news, (unsigned long long)s.judged_age.n);
        if (s.judged_age.n)
            std::printf(", age max %.2f ms; worst %.2f ms against its bound %.2f ms (%.3f)",
                        double(s.judged_age.max) * ms, double(s.worst_pm_age) * ms, double(s.worst_pm_bound) * ms,
                        double(s.worst_pm) / 1000.0);
        if (s.comeback_age.n)
            std::printf("; after coming back %llu, worst %.2f ms against %.2f ms (%.3f)",
                        (unsigned long long)s.comeback_age.n, double(s.comeback_pm_age) * ms,
                        double(s.comeback_pm_bound) * ms, double(s.comeback_pm) / 1000.0);
        std::printf("\n");
    }
    return js + "]";
}

std::string producers_report(const std::map<int, Producer> &producers, const Plan &plan)
{
    std::string js = "[";
    std::printf("  %-11s %-11s %7s %9s %9s %13s\n", "channel", "producer", "Exports", "cyc mean", "cyc max",
                "max gap (clk)");
    for (const auto &pp : producers) {
        const Producer &p = pp.second;
        std::printf("  %-11s %-11s %7llu %9.0f %9llu %13llu\n", p.ch->name.c_str(),
                    plan.board_names[p.ch->src_board].c_str(), (unsigned long long)p.exports, p.export_cycles.mean(),
                    (unsigned long long)p.export_cycles.max, (unsigned long long)p.max_gap);
        JsonReport e;
        e.str("channel", p.ch->name).str("producer", plan.board_names[p.ch->src_board])
         .num("exports", double(p.exports)).num("actual_stores", double(p.stores)).num("max_gap", double(p.max_gap))
         .raw("export_cycles", p.export_cycles.json());
        append(js, e);
    }
    return js + "]";
}

std::string checks_report(const std::map<std::string, std::string> &failed)
{
    std::string checks = "{";
    for (const char *c : kChecks)
        checks += std::string(checks.size() > 1 ? ", " : "") + "\"" + c + "\": \"" + (failed.count(c) ? "fail" : "pass") + "\"";
    return checks + "}";
}

std::string judge(const std::map<std::string, std::string> &failed, const std::vector<std::string> &expect,
                  bool positive, std::string &last, std::vector<std::string> &lines)
{
    std::string verdict = "pass";
    if (positive) {
        for (auto &f : failed) lines.push_back(f.first + ": " + f.second);
        if (!failed.empty()) verdict = "fail";
        last = lines.empty() ? "pass" : "FAIL: " + lines.front();
    } else {
        std::string caught_by;
        for (const std::string &e : expect) {
            if (failed.count(e)) caught_by += (caught_by.empty() ? "" : "; ") + e + ": " + failed.at(e);
            else lines.push_back("negative test: expected the fault to be caught by " + e + ", it was not");
        }
        for (auto &f : failed)
            if (std::find(expect.begin(), expect.end(), f.first) == expect.end())
                lines.push_back("also failed, unexpectedly: " + f.first + ": " + f.second);
        verdict = lines.empty() ? "pass" : "fail";
        last = verdict == "pass" ? "pass: negative test: caught as expected by " + caught_by : "FAIL: " + lines.back();
    }
    return verdict;
}

std::vector<std::pair<std::string, std::string>> board_failures(const BoardsAtEnd &e, const Plan &plan, const Options &o,
                                                                uint64_t cycle, bool &cpu_failed)
{
    std::vector<std::pair<std::string, std::string>> out;
    char b[512];
    for (int c = 0; c < NB; ++c)
        if (((e.done >> c) & 1u) && e.code[c] != 0) {
            std::snprintf(b, sizeof b, "expected %s exit code 0, got 0x%x (%s)", plan.board_names[c].c_str(), e.code[c],
                          code_text(e.code[c], plan).c_str());
            out.emplace_back("cpu", b);
        }
    for (int c = 0; c < NB; ++c) {
        if ((e.trap >> c) & 1u) out.emplace_back("liveness", "expected no trap, got a trap on " + plan.board_names[c]);
        if ((e.bus_err >> c) & 1u)
            out.emplace_back("liveness", "expected no unmapped access, got one from " + plan.board_names[c]);
    }
    if (e.error) {
        std::snprintf(b, sizeof b, "expected no controller error, got error_o with %u rom errors", e.rom_errors);
        out.emplace_back("liveness", b);
    }
    const bool crash_run = o.crash_board >= 0;
    cpu_failed = false;
    for (int c = 0; c < NB; ++c) cpu_failed = cpu_failed || (((e.done >> c) & 1u) && e.code[c] != 0);
    for (int c = 0; c < NB && !cpu_failed; ++c) {
        if (crash_run && c == o.crash_board) continue;
        if (o.require_done && !crash_run && !((e.done >> c) & 1u)) {
            std::snprintf(b, sizeof b, "expected %s to report done (its quotas met) within %llu cycles, it did not",
                          plan.board_names[c].c_str(), (unsigned long long)o.cycles);
            out.emplace_back("liveness", b);
        }
        if (e.last_event[c] + o.cycles / 4 < cycle) {
            std::snprintf(b, sizeof b, "expected %s to keep calling the driver to the end, its last event was "
                          "at cycle %llu of %llu", plan.board_names[c].c_str(), (unsigned long long)e.last_event[c],
                          (unsigned long long)cycle);
            out.emplace_back("liveness", b);
        }
    }
    return out;
}
