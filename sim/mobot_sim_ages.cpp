// mobot_sim_ages.cpp -- per-series figures of sim/mobot_sim.cpp beside the
// main loop: the --ages CSV (the data of the ages picture: the worst age per
// time bucket and series), and Import termination
// (docs/robot.md "Import termination"), the check "termination".
// Termination rules: an Import's window is every acked DPRAM access of the
// consumer's core to the channel's instance (control word and three buffers)
// since the core's previous board event (the firmware reports every Import
// and Export, sim/firmware/mobot_check.h, and touches the instance only in
// alb_import, so the window holds exactly that Import's accesses); the core's
// first Import is left out (its window also holds alb_*_attach_all).  A pass
// is a store to byte 1 of the control word (ReadLocked); a load of the
// control word is a load of Actual.  The compiler's bound (report.txt beside
// the plan: "<ch> -> <board>: D d, T t, V v: three-buffer: <= P passes, A
// accesses") assumes the loop's loads of Actual are at most T apart and the
// first two at most V.  Without --stall every Import is judged (passes <=
// scale x P and accesses <= scale x A) and one whose measured gaps exceed T
// or V fails too (the description understates the loop); with --stall (the
// harness holds a core in bursts the description does not model) only the
// Imports whose gaps are within T and V are judged, the others are counted.
// An Import still running at the end of the run is judged by the passes it
// has made so far (a starved reader never reports its Import).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <fstream>
#include <vector>
#include "mobot_sim.h"

void Termination::access(bool write, bool control, uint32_t sel, uint64_t cycle)
{
    ++accesses;
    if (!control) return;
    if (write) {
        if (sel & 2u) ++passes;  // ReadLocked := Actual
        return;
    }
    if (loads) {  // a load of Actual: the gap since the last one
        const uint64_t gap = cycle - last_load;
        if (loads == 1) first_gap = gap;
        max_gap = std::max(max_gap, gap);
    }
    ++loads;
    last_load = cycle;
}

void Termination::import_done(double scale, uint64_t cycle, bool judge_all)
{
    passes_all.add(passes);
    accesses_all.add(accesses);
    if (hist.size() <= passes) hist.resize(passes + 1, 0);
    ++hist[passes];
    t_max = std::max(t_max, max_gap);
    v_max = std::max(v_max, first_gap);
    if (!known) return;
    const bool beyond = first_gap > V || max_gap > T;
    if (beyond) {
        ++outside;
        worst_beyond_passes = std::max<uint64_t>(worst_beyond_passes, passes);
        if (!judge_all) return;
    }
    ++judged;
    worst_passes = std::max<uint64_t>(worst_passes, passes);
    worst_accesses = std::max<uint64_t>(worst_accesses, accesses);
    if (double(passes) > scale * double(max_passes) || double(accesses) > scale * double(max_accesses)) {
        if (!over++) worst_over_cycle = cycle;
        worst_over_passes = std::max<uint64_t>(worst_over_passes, passes);
        worst_over_accesses = std::max<uint64_t>(worst_over_accesses, accesses);
    }
}

void Termination::finish(double scale, uint64_t cycle, bool judge_all)
{
    if (!known || !loads) return;
    const bool beyond = first_gap > V || max_gap > T;
    if (beyond && !judge_all) return;
    if (double(passes) > scale * double(max_passes)) {  // an Import that never ended
        ++unfinished;
        if (!over++) worst_over_cycle = cycle;
        worst_over_passes = std::max<uint64_t>(worst_over_passes, passes);
        worst_over_accesses = std::max<uint64_t>(worst_over_accesses, accesses);
    }
}

int load_termination(const std::string &plan_path, std::vector<Series> &series, const Plan &plan)
{
    const size_t slash = plan_path.find_last_of('/');
    std::ifstream f((slash == std::string::npos ? std::string(".") : plan_path.substr(0, slash)) + "/report.txt");
    int n = 0;
    for (std::string line; std::getline(f, line);) {
        const size_t arrow = line.find(" -> "), colon = line.find(": D ");
        if (arrow == std::string::npos || colon == std::string::npos || colon < arrow) continue;
        const size_t name0 = line.find_first_not_of(' ');
        const std::string ch = line.substr(name0, arrow - name0), board = line.substr(arrow + 4, colon - arrow - 4);
        unsigned long long d, t, v, p, a;
        if (std::sscanf(line.c_str() + colon, ": D %llu, T %llu, V %llu: three-buffer: <= %llu passes, %llu accesses",
                        &d, &t, &v, &p, &a) != 5)
            continue;  // not checked (no timing), unbounded, or four-slot
        for (Series &s : series)
            if (s.ch->name == ch && plan.board_names[s.board] == board) {
                Termination &m = s.term;
                m.known = true;
                m.D = d; m.T = t; m.V = v; m.max_passes = p; m.max_accesses = a;
                ++n;
            }
    }
    return n;
}

