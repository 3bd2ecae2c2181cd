// tb_dpram_random.h -- the speed model and CPU driver of random mode, shared
// with crash and bench modes.
#ifndef TB_DPRAM_RANDOM_H
#define TB_DPRAM_RANDOM_H
#include "tb_dpram.h"

namespace tbd {

// ------------------------------------------------------------------- random
//
// The speed model: each CPU runs on its own clock, expressed as RAM cycles
// per CPU cycle (>= 1), and spends 0-2 CPU cycles between accesses, with rare
// long stalls.  log10(writer speed / reader speed) drifts as a random walk
// over [-2, 2]: ratios from 1:100 to 100:1, the faster side at full speed.
struct Timing {
    std::mt19937_64 rng;
    double log_ratio = 0.0;      // log10(writer speed / reader speed)
    bool fixed = false;          // ratio mode: log_ratio stays put (stalls stay random)
    double period[2] = {1, 1};   // RAM cycles per CPU cycle, per port
    double frac[2] = {0, 0};
    uint64_t next_drift = 0;

    explicit Timing(uint64_t seed) : rng(seed) {}
    double uni() { return std::uniform_real_distribution<double>(0, 1)(rng); }
    void drift(uint64_t now, int writer_port) {
        if (now < next_drift) return;
        next_drift = now + 500 + rng() % 3000;
        if (!fixed) {
            log_ratio += std::normal_distribution<double>(0, 0.35)(rng);
            if (uni() < 0.02) log_ratio = uni() * 4 - 2;   // an occasional jump
        }
        log_ratio = std::max(-2.0, std::min(2.0, log_ratio));
        double r = std::pow(10.0, std::fabs(log_ratio));
        int slow = log_ratio >= 0 ? 1 - writer_port : writer_port;
        period[slow] = r;
        period[1 - slow] = 1.0;
        g_bucket = std::min(ProtocolChecker::kBuckets - 1, std::max(0, static_cast<int>((log_ratio + 2.0) * 2.0)));
    }
    // Idle RAM cycles before a CPU's next access.
    uint64_t gap(int port) {
        double cpu_cycles = static_cast<double>(rng() % 3);
        if ((rng() & 63) == 0) cpu_cycles += static_cast<double>(rng() % 200);
        double t = frac[port] + cpu_cycles * period[port];
        uint64_t whole = static_cast<uint64_t>(t);
        frac[port] = t - static_cast<double>(whole);
        return whole;
    }
};

// Decides, just before a CPU's request is issued, whether to stop it instead.
class IssueGate {
public:
    virtual ~IssueGate() {}
    virtual bool stop_before_issue(int port) = 0;
};

// Drives both CPUs for one clock: resume the ones whose gap has elapsed,
// issue their requests, tick.  frozen[p] CPUs are left alone.
struct Driver {
    Timing &tm;
    IssueGate *gate = nullptr;
    uint64_t wait[2] = {0, 0};
    bool frozen[2] = {false, false};
    bool ram_dead = false;
    std::string dead_why;
    explicit Driver(Timing &t) : tm(t) {}
    void cycle() {
        RamBus &bus = *g_bus;
        for (int p = 0; p < 2; ++p) {
            SimCpu &c = bus.cpu[p];
            if (frozen[p] || bus.busy(p) || c.finished() || c.faulted) continue;
            if (wait[p]) { --wait[p]; continue; }
            if (!c.has_request) c.resume();
            if (c.has_request && gate && gate->stop_before_issue(p)) continue;
            if (c.has_request) bus.issue(p);
        }
        unsigned done = bus.tick();
        for (int p = 0; p < 2; ++p) {
            if (done & (1u << p)) wait[p] = tm.gap(p);
            if (bus.busy(p) && bus.cycle() - bus.issue_cycle(p) > 64 && !ram_dead) {
                ram_dead = frozen[p] = true;
                char m[160];
                std::snprintf(m, sizeof m, "the RAM stopped acknowledging: port %c issued at cycle %llu had no "
                              "acknowledge after 64 cycles, expected one within %d", 'A' + p,
                              static_cast<unsigned long long>(bus.issue_cycle(p)), RamBus::kMaxLatency);
                dead_why = m;
            }
        }
    }
};

Channel random_channel(std::mt19937_64 &rng);

struct RandomStats {
    uint64_t imports = 0, imports_new = 0, exports = 0, cycles = 0, accesses = 0, segments = 0;
    uint64_t worst_iter = 0, worst_acc = 0;
    uint64_t worst_export_cycles = 0, worst_import_cycles = 0, worst_segment_cycles_per_import = 0;
    uint64_t b_imports[ProtocolChecker::kBuckets] = {}, b_worst_iter[ProtocolChecker::kBuckets] = {};
    uint64_t b_worst_acc[ProtocolChecker::kBuckets] = {}, b_iter_sum[ProtocolChecker::kBuckets] = {};
    uint64_t ov_min[3] = {~0ull, ~0ull, ~0ull}, ov_max[3] = {};
    uint64_t ctl_sum = 0, ctl_worst = 0, ctl_imports = 0;   // Import accesses beyond the payload
    Verdict verdict;
};

// fixed_log_ratio: NAN for the drifting speed model, else log10(writer/reader)
// held at that value (ratio mode).
void run_random(uint64_t target, uint64_t seed, RandomStats &st, bool stop_on_violation, bool progress,
                double fixed_log_ratio = NAN);

}  // namespace tbd
#endif
