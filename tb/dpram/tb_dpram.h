// tb_dpram.h -- shared declarations of the tb_dpram modes (tb_dpram.cpp,
// tb_dpram_common.cpp, tb_dpram_exhaustive.cpp, tb_dpram_random.cpp,
// tb_dpram_crash.cpp): options, the channel run, the verdict.
#ifndef TB_DPRAM_H
#define TB_DPRAM_H
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>
#include "protocol_checker.h"
#include "ram_bus.h"
#include "report.h"
extern "C" {
#include "albatross.h"
}

namespace tbd {

const uint32_t kMaxPayload = 64;

struct Options {
    std::string mode, report;
    uint64_t imports = 1000000, seed = 1;
    uint32_t payload = 12;
    bool expect_violation = false;
    std::vector<std::string> expect_caught_by;   // checkers that must fire
    std::string variant = "albatross";
    std::string trace;                 // VCD path (models built with --trace)
    uint64_t trace_cycles = 20000;
    std::string ratios;                // ratio mode: log10(writer/reader) points, comma-separated
};

struct Channel {
    uint32_t base, size;
    int prod_port, cons_port;
};

inline RamBus *g_bus = nullptr;
// The channel kind both sides run (--kind): ALB_THREE_BUFFER or ALB_FOUR_SLOT.
inline int g_kind = ALB_THREE_BUFFER;
inline const char *kind_label() { return g_kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer"; }
// Bytes of a channel of the current kind.
inline uint32_t chan_bytes(uint32_t size)
{
    return g_kind == ALB_FOUR_SLOT ? ALB_FS_CHANNEL_BYTES(size) : ALB_CHANNEL_BYTES(size);
}
// Accesses of an Export beyond the payload (fixed): 2, four-slot 3.
inline unsigned export_overhead() { return g_kind == ALB_FOUR_SLOT ? 3u : 2u; }
inline int g_bucket = 0;   // current log-ratio bucket, for the termination figures
// Checkers whose verdicts a negative test ignores (--ignore), to show that
// the others catch the fault on their own.  Bits: the ProtocolChecker kinds,
// then byte_atomicity, access_time, in_channel, watchdog.
inline unsigned g_ignored = 0;
enum { IGN_ATOMICITY = ProtocolChecker::KINDS, IGN_LATENCY, IGN_IN_CHANNEL, IGN_WATCHDOG, IGN_COUNT };
const char *ignorable_name(int k);
inline bool ignored(int k) { return (g_ignored >> k) & 1u; }

// Watchdogs, in simulated cycles or steps: every mode ends on its own, with a
// "watchdog" verdict that says which call or run overran and what was expected.
// The bounds sit far above anything a correct driver needs (see the figures
// in the comments) and far below a wall-clock minute.
struct Limits {
    // One Import or Export of a side that is not frozen, from its call to its
    // return.  A correct Export of 64 bytes at the slowest CPU speed (1/100)
    // with every gap a long stall needs about 18 * 202 * 100 = 0.36 M cycles.
    uint64_t call_cycles = 4000000;
    // RAM accesses of one call (a driver loop that never returns).  Correct:
    // an Export 2 + W; an Import 1 + W, plus 2 per loop pass (a few).
    uint64_t call_accesses = 20000;
    // exhaustive: steps of one schedule (correct: under 100) and schedules
    // from one start state (correct: at most 1.0 M at 12 bytes, growing
    // about tenfold per payload word: the bound is 5 M at 3 words, times 10
    // per word beyond; --max-schedules sets it).
    uint64_t schedule_steps = 4096;
    uint64_t schedules = 0;
    // crash: cycles of one crash run (correct: 300 survivor calls after the
    // crash, under 1 M cycles at 1:100); calls of the victim after the one
    // planned for the crash before the crash point counts as never reached
    // (a consumer at 100:1 makes about 200 Imports without new data per
    // Export, and only one with new data reaches the last access points).
    uint64_t crash_run_cycles = 8000000;
    uint64_t crash_search_calls = 20000;
    // random and bench: cycles of one channel's segment per Import it must
    // check (correct: under 140 per channel in 1 M Imports).
    uint64_t segment_cycles_per_import = 2000;
};
inline Limits g_limits;

struct SideCtx {
    Channel chan{};
    ProtocolChecker *chk = nullptr;
    uint64_t next_seq = 1;           // producer: the next value to export
    uint64_t limit = ~0ull;          // calls to make
    uint64_t calls = 0;              // calls begun
    uint64_t call_start_acc = 0;     // cpu.accesses when the current call began
    uint64_t call_start_cycle = 0;   // the bus cycle when it began
    bool in_call = false;            // inside alb_import/alb_export
    uint64_t worst_call_cycles = 0;  // the longest call so far (for the watchdog's margin)
    unsigned warmup_calls = 0;
    unsigned align = 0;              // local buffer misalignment 0..3
    int attach_rc = 0;
    int last_rc = 0;
};

void producer_program(SimCpu &cpu);
void consumer_program(SimCpu &cpu);
void load_image(RamBus &bus, const Channel &c);


// One channel's run: the RAM, both programs and the checker, set up afresh.
struct Run {
    Channel chan;
    ProtocolChecker chk;
    SideCtx prod, cons;

    Run(const Channel &c) : chan(c), chk(c.base, c.size, c.prod_port, c.cons_port, g_kind) {
        RamBus &bus = *g_bus;
        bus.reset();
        load_image(bus, c);
        bus.observer = &chk;
        prod.chan = cons.chan = c;
        prod.chk = cons.chk = &chk;
        SimCpu &pc = bus.cpu[c.prod_port], &cc = bus.cpu[c.cons_port];
        pc.window_lo = cc.window_lo = c.base;
        pc.window_hi = cc.window_hi = c.base + chan_bytes(c.size);
        pc.faulted = cc.faulted = false;
        pc.context = &prod;
        cc.context = &cons;
        pc.start(producer_program);
        cc.start(consumer_program);
    }
    ~Run() { g_bus->observer = nullptr; }
    SimCpu &producer() { return g_bus->cpu[chan.prod_port]; }
    SimCpu &consumer() { return g_bus->cpu[chan.cons_port]; }

    // The calls under way, for a watchdog's message.
    std::string calls_under_way() const {
        std::string r;
        for (int s = 0; s < 2; ++s) {
            const SideCtx &x = s == 0 ? prod : cons;
            const SimCpu &cpu = g_bus->cpu[s == 0 ? chan.prod_port : chan.cons_port];
            char m[160];
            if (x.in_call)
                std::snprintf(m, sizeof m, "the %s's %s number %llu has made %llu accesses without returning",
                              s == 0 ? "producer" : "consumer", s == 0 ? "Export" : "Import",
                              static_cast<unsigned long long>(x.calls),
                              static_cast<unsigned long long>(cpu.accesses - x.call_start_acc));
            else
                std::snprintf(m, sizeof m, "the %s has made %llu calls", s == 0 ? "producer" : "consumer",
                              static_cast<unsigned long long>(x.calls));
            r += (r.empty() ? "" : "; ") + std::string(m);
        }
        return r;
    }

    // The per-call watchdog: a message naming the first call of a side that
    // is not frozen (frozen[port]) and has run past its bound, or "".
    std::string overdue_call(const bool *frozen = nullptr) const {
        const uint64_t now = g_bus->cycle();
        for (int s = 0; s < 2; ++s) {
            const SideCtx &x = s == 0 ? prod : cons;
            const int port = s == 0 ? chan.prod_port : chan.cons_port;
            const SimCpu &cpu = g_bus->cpu[port];
            if (!x.in_call || (frozen && frozen[port]) || cpu.faulted) continue;
            const uint64_t cyc = now - x.call_start_cycle, acc = cpu.accesses - x.call_start_acc;
            if (cyc <= g_limits.call_cycles && acc <= g_limits.call_accesses) continue;
            const unsigned w = (chan.size + 3) / 4;
            char m[320];
            if (s == 0)
                std::snprintf(m, sizeof m, "watchdog: the producer's Export of seq %llu (%u-byte payload), begun at cycle %llu, "
                              "has not returned after %llu cycles and %llu RAM accesses; expected it to return after "
                              "exactly %u + %u = %u accesses, within %llu cycles",
                              static_cast<unsigned long long>(x.next_seq), chan.size,
                              static_cast<unsigned long long>(x.call_start_cycle), static_cast<unsigned long long>(cyc),
                              static_cast<unsigned long long>(acc), export_overhead(), w, export_overhead() + w,
                              static_cast<unsigned long long>(g_limits.call_cycles));
            else
                std::snprintf(m, sizeof m, "watchdog: the consumer's Import number %llu (%u-byte payload), begun at cycle %llu, "
                              "has not returned after %llu cycles and %llu RAM accesses; expected at most %llu cycles "
                              "and %llu accesses (1 + %u, plus 2 per loop pass)",
                              static_cast<unsigned long long>(x.calls), chan.size,
                              static_cast<unsigned long long>(x.call_start_cycle), static_cast<unsigned long long>(cyc),
                              static_cast<unsigned long long>(acc), static_cast<unsigned long long>(g_limits.call_cycles),
                              static_cast<unsigned long long>(g_limits.call_accesses), w);
            return m;
        }
        return "";
    }
};

uint64_t counted_violations(const ProtocolChecker &chk);

// Everything a run can be blamed for, in one place.
struct Verdict {
    uint64_t violations[ProtocolChecker::KINDS] = {};
    std::string first[ProtocolChecker::KINDS];
    uint64_t atomicity = 0, latency = 0, faults = 0, watchdog = 0, other = 0;
    std::string first_atomicity, first_latency, first_fault, first_watchdog, first_other, context;

    void take(const Run &r) {
        if (context.empty() && !r.chk.first_context.empty())
            context = "  the last accesses before the first protocol violation:\n" + r.chk.first_context;
        for (int k = 0; k < ProtocolChecker::KINDS; ++k) {
            if (r.chk.violations[k] && !violations[k]) first[k] = r.chk.first_message[k];
            violations[k] += r.chk.violations[k];
        }
        for (int p = 0; p < 2; ++p) {
            const SimCpu &c = g_bus->cpu[p];
            if (c.faulted) { if (!faults++) first_fault = c.fault; }
        }
    }
    void take_bus() {
        RamBus &b = *g_bus;
        if (b.ref.violations && !atomicity) first_atomicity = b.ref.first_violation;
        atomicity += b.ref.violations;
        if (b.latency_violations && !latency) first_latency = b.first_latency_violation;
        latency += b.latency_violations;
        b.ref.violations = b.latency_violations = 0;
    }
    void add_other(const std::string &m) { if (!other++) first_other = m; }
    void add_watchdog(const std::string &m) { if (!watchdog++) first_watchdog = m; }
    // Another verdict's counts and first messages added to this one.
    void merge(const Verdict &v) {
        for (int k = 0; k < ProtocolChecker::KINDS; ++k) {
            if (v.violations[k] && !violations[k]) first[k] = v.first[k];
            violations[k] += v.violations[k];
        }
        if (v.atomicity && !atomicity) first_atomicity = v.first_atomicity;
        atomicity += v.atomicity;
        if (v.latency && !latency) first_latency = v.first_latency;
        latency += v.latency;
        if (v.faults && !faults) first_fault = v.first_fault;
        faults += v.faults;
        if (v.watchdog && !watchdog) first_watchdog = v.first_watchdog;
        watchdog += v.watchdog;
        if (v.other && !other) first_other = v.first_other;
        other += v.other;
        if (context.empty()) context = v.context;
    }
    // Violations that count (not --ignore'd).
    uint64_t total() const {
        uint64_t t = other;
        if (!ignored(IGN_ATOMICITY)) t += atomicity;
        if (!ignored(IGN_LATENCY)) t += latency;
        if (!ignored(IGN_IN_CHANNEL)) t += faults;
        if (!ignored(IGN_WATCHDOG)) t += watchdog;
        for (int k = 0; k < ProtocolChecker::KINDS; ++k)
            if (!ignored(k)) t += violations[k];
        return t;
    }
    void print() const {
        for (int k = 0; k < IGN_COUNT; ++k) {
            uint64_t n = k < ProtocolChecker::KINDS ? violations[k] : k == IGN_ATOMICITY ? atomicity
                       : k == IGN_LATENCY ? latency : k == IGN_IN_CHANNEL ? faults : watchdog;
            const std::string &m = k < ProtocolChecker::KINDS ? first[k] : k == IGN_ATOMICITY ? first_atomicity
                                 : k == IGN_LATENCY ? first_latency : k == IGN_IN_CHANNEL ? first_fault
                                 : first_watchdog;
            std::printf("  %-18s %llu violations%s%s%s\n", ignorable_name(k), static_cast<unsigned long long>(n),
                        ignored(k) ? " (ignored)" : "", n ? ": " : "", n ? m.c_str() : "");
        }
        if (other) std::printf("  %-18s %llu: %s\n", "harness", static_cast<unsigned long long>(other), first_other.c_str());
        if (!context.empty()) std::printf("%s", context.c_str());
    }
    std::string json() const {
        std::string s = "{";
        char b[96];
        for (int k = 0; k < ProtocolChecker::KINDS; ++k) {
            std::snprintf(b, sizeof b, "\"%s\": %llu, ", ProtocolChecker::kind_name(k),
                          static_cast<unsigned long long>(violations[k]));
            s += b;
        }
        std::snprintf(b, sizeof b, "\"byte_atomicity\": %llu, \"access_time\": %llu, \"in_channel\": %llu, "
                      "\"watchdog\": %llu, \"harness\": %llu}",
                      static_cast<unsigned long long>(atomicity), static_cast<unsigned long long>(latency),
                      static_cast<unsigned long long>(faults), static_cast<unsigned long long>(watchdog),
                      static_cast<unsigned long long>(other));
        return s + b;
    }
    // Names of the checkers that fired.
    std::string caught_by() const {
        std::string s;
        for (int k = 0; k < ProtocolChecker::KINDS; ++k)
            if (violations[k] && !ignored(k)) s += std::string(s.empty() ? "" : ", ") + ProtocolChecker::kind_name(k);
        if (atomicity && !ignored(IGN_ATOMICITY)) s += std::string(s.empty() ? "" : ", ") + "byte_atomicity";
        if (latency && !ignored(IGN_LATENCY)) s += std::string(s.empty() ? "" : ", ") + "access_time";
        if (faults && !ignored(IGN_IN_CHANNEL)) s += std::string(s.empty() ? "" : ", ") + "in_channel";
        if (watchdog && !ignored(IGN_WATCHDOG)) s += std::string(s.empty() ? "" : ", ") + "watchdog";
        if (other) s += std::string(s.empty() ? "" : ", ") + "harness";
        return s;
    }
};

bool run_until(unsigned need, std::string &why);

inline const Options *g_opts = nullptr;

std::string first_message(const Verdict &v);
bool negative_satisfied(const Verdict &v);
int verdict_status(const Options &o, const Verdict &v, const char *what, uint64_t amount);

int mode_exhaustive(const Options &o);
int mode_random(const Options &o);
int mode_crash(const Options &o);
int mode_bench(const Options &o);
int mode_ratio(const Options &o);

}  // namespace tbd
#endif