void print_termination(const std::vector<Series> &series, const Plan &plan, const Options &o)
{
    std::printf("  Import termination (passes = ReadLocked stores per Import; bound: compiler, x%.2f)\n", o.term_scale);
    std::printf("  %-11s %-11s %7s %7s %7s %-22s %6s %5s %6s %5s %5s %5s %5s %5s\n", "channel", "consumer", "Imports",
                "judged", "beyond", "passes 0/1/2/3/4+", "worst", "bound", "access", "bound", "T max", "T", "V max", "V");
    for (const Series &s : series) {
        const Termination &t = s.term;
        std::string h;
        for (size_t k = 0; k < 5; ++k) {
            uint64_t c = 0;
            if (k < 4) c = k < t.hist.size() ? t.hist[k] : 0;
            else for (size_t j = 4; j < t.hist.size(); ++j) c += t.hist[j];
            h += (k ? "/" : "") + std::to_string(c);
        }
        if (t.known)
            std::printf("  %-11s %-11s %7llu %7llu %7llu %-22s %6llu %5llu %6llu %5llu %5llu %5llu %5llu %5llu\n",
                        s.ch->name.c_str(), plan.board_names[s.board].c_str(), (unsigned long long)t.passes_all.n,
                        (unsigned long long)t.judged, (unsigned long long)t.outside, h.c_str(),
                        (unsigned long long)t.worst_passes, (unsigned long long)t.max_passes,
                        (unsigned long long)t.worst_accesses, (unsigned long long)t.max_accesses,
                        (unsigned long long)t.t_max, (unsigned long long)t.T, (unsigned long long)t.v_max,
                        (unsigned long long)t.V);
        else
            std::printf("  %-11s %-11s %7llu %7s %7s %-22s %6llu %5s %6llu %5s %5llu %5s %5llu %5s\n",
                        s.ch->name.c_str(), plan.board_names[s.board].c_str(), (unsigned long long)t.passes_all.n, "-",
                        "-", h.c_str(), (unsigned long long)t.passes_all.max, "-", (unsigned long long)t.accesses_all.max,
                        "-", (unsigned long long)t.t_max, "-", (unsigned long long)t.v_max, "-");
    }
}

std::string termination_json(const Termination &t)
{
    JsonReport r;
    r.num("bounded", t.known ? 1 : 0).num("D_clocks", double(t.D)).num("T_clocks", double(t.T))
     .num("V_clocks", double(t.V)).num("max_passes", double(t.max_passes)).num("max_accesses", double(t.max_accesses))
     .num("judged", double(t.judged)).num("beyond_timing", double(t.outside)).num("over_bound", double(t.over))
     .num("unfinished_over_bound", double(t.unfinished)).num("worst_passes_beyond_timing", double(t.worst_beyond_passes))
     .num("worst_passes", double(t.worst_passes)).num("worst_accesses", double(t.worst_accesses))
     .num("measured_T_max", double(t.t_max)).num("measured_V_max", double(t.v_max))
     .raw("passes", t.passes_all.json()).raw("accesses", t.accesses_all.json());
    std::string h = "[";
    for (size_t k = 0; k < t.hist.size(); ++k) h += (k ? ", " : "") + std::to_string(t.hist[k]);
    r.raw("passes_histogram", h + "]");
    const std::string s = r.text();
    return s.substr(0, s.size() - 1);
}

bool write_ages(const std::string &path, const std::vector<Series> &series, const Plan &plan, uint64_t n_buckets,
                uint64_t bucket_len, uint64_t cycle, uint64_t crash_cycle, uint64_t first_stale)
{
    FILE *f = std::fopen(path.c_str(), "w");
    if (!f) { std::fprintf(stderr, "cannot write %s\n", path.c_str()); return false; }
    std::fprintf(f, "# mobot_sim ages: bucket_start_cycle, then per series the worst age in the bucket "
                    "(clocks; empty: no Import) and the largest bound in force its samples were judged by "
                    "(empty: none, a mode without the channel)\n# crash_cycle %llu first_stale %llu\ncycle",
                 (unsigned long long)crash_cycle, (unsigned long long)first_stale);
    for (const Series &s : series)
        std::fprintf(f, ",%s@%s(bound=%llu),bound", s.ch->name.c_str(), plan.board_names[s.board].c_str(),
                     (unsigned long long)s.bound);
    std::fprintf(f, "\n");
    const uint64_t used = std::min<uint64_t>(n_buckets, (cycle + bucket_len - 1) / bucket_len);
    for (uint64_t k = 0; k < used; ++k) {
        std::fprintf(f, "%llu", (unsigned long long)(k * bucket_len));
        for (const Series &s : series) {
            if (s.bucket_max[k]) std::fprintf(f, ",%llu", (unsigned long long)s.bucket_max[k]);
            else std::fprintf(f, ",");
            if (s.bucket_bound[k]) std::fprintf(f, ",%llu", (unsigned long long)s.bucket_bound[k]);
            else std::fprintf(f, ",");
        }
        std::fprintf(f, "\n");
    }
    std::fclose(f);
    return true;
}

