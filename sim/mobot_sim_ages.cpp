// mobot_sim_ages.cpp -- the --ages CSV of sim/mobot_sim.cpp (the data of the
// ages picture): the worst age per time bucket and series.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>
#include "mobot_sim.h"

bool write_ages(const std::string &path, const std::vector<Series> &series, const Plan &plan, uint64_t n_buckets,
                uint64_t bucket_len, uint64_t cycle, uint64_t crash_cycle, uint64_t first_stale)
{
    FILE *f = std::fopen(path.c_str(), "w");
    if (!f) { std::fprintf(stderr, "cannot write %s\n", path.c_str()); return false; }
    std::fprintf(f, "# mobot_sim ages: bucket_start_cycle, then per series the worst age in the bucket "
                    "(clocks; empty: no Import)\n# crash_cycle %llu first_stale %llu\ncycle", (unsigned long long)crash_cycle,
                 (unsigned long long)first_stale);
    for (const Series &s : series)
        std::fprintf(f, ",%s@%s(bound=%llu)", s.ch->name.c_str(), plan.board_names[s.board].c_str(),
                     (unsigned long long)s.bound);
    std::fprintf(f, "\n");
    const uint64_t used = std::min<uint64_t>(n_buckets, (cycle + bucket_len - 1) / bucket_len);
    for (uint64_t k = 0; k < used; ++k) {
        std::fprintf(f, "%llu", (unsigned long long)(k * bucket_len));
        for (const Series &s : series) {
            if (s.bucket_max[k]) std::fprintf(f, ",%llu", (unsigned long long)s.bucket_max[k]);
            else std::fprintf(f, ",");
        }
        std::fprintf(f, "\n");
    }
    std::fclose(f);
    return true;
}
