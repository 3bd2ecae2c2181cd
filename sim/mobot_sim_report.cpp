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

std::string series_report(const std::vector<Series> &series, const Plan &plan)
{
    std::string js = "[";
    for (const Series &s : series) {
        std::printf("  %-11s %-11s %7llu %7llu %9llu %9.0f %9llu %9llu %6.3f %11.0f\n", s.ch->name.c_str(),
                    plan.board_names[s.board].c_str(), (unsigned long long)s.news, (unsigned long long)s.olds,
                    (unsigned long long)s.age.min, s.age.mean(), (unsigned long long)s.age.max,
                    (unsigned long long)s.bound, double(s.worst_pm) / 1000.0,
                    s.import_cycles.mean());
        JsonReport e;
        e.str("channel", s.ch->name).str("kind", s.ch->kind).str("consumer", plan.board_names[s.board])
         .num("new", double(s.news)).num("old", double(s.olds)).num("bound", double(s.bound))
         .num("latency_bound", double(s.ch->latency_retry)).num("period", double(s.ch->period))
         .num("over_bound_samples", double(s.over_bound))
         .num("worst_ratio", double(s.worst_pm) / 1000.0).num("unjudged_samples", double(s.unjudged)).num("new_after_crash", double(s.news_after_crash)).raw("age", s.age.json())
         .raw("import_cycles", s.import_cycles.json()).raw("termination", termination_json(s.term));
        append(js, e);
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