void Series::judge(uint64_t age, uint64_t bound, uint64_t k, double scale, bool crashed, bool comeback)
{
    bucket_bound[k] = std::max(bucket_bound[k], bound);
    if (crashed) return;
    const uint64_t pm = bound ? 1000 * age / bound : 0;
    if (comeback) {
        comeback_age.add(age);
        if (pm > comeback_pm || !comeback_pm_bound) comeback_pm = pm, comeback_pm_age = age, comeback_pm_bound = bound;
    } else {
        judged_age.add(age);
        if (pm > worst_pm || !worst_pm_bound) worst_pm = pm, worst_pm_age = age, worst_pm_bound = bound;
    }
    if (double(age) > scale * double(bound) && (!over_bound++ || age * worst_over_bound > worst_over * bound))
        worst_over = age, worst_over_bound = bound;
}

std::vector<std::string> age_failures(const std::vector<Series> &series, const Plan &plan, const Options &o)
{
    std::vector<std::string> out;
    char b[512];
    for (const Series &s : series)
        if (s.over_bound) {
            std::snprintf(b, sizeof b, "expected every age of %s at %s <= %.4g x its bound in force, got %llu over "
                          "it (worst %llu clocks against %llu)", s.ch->name.c_str(), plan.board_names[s.board].c_str(),
                          o.age_scale, (unsigned long long)s.over_bound, (unsigned long long)s.worst_over,
                          (unsigned long long)s.worst_over_bound);
            out.push_back(b);
        }
    return out;
}

std::vector<std::string> termination_failures(std::vector<Series> &series, const Plan &plan, const Options &o,
                                              uint64_t cycle, const bool seen_event[NB])
{
    std::vector<std::string> out;
    char b[512];
    for (Series &s : series) {
        if (seen_event[s.board]) s.term.finish(o.term_scale, cycle, o.stall == 0);
        if (s.term.over) {
            const Termination &t = s.term;
            std::snprintf(b, sizeof b, "expected every Import of %s at %s within %.4g passes and %.4g accesses "
                          "(compiler: D %llu, T %llu, V %llu), got %llu over it (worst %llu passes, %llu accesses; "
                          "first at cycle %llu)", s.ch->name.c_str(), plan.board_names[s.board].c_str(),
                          o.term_scale * double(t.max_passes), o.term_scale * double(t.max_accesses),
                          (unsigned long long)t.D, (unsigned long long)t.T, (unsigned long long)t.V,
                          (unsigned long long)t.over, (unsigned long long)t.worst_over_passes,
                          (unsigned long long)t.worst_over_accesses, (unsigned long long)t.worst_over_cycle);
            out.push_back(b);
        }
    }
    for (const Series &s : series) {
        if (o.stall == 0 && s.term.outside) {
            const Termination &t = s.term;
            std::snprintf(b, sizeof b, "expected the Import loop of %s at %s within the compiler's T %llu and V %llu "
                          "clocks (the bound's premise), got %llu Imports beyond (T up to %llu, V up to %llu; up "
                          "to %llu passes against the bound %llu)", s.ch->name.c_str(), plan.board_names[s.board].c_str(),
                          (unsigned long long)t.T, (unsigned long long)t.V, (unsigned long long)t.outside,
                          (unsigned long long)t.t_max, (unsigned long long)t.v_max,
                          (unsigned long long)t.worst_beyond_passes, (unsigned long long)t.max_passes);
            out.push_back(b);
        }
    }
    return out;
}

void judge_fresh(Series &s, const Producer &p, const ModeTrack &modes, const std::string &consumer, uint64_t t_start,
                 uint64_t taken_at, uint64_t from)
{
    uint64_t bound = 0;
    if (!modes.bound_at(*s.ch, 0, t_start, bound)) return;   // a mode without the channel: not judged
    const std::vector<uint64_t> &P = p.store_times;
    // i: the newest value whose bound had run out by t_start; then back to
    // the newest one that stayed the newest for longer than the bound.
    size_t i = std::upper_bound(P.begin(), P.end(), t_start > bound ? t_start - bound : 0) - P.begin();
    for (size_t steps = 0; i > 0 && steps < 64; --i, ++steps) {
        const size_t j = i - 1;
        if (P[j] < from) return;
        if (j + 1 < P.size() && P[j + 1] <= P[j] + bound) continue;   // superseded within the bound
        ++s.fresh_judged;
        if (taken_at >= P[j]) return;
        if (!s.fresh_late++) {
            char b[300];
            std::snprintf(b, sizeof b, "%s at %s: an Import begun at time %llu returned a value taken at %llu, "
                          "older than the producer's value stored at %llu and the newest for longer than the bound "
                          "%llu: expected it or a newer one", s.ch->name.c_str(), consumer.c_str(), (unsigned long long)t_start,
                          (unsigned long long)taken_at, (unsigned long long)P[j], (unsigned long long)bound);
            s.fresh_first = b;
        }
        return;
    }
}
