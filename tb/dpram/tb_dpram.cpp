// tb_dpram.cpp -- two simulated CPUs run the real C driver (c-driver/) against
// the RTL dual-ported RAM, under adversarial timing, with the paper's four
// proof points checked on every Import (protocol_checker.h) and byte
// atomicity and access time checked on every RAM access (ram_bus.h).
//
//   tb_dpram exhaustive [--payload N] [--max-schedules N] [--expect-violation]
//       every interleaving of 2 Exports against 2 Imports, same-cycle
//       collisions on one byte in both slot orders, from 6 start states
//   tb_dpram random [--imports N] [--seed S] [--expect-violation]
//       drifting speed ratios 1:100..100:1, random stalls, payload sizes,
//       alignments and port assignment
//   tb_dpram crash [--seed S]
//       one side frozen or reset at every access point of Import and Export
//   tb_dpram bench [--imports N]
//       simulated-CPU access rate and cycles per second of wall time
//
// Every mode ends on its own: watchdogs in simulated cycles and RAM accesses
// bound each Import and Export, each run (a channel's segment, a schedule, a
// crash run) and each search (schedules, the crash point), and a wall-clock
// hand-off watchdog (sim_cpu.h) catches C code that loops without touching
// the RAM.  A watchdog that fires is the checker "watchdog", and its message
// names the call or run, what it had done and what was expected; a failing
// run ends with one line "FAIL: ..." naming the first fault.
//
// --trace FILE.vcd writes a wave of the first --trace-cycles cycles (binary
// built with Verilator --trace: build/tb/albatross-trace/).
// --report FILE writes the figures as JSON.  Exit status 0 means: no
// violation (or, with --expect-violation, at least one: a negative test).
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

namespace {

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
};

struct Channel {
    uint32_t base, size;
    int prod_port, cons_port;
};

RamBus *g_bus = nullptr;
int g_bucket = 0;   // current log-ratio bucket, for the termination figures
// Checkers whose verdicts a negative test ignores (--ignore), to show that
// the others catch the fault on their own.  Bits: the ProtocolChecker kinds,
// then byte_atomicity, access_time, in_channel, watchdog.
unsigned g_ignored = 0;
enum { IGN_ATOMICITY = ProtocolChecker::KINDS, IGN_LATENCY, IGN_IN_CHANNEL, IGN_WATCHDOG, IGN_COUNT };
const char *ignorable_name(int k)
{
    if (k < ProtocolChecker::KINDS) return ProtocolChecker::kind_name(k);
    static const char *n[] = {"byte_atomicity", "access_time", "in_channel", "watchdog"};
    return n[k - ProtocolChecker::KINDS];
}
bool ignored(int k) { return (g_ignored >> k) & 1u; }

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
Limits g_limits;

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

void producer_program(SimCpu &cpu)
{
    SideCtx &p = *static_cast<SideCtx *>(cpu.context);
    alignas(8) uint8_t buf[kMaxPayload + 8];
    alb_channel_t ch;
    cpu.warmup = true;
    alb_channel_setup(&ch, p.chan.base, p.chan.size);
    p.attach_rc = alb_producer_attach(&ch);
    if (p.attach_rc != ALB_OK) return;
    for (uint64_t n = 0; n < p.limit; ++n) {
        cpu.warmup = n < p.warmup_calls;
        uint8_t *v = buf + p.align;
        make_value(p.next_seq, v, p.chan.size);
        ++p.calls;
        p.call_start_acc = cpu.accesses;
        p.call_start_cycle = g_bus->cycle();
        p.in_call = true;
        p.chk->export_begin(p.next_seq);
        p.last_rc = alb_export(&ch, v);
        p.in_call = false;
        p.worst_call_cycles = std::max(p.worst_call_cycles, g_bus->cycle() - p.call_start_cycle);
        p.chk->export_end(p.last_rc);
        ++p.next_seq;
    }
}

void consumer_program(SimCpu &cpu)
{
    SideCtx &c = *static_cast<SideCtx *>(cpu.context);
    alignas(8) uint8_t buf[kMaxPayload + 8];
    alb_channel_t ch;
    cpu.warmup = true;
    alb_channel_setup(&ch, c.chan.base, c.chan.size);
    c.attach_rc = alb_consumer_attach(&ch);
    if (c.attach_rc != ALB_OK) return;
    for (uint64_t n = 0; n < c.limit; ++n) {
        cpu.warmup = n < c.warmup_calls;
        uint8_t *v = buf + c.align;
        ++c.calls;
        c.call_start_acc = cpu.accesses;
        c.call_start_cycle = g_bus->cycle();
        c.in_call = true;
        c.chk->import_begin(g_bus->cycle(), g_bucket);
        c.last_rc = alb_import(&ch, v);
        c.in_call = false;
        c.worst_call_cycles = std::max(c.worst_call_cycles, g_bus->cycle() - c.call_start_cycle);
        c.chk->import_end(c.last_rc, v, g_bus->cycle());
    }
}

// The RAM image of a fresh channel: Actual = ReadLocked = Buffer1 holding the
// initial value (seq 0); the other buffers hold garbage.
void load_image(RamBus &bus, const Channel &c)
{
    std::vector<uint8_t> img(ALB_CHANNEL_BYTES(c.size), 0xEE);
    img[ALB_OFF_ACTUAL] = ALB_BUFFER1;
    img[ALB_OFF_READLOCKED] = ALB_BUFFER1;
    img[2] = img[3] = 0;
    make_value(0, &img[ALB_OFF_BUFFER(1u, c.size)], c.size);
    bus.load(c.base, img.data(), static_cast<uint32_t>(img.size()));
}

// One channel's run: the RAM, both programs and the checker, set up afresh.
struct Run {
    Channel chan;
    ProtocolChecker chk;
    SideCtx prod, cons;

    Run(const Channel &c) : chan(c), chk(c.base, c.size, c.prod_port, c.cons_port) {
        RamBus &bus = *g_bus;
        bus.reset();
        load_image(bus, c);
        bus.observer = &chk;
        prod.chan = cons.chan = c;
        prod.chk = cons.chk = &chk;
        SimCpu &pc = bus.cpu[c.prod_port], &cc = bus.cpu[c.cons_port];
        pc.window_lo = cc.window_lo = c.base;
        pc.window_hi = cc.window_hi = c.base + ALB_CHANNEL_BYTES(c.size);
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
                              "exactly 2 + %u = %u accesses, within %llu cycles",
                              static_cast<unsigned long long>(x.next_seq), chan.size,
                              static_cast<unsigned long long>(x.call_start_cycle), static_cast<unsigned long long>(cyc),
                              static_cast<unsigned long long>(acc), w, 2 + w,
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

uint64_t counted_violations(const ProtocolChecker &chk)
{
    uint64_t t = 0;
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (!ignored(k)) t += chk.violations[k];
    return t;
}

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

// Tick until every port in `need` has completed; false if the RAM stops
// answering within 64 cycles (then the access-time checker has already fired),
// with `why` saying which port.
bool run_until(unsigned need, std::string &why)
{
    unsigned got = 0;
    for (int guard = 0; (got & need) != need; ++guard) {
        if (guard > 64) {
            char m[160];
            std::snprintf(m, sizeof m, "the RAM stopped acknowledging: port%s%s%s issued at cycle %llu had no "
                          "acknowledge after 64 cycles, expected one within %d",
                          (need & ~got & 1u) ? " A" : "", (need & ~got & 2u) ? " B" : "",
                          (need & ~got) == 3u ? " (both)" : "",
                          static_cast<unsigned long long>(g_bus->cycle() - 65), RamBus::kMaxLatency);
            why = m;
            return false;
        }
        got |= g_bus->tick();
    }
    return true;
}

const Options *g_opts = nullptr;

// The first message of the first counted checker that fired, with its name.
std::string first_message(const Verdict &v)
{
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (v.violations[k] && !ignored(k)) return std::string(ProtocolChecker::kind_name(k)) + ": " + v.first[k];
    if (v.atomicity && !ignored(IGN_ATOMICITY)) return "byte_atomicity: " + v.first_atomicity;
    if (v.latency && !ignored(IGN_LATENCY)) return "access_time: " + v.first_latency;
    if (v.faults && !ignored(IGN_IN_CHANNEL)) return "in_channel: " + v.first_fault;
    if (v.watchdog && !ignored(IGN_WATCHDOG)) return v.first_watchdog;
    if (v.other) return "harness: " + v.first_other;
    return "";
}

// A negative test may stop: a counted checker fired, and every expected one.
bool negative_satisfied(const Verdict &v)
{
    if (!v.total()) return false;
    std::string fired = ", " + v.caught_by() + ", ";
    for (const std::string &c : g_opts->expect_caught_by)
        if (fired.find(", " + c + ", ") == std::string::npos) return false;
    return true;
}

// The exit status.  Normal run: 0 if no counted violation.  Negative test
// (--expect-violation): 0 only if some counted checker fired, and every
// checker named by --expect-caught-by among them.
int verdict_status(const Options &o, const Verdict &v, const char *what, uint64_t amount)
{
    if (!o.expect_violation) {
        if (!v.total()) return 0;
        std::printf("FAIL: %llu violations in %llu %s; the first: %s\n", static_cast<unsigned long long>(v.total()),
                    static_cast<unsigned long long>(amount), what, first_message(v).c_str());
        return 1;
    }
    std::string fired = ", " + v.caught_by() + ", ";
    bool ok = v.total() != 0;
    std::string missing;
    for (const std::string &c : o.expect_caught_by)
        if (fired.find(", " + c + ", ") == std::string::npos) { ok = false; missing += " " + c; }
    if (ok) {
        std::printf("negative test: the fault was caught by: %s\n", v.caught_by().c_str());
        return 0;
    }
    std::printf("negative test FAILED: expected the fault to be caught%s%s, got %s in %llu %s\n",
                missing.empty() ? "" : " by", missing.c_str(),
                v.total() ? ("only " + v.caught_by()).c_str() : "0 violations",
                static_cast<unsigned long long>(amount), what);
    return 1;
}

// ---------------------------------------------------------------- exhaustive
//
// Stateless search: each schedule is replayed from the start along a path of
// choices.  At every point both CPUs are suspended at their next access; the
// choices are: A's access alone, B's alone, and, if the two touch a common
// byte, both issued in the same cycle with the RAM serving A first or B
// first.  Independent simultaneous accesses equal either order, so they are
// not repeated.  Warm-up calls (bringing the channel to a start state) run
// forced, producer first.
enum Choice : uint8_t { STEP_A, STEP_B, BOTH_A_FIRST, BOTH_B_FIRST };

struct Search {
    uint32_t payload = 0;
    unsigned warm_exports = 0, warm_imports = 0;
    uint64_t schedules = 0, steps = 0, collisions = 0, imports = 0;
    uint64_t imports_new = 0, max_depth = 0;
    Verdict verdict;
};

bool overlap(const BusRequest &a, const BusRequest &b)
{
    return a.addr == b.addr && (a.sel & b.sel) != 0;
}

// Runs one schedule; extends path/counts to a leaf.  Returns false if the
// replay diverged (nondeterminism: a harness bug).
bool run_schedule(Search &s, std::vector<uint8_t> &path, std::vector<uint8_t> &counts)
{
    Channel c{0, s.payload, 0, 1};
    Run run(c);
    run.prod.limit = s.warm_exports + 2;
    run.prod.warmup_calls = s.warm_exports;
    run.cons.limit = s.warm_imports + 2;
    run.cons.warmup_calls = s.warm_imports;
    RamBus &bus = *g_bus;
    SimCpu &a = bus.cpu[0], &b = bus.cpu[1];
    size_t depth = 0;
    for (;;) {
        for (SimCpu *cpu : {&a, &b})
            if (!cpu->has_request && !cpu->finished() && !cpu->faulted) cpu->resume();
        bool pa = a.has_request, pb = b.has_request;
        if (!pa && !pb) break;
        uint8_t opts[4];
        int n = 0;
        if (pa && a.warmup) opts[n++] = STEP_A;
        else if (pb && b.warmup) opts[n++] = STEP_B;
        else {
            if (pa) opts[n++] = STEP_A;
            if (pb) opts[n++] = STEP_B;
            if (pa && pb && overlap(a.request, b.request)) {
                opts[n++] = BOTH_A_FIRST;
                opts[n++] = BOTH_B_FIRST;
            }
        }
        uint8_t pick;
        if (depth < path.size()) {
            if (counts[depth] != n) return false;
            pick = path[depth];
        } else {
            path.push_back(0);
            counts.push_back(static_cast<uint8_t>(n));
            pick = 0;
        }
        Choice ch = static_cast<Choice>(opts[pick]);
        bool ok;
        std::string why;
        if (ch == STEP_A || ch == STEP_B) {
            int p = ch == STEP_A ? 0 : 1;
            bus.issue(p);
            ok = run_until(1u << p, why);
        } else {
            ++s.collisions;
            int first = ch == BOTH_A_FIRST ? 0 : 1;
            if (bus.next_slot() != first) bus.tick();
            bus.issue(0);
            bus.issue(1);
            ok = run_until(3u, why);
        }
        ++depth;
        ++s.steps;
        if (!ok) {
            s.verdict.add_other(why);
            break;
        }
        std::string late = run.overdue_call();
        if (!late.empty()) {
            s.verdict.add_watchdog(late);
            break;
        }
        if (depth > g_limits.schedule_steps) {
            char m[400];
            std::snprintf(m, sizeof m, "watchdog: a schedule of %u Exports and %u Imports (%u-byte payload) ran past "
                          "%llu RAM accesses, expected under 100: %s",
                          s.warm_exports + 2, s.warm_imports + 2, s.payload,
                          static_cast<unsigned long long>(g_limits.schedule_steps), run.calls_under_way().c_str());
            s.verdict.add_watchdog(m);
            break;
        }
    }
    s.max_depth = std::max<uint64_t>(s.max_depth, depth);
    ++s.schedules;
    s.imports += run.chk.imports;
    s.imports_new += run.chk.imports_new;
    if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
        s.verdict.add_other("attach failed on a valid RAM image");
    s.verdict.take(run);
    s.verdict.take_bus();
    return true;
}

int mode_exhaustive(const Options &o)
{
    if (o.payload < 3 || o.payload > kMaxPayload) {
        std::fprintf(stderr, "exhaustive: --payload must be 3..%u bytes, got %u\n", kMaxPayload, o.payload);
        return 2;
    }
    if (!g_limits.schedules) {
        g_limits.schedules = 5000000;
        for (unsigned w = 3; w < (o.payload + 3) / 4 && g_limits.schedules < (1ull << 60); ++w) g_limits.schedules *= 10;
    }
    std::printf("exhaustive: 2 Exports against 2 Imports of %u bytes (%u word accesses each), "
                "every interleaving, same-cycle collisions in both orders\n",
                o.payload, (o.payload + 3) / 4);
    uint64_t total = 0, collisions = 0, imports = 0, imports_new = 0;
    Verdict all;
    JsonReport rep;
    std::string states = "[";
    bool stop = false;
    for (unsigned we = 0; we <= 2 && !stop; ++we) {
        for (unsigned wi = 0; wi <= 1 && !stop; ++wi) {
            Search s;
            s.payload = o.payload;
            s.warm_exports = we;
            s.warm_imports = wi;
            std::vector<uint8_t> path, counts;
            auto t0 = std::chrono::steady_clock::now();
            for (;;) {
                if (!run_schedule(s, path, counts)) {
                    s.verdict.add_other("replay diverged: the harness is not deterministic");
                    break;
                }
                if (o.expect_violation && negative_satisfied(s.verdict)) { stop = true; break; }
                // A schedule that hit a watchdog would be replayed and extended
                // in every sibling: stop at the first one.
                if (s.verdict.watchdog) { stop = true; break; }
                if (s.schedules >= g_limits.schedules) {
                    char m[200];
                    std::snprintf(m, sizeof m, "watchdog: the start state with %u warm-up Exports and %u warm-up Imports explored %llu schedules "
                                  "without finishing, "
                                  "expected at most %llu (--max-schedules to change)", we, wi,
                                  static_cast<unsigned long long>(s.schedules),
                                  static_cast<unsigned long long>(g_limits.schedules));
                    s.verdict.add_watchdog(m);
                    stop = true;
                    break;
                }
                int d = static_cast<int>(path.size()) - 1;
                while (d >= 0 && path[d] + 1 >= counts[d]) --d;
                if (d < 0) break;
                path.resize(d + 1);
                counts.resize(d + 1);
                ++path[d];
            }
            double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("  start state: %u warm-up Exports, %u warm-up Imports: %llu schedules, "
                        "%llu same-cycle collisions, %llu Imports checked (%.1f s)\n",
                        we, wi, static_cast<unsigned long long>(s.schedules),
                        static_cast<unsigned long long>(s.collisions),
                        static_cast<unsigned long long>(s.imports), sec);
            std::fflush(stdout);
            char b[200];
            std::snprintf(b, sizeof b, "%s{\"warm_exports\": %u, \"warm_imports\": %u, \"schedules\": %llu, \"collisions\": %llu}",
                          states.size() > 1 ? ", " : "", we, wi, static_cast<unsigned long long>(s.schedules),
                          static_cast<unsigned long long>(s.collisions));
            states += b;
            total += s.schedules;
            collisions += s.collisions;
            imports += s.imports;
            imports_new += s.imports_new;
            all.merge(s.verdict);
        }
    }
    std::printf("exhaustive: %llu schedules explored, %llu same-cycle same-byte collisions, "
                "%llu Imports checked (%llu New), %llu violations\n",
                static_cast<unsigned long long>(total), static_cast<unsigned long long>(collisions),
                static_cast<unsigned long long>(imports), static_cast<unsigned long long>(imports_new),
                static_cast<unsigned long long>(all.total()));
    all.print();
    rep.str("variant", o.variant).num("payload_bytes", o.payload).num("schedules", total)
        .num("collisions", collisions).num("imports_checked", imports).num("imports_new", imports_new)
        .num("violations_total", all.total()).raw("violations", all.json()).raw("start_states", states + "]")
        .str("caught_by", all.caught_by());
    if (!o.report.empty()) rep.write(o.report);
    return verdict_status(o, all, "schedules", total);
}

// ------------------------------------------------------------------- random
//
// The speed model: each CPU runs on its own clock, expressed as RAM cycles
// per CPU cycle (>= 1), and spends 0-2 CPU cycles between accesses, with rare
// long stalls.  log10(writer speed / reader speed) drifts as a random walk
// over [-2, 2]: ratios from 1:100 to 100:1, the faster side at full speed.
struct Timing {
    std::mt19937_64 rng;
    double log_ratio = 0.0;      // log10(writer speed / reader speed)
    double period[2] = {1, 1};   // RAM cycles per CPU cycle, per port
    double frac[2] = {0, 0};
    uint64_t next_drift = 0;

    explicit Timing(uint64_t seed) : rng(seed) {}
    double uni() { return std::uniform_real_distribution<double>(0, 1)(rng); }
    void drift(uint64_t now, int writer_port) {
        if (now < next_drift) return;
        next_drift = now + 500 + rng() % 3000;
        log_ratio += std::normal_distribution<double>(0, 0.35)(rng);
        if (uni() < 0.02) log_ratio = uni() * 4 - 2;   // an occasional jump
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

Channel random_channel(std::mt19937_64 &rng)
{
    Channel c;
    c.size = 1 + static_cast<uint32_t>(rng() % kMaxPayload);
    uint32_t bytes = ALB_CHANNEL_BYTES(c.size);
    c.base = static_cast<uint32_t>(rng() % ((RamBus::kBytes - bytes) / 4 + 1)) * 4;
    c.prod_port = static_cast<int>(rng() & 1);
    c.cons_port = 1 - c.prod_port;
    return c;
}

struct RandomStats {
    uint64_t imports = 0, imports_new = 0, exports = 0, cycles = 0, accesses = 0, segments = 0;
    uint64_t worst_iter = 0, worst_acc = 0;
    uint64_t worst_export_cycles = 0, worst_import_cycles = 0, worst_segment_cycles_per_import = 0;
    uint64_t b_imports[ProtocolChecker::kBuckets] = {}, b_worst_iter[ProtocolChecker::kBuckets] = {};
    uint64_t b_worst_acc[ProtocolChecker::kBuckets] = {}, b_iter_sum[ProtocolChecker::kBuckets] = {};
    uint64_t ov_min[3] = {~0ull, ~0ull, ~0ull}, ov_max[3] = {};
    Verdict verdict;
};

void run_random(uint64_t target, uint64_t seed, RandomStats &st, bool stop_on_violation, bool progress)
{
    std::mt19937_64 rng(seed);
    Timing tm(seed ^ 0xA5A5A5A5ull);
    uint64_t next_report = target / 10;
    while (st.imports < target) {
        Channel c = random_channel(rng);
        Run run(c);
        run.prod.align = static_cast<unsigned>(rng() % 4);
        run.cons.align = static_cast<unsigned>(rng() % 4);
        Driver drv(tm);
        uint64_t seg = std::min<uint64_t>(target - st.imports, 5000 + rng() % 20000);
        uint64_t c0 = g_bus->cycle(), a0 = g_bus->accesses;
        const uint64_t budget = seg * g_limits.segment_cycles_per_import;
        char m[320];
        while (run.chk.imports < seg) {
            tm.drift(g_bus->cycle(), c.prod_port);
            drv.cycle();
            if (run.producer().faulted || run.consumer().faulted || drv.ram_dead) break;
            if (stop_on_violation && counted_violations(run.chk)) break;
            if (run.producer().finished() || run.consumer().finished()) {
                // Both programs call for ever: one that returned failed to attach.
                std::snprintf(m, sizeof m, "the %s program returned after %llu calls (attach result %d), expected it "
                              "to keep calling", run.producer().finished() ? "producer" : "consumer",
                              static_cast<unsigned long long>(run.producer().finished() ? run.prod.calls : run.cons.calls),
                              run.producer().finished() ? run.prod.attach_rc : run.cons.attach_rc);
                st.verdict.add_other(m);
                break;
            }
            if ((g_bus->cycle() & 1023u) == 0) {
                std::string late = run.overdue_call();
                if (late.empty() && g_bus->cycle() - c0 > budget) {
                    std::snprintf(m, sizeof m, "watchdog: a channel of %u bytes checked only %llu of %llu Imports in "
                                  "%llu cycles, expected them within %llu cycles (%llu per Import)",
                                  c.size, static_cast<unsigned long long>(run.chk.imports),
                                  static_cast<unsigned long long>(seg), static_cast<unsigned long long>(g_bus->cycle() - c0),
                                  static_cast<unsigned long long>(budget),
                                  static_cast<unsigned long long>(g_limits.segment_cycles_per_import));
                    late = m;
                }
                if (!late.empty()) {
                    st.verdict.add_watchdog(late);
                    break;
                }
            }
        }
        ++st.segments;
        st.imports += run.chk.imports;
        st.imports_new += run.chk.imports_new;
        st.exports += run.chk.exports;
        st.cycles += g_bus->cycle() - c0;
        st.accesses += g_bus->accesses - a0;
        st.worst_iter = std::max(st.worst_iter, run.chk.worst_import_iterations);
        st.worst_export_cycles = std::max(st.worst_export_cycles, run.prod.worst_call_cycles);
        st.worst_import_cycles = std::max(st.worst_import_cycles, run.cons.worst_call_cycles);
        if (run.chk.imports)
            st.worst_segment_cycles_per_import = std::max(st.worst_segment_cycles_per_import,
                                                          (g_bus->cycle() - c0) / run.chk.imports);
        st.worst_acc = std::max(st.worst_acc, run.chk.worst_import_accesses);
        for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
            st.b_imports[k] += run.chk.bucket_imports[k];
            st.b_iter_sum[k] += run.chk.bucket_iter_sum[k];
            st.b_worst_iter[k] = std::max(st.b_worst_iter[k], run.chk.bucket_worst_iter[k]);
            st.b_worst_acc[k] = std::max(st.b_worst_acc[k], run.chk.bucket_worst_accesses[k] -
                                         std::min<uint64_t>(run.chk.bucket_worst_accesses[k], (c.size + 3) / 4));
        }
        for (int k = 0; k < 3; ++k) {
            st.ov_min[k] = std::min(st.ov_min[k], run.chk.overhead_min[k]);
            st.ov_max[k] = std::max(st.ov_max[k], run.chk.overhead_max[k]);
        }
        if (drv.ram_dead) st.verdict.add_other(drv.dead_why);
        if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
            st.verdict.add_other("attach failed on a valid RAM image");
        st.verdict.take(run);
        st.verdict.take_bus();
        if (stop_on_violation && negative_satisfied(st.verdict)) return;
        // A watchdog or a harness failure means the run cannot go on meaningfully.
        if (st.verdict.watchdog || st.verdict.other) return;
        if (run.chk.imports == 0 && !st.verdict.total()) {
            std::snprintf(m, sizeof m, "a channel of %u bytes checked no Import in %llu cycles, expected %llu",
                          c.size, static_cast<unsigned long long>(g_bus->cycle() - c0),
                          static_cast<unsigned long long>(seg));
            st.verdict.add_other(m);
            return;
        }
        if (progress && st.imports >= next_report) {
            std::printf("  %3.0f%%  %llu Imports checked, %llu violations\n", 100.0 * st.imports / target,
                        static_cast<unsigned long long>(st.imports),
                        static_cast<unsigned long long>(st.verdict.total()));
            std::fflush(stdout);
            next_report += target / 10;
        }
    }
}

std::string bucket_json(const RandomStats &st)
{
    std::string s = "[";
    for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
        char b[240];
        double lo = -2.0 + 0.5 * k;
        std::snprintf(b, sizeof b,
                      "%s{\"log10_ratio_from\": %.1f, \"log10_ratio_to\": %.1f, \"imports\": %llu, "
                      "\"mean_iterations\": %.4f, \"worst_iterations\": %llu, \"worst_control_accesses\": %llu}",
                      k ? ", " : "", lo, lo + 0.5, static_cast<unsigned long long>(st.b_imports[k]),
                      st.b_imports[k] ? static_cast<double>(st.b_iter_sum[k]) / st.b_imports[k] : 0.0,
                      static_cast<unsigned long long>(st.b_worst_iter[k]),
                      static_cast<unsigned long long>(st.b_worst_acc[k]));
        s += b;
    }
    return s + "]";
}

void print_buckets(const RandomStats &st)
{
    std::printf("  termination: Import loop iterations against writer/reader speed ratio\n");
    std::printf("    %-17s %12s %10s %10s %16s\n", "writer:reader", "imports", "mean iter", "worst iter", "worst ctl acc");
    for (int k = 0; k < ProtocolChecker::kBuckets; ++k) {
        double lo = -2.0 + 0.5 * k;
        char range[40];
        std::snprintf(range, sizeof range, "%g..%g", std::pow(10, lo), std::pow(10, lo + 0.5));
        std::printf("    %-17s %12llu %10.3f %10llu %16llu\n", range, static_cast<unsigned long long>(st.b_imports[k]),
                    st.b_imports[k] ? static_cast<double>(st.b_iter_sum[k]) / st.b_imports[k] : 0.0,
                    static_cast<unsigned long long>(st.b_worst_iter[k]),
                    static_cast<unsigned long long>(st.b_worst_acc[k]));
    }
}

int mode_random(const Options &o)
{
    std::printf("random: %llu Imports, seed %llu, speed ratios 1:100..100:1, payloads 1..%u bytes\n",
                static_cast<unsigned long long>(o.imports), static_cast<unsigned long long>(o.seed), kMaxPayload);
    std::fflush(stdout);
    RandomStats st;
    auto t0 = std::chrono::steady_clock::now();
    run_random(o.imports, o.seed, st, o.expect_violation, !o.expect_violation);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("random: %llu Imports checked (%llu New), %llu Exports, %llu channels, %llu cycles, "
                "%llu violations (%.1f s)\n",
                static_cast<unsigned long long>(st.imports), static_cast<unsigned long long>(st.imports_new),
                static_cast<unsigned long long>(st.exports), static_cast<unsigned long long>(st.segments),
                static_cast<unsigned long long>(st.cycles), static_cast<unsigned long long>(st.verdict.total()), sec);
    st.verdict.print();
    const char *names[3] = {"Import, no new data", "Import, new data", "Export"};
    const uint64_t want[3] = {1, 3, 2};
    bool overhead_ok = true;
    std::printf("  RAM accesses beyond the payload, undisturbed calls (expected 1, 3, 2):\n");
    for (int k = 0; k < 3; ++k) {
        if (st.ov_min[k] > st.ov_max[k]) {
            std::printf("    %-20s none seen\n", names[k]);
            overhead_ok = false;
            continue;
        }
        std::printf("    %-20s %llu..%llu\n", names[k], static_cast<unsigned long long>(st.ov_min[k]),
                    static_cast<unsigned long long>(st.ov_max[k]));
        if (st.ov_min[k] != want[k] || st.ov_max[k] != want[k]) overhead_ok = false;
    }
    print_buckets(st);
    std::printf("  longest calls: Export %llu cycles, Import %llu cycles (watchdog %llu); "
                "worst channel %llu cycles per Import (watchdog %llu)\n",
                static_cast<unsigned long long>(st.worst_export_cycles), static_cast<unsigned long long>(st.worst_import_cycles),
                static_cast<unsigned long long>(g_limits.call_cycles),
                static_cast<unsigned long long>(st.worst_segment_cycles_per_import),
                static_cast<unsigned long long>(g_limits.segment_cycles_per_import));
    if (!o.report.empty()) {
        JsonReport rep;
        char ov[160];
        std::snprintf(ov, sizeof ov, "{\"import_old\": %llu, \"import_new\": %llu, \"export\": %llu}",
                      static_cast<unsigned long long>(st.ov_max[0]), static_cast<unsigned long long>(st.ov_max[1]),
                      static_cast<unsigned long long>(st.ov_max[2]));
        rep.str("variant", o.variant).num("seed", o.seed).num("imports_checked", st.imports)
            .num("imports_new", st.imports_new).num("exports", st.exports).num("channels", st.segments)
            .num("cycles", st.cycles).num("accesses", st.accesses).num("violations_total", st.verdict.total())
            .raw("violations", st.verdict.json()).str("caught_by", st.verdict.caught_by())
            .raw("accesses_beyond_payload", ov).num("worst_import_iterations", st.worst_iter)
            .raw("termination_by_speed_ratio", bucket_json(st)).num("worst_export_cycles", st.worst_export_cycles)
            .num("worst_import_cycles", st.worst_import_cycles)
            .num("worst_channel_cycles_per_import", st.worst_segment_cycles_per_import).num("seconds", sec);
        rep.write(o.report);
    }
    if (o.expect_violation || st.verdict.total()) return verdict_status(o, st.verdict, "Imports", st.imports);
    if (!overhead_ok) {
        std::printf("FAIL: accesses beyond the payload differ from the expected 1, 3, 2\n");
        return 1;
    }
    return 0;
}

// -------------------------------------------------------------------- crash
//
// A victim side stops at access point k of one of its calls: frozen forever
// (never resumed) or reset (its coroutine restarted later, re-attaching from
// the RAM).  The survivor keeps calling; every call must finish within its
// fixed bound and every value stay consistent.
struct CrashResult {
    uint64_t runs = 0, not_reached = 0, survivor_calls = 0, cycles = 0;
    std::string first_not_reached;   // the first crash point never reached, in words
    Verdict verdict;
};

struct CrashPlan : public IssueGate {
    Run &run;
    Driver &drv;
    bool victim_producer, reset;
    unsigned k;
    int vport;
    SideCtx &victim, &surv;
    uint64_t crash_call;
    bool crashed = false;
    uint64_t crash_cycle = 0, restart_at = 0, surv_calls_at_crash = 0;
    uint8_t held = 0;            // ReadLocked of a frozen consumer
    uint64_t held_writes = 0;    // producer writes to it in Exports begun after the freeze
    uint64_t prod_calls_at_crash = 0, next_export_cycle = 0;

    CrashPlan(Run &r, Driver &d, bool vp, bool rs, unsigned kk, uint64_t call)
        : run(r), drv(d), victim_producer(vp), reset(rs), k(kk),
          vport(vp ? r.chan.prod_port : r.chan.cons_port), victim(vp ? r.prod : r.cons),
          surv(vp ? r.cons : r.prod), crash_call(call) {}

    // Stop the victim just before it issues access k of call crash_call or later.
    bool stop_before_issue(int port) override {
        SimCpu &vcpu = g_bus->cpu[vport];
        if (crashed || port != vport || victim.calls < crash_call || vcpu.accesses - victim.call_start_acc != k)
            return false;
        crashed = true;
        crash_cycle = g_bus->cycle();
        surv_calls_at_crash = surv.calls;
        prod_calls_at_crash = run.prod.calls;
        drv.frozen[vport] = true;
        vcpu.has_request = false;
        if (victim_producer) {
            run.chk.producer_restarted();
            run.chk.set_import_iteration_limit(1);   // Actual can no longer change
        } else {
            run.chk.consumer_restarted();
            held = g_bus->ram_byte(run.chan.base + ALB_OFF_READLOCKED);
        }
        return true;
    }
};

void crash_run(uint32_t size, bool victim_producer, bool reset, unsigned k, uint64_t seed, CrashResult &cr)
{
    std::mt19937_64 rng(seed);
    Timing tm(seed * 7 + 3);
    Channel c{64, size, static_cast<int>(seed & 1), static_cast<int>(1 - (seed & 1))};
    Run run(c);
    Driver drv(tm);
    CrashPlan plan(run, drv, victim_producer, reset, k, 3 + rng() % 5);
    drv.gate = &plan;
    SimCpu &vcpu = g_bus->cpu[plan.vport];
    const uint64_t after = 300;
    bool restarted = false, gave_up = false;
    tm.log_ratio = static_cast<double>(rng() % 5) - 2.0;
    const char *vname = victim_producer ? "producer" : "consumer", *sname = victim_producer ? "consumer" : "producer";
    const char *vcall = victim_producer ? "Export" : "Import";
    const uint64_t c0 = g_bus->cycle();
    uint64_t victim_most = 0;    // the most accesses the victim made in one call before the crash
    char m[320];
    for (;;) {
        if (g_bus->cycle() - c0 > g_limits.crash_run_cycles) {
            std::snprintf(m, sizeof m, "watchdog: a crash run (%s %s at access %u of %s, %u-byte payload, seed %llu) "
                          "went on for %llu cycles: %s; expected it within %llu cycles",
                          vname, reset ? "reset" : "frozen", k, vcall, size, static_cast<unsigned long long>(seed),
                          static_cast<unsigned long long>(g_bus->cycle() - c0),
                          plan.crashed ? "the survivor had not made its calls" : "the crash point was not reached",
                          static_cast<unsigned long long>(g_limits.crash_run_cycles));
            cr.verdict.add_watchdog(m);
            break;
        }
        tm.drift(g_bus->cycle(), c.prod_port);
        // A frozen consumer's ReadLocked must be honoured by every Export that
        // begins after the freeze (the one under way may still be writing the
        // buffer the consumer had not yet confirmed).
        if (plan.crashed && !reset && !victim_producer && plan.held >= 1 && plan.held <= 3) {
            if (!plan.next_export_cycle && run.prod.calls > plan.prod_calls_at_crash)
                plan.next_export_cycle = g_bus->cycle();
            if (plan.next_export_cycle && run.chk.producer_wrote_since(plan.held, plan.next_export_cycle))
                ++plan.held_writes;
        }
        if (plan.crashed && reset && !restarted && g_bus->cycle() >= plan.crash_cycle + 1 + (seed % 400)) {
            restarted = true;
            drv.frozen[plan.vport] = false;
            plan.victim.in_call = false;   // the call under way is abandoned
            vcpu.start(victim_producer ? producer_program : consumer_program);
            if (victim_producer) run.chk.set_import_iteration_limit(-1);
        }
        if (!plan.crashed && plan.victim.in_call)
            victim_most = std::max(victim_most, vcpu.accesses - plan.victim.call_start_acc);
        drv.cycle();
        if (vcpu.faulted || g_bus->cpu[1 - plan.vport].faulted || drv.ram_dead) break;
        if (plan.crashed && plan.surv.calls >= plan.surv_calls_at_crash + after) break;
        // A protocol violation already names the fault: no need to go on.
        if (counted_violations(run.chk)) break;
        std::string late = run.overdue_call(drv.frozen);
        if (!late.empty()) {
            cr.verdict.add_watchdog(late);
            break;
        }
        // The crash point is searched for in the planned call and the next
        // ones (an Import with new data is longer than one without); give up
        // after a bounded number of calls.
        if (!plan.crashed && plan.victim.calls > plan.crash_call + g_limits.crash_search_calls) {
            gave_up = true;
            break;
        }
        if (vcpu.finished() || g_bus->cpu[1 - plan.vport].finished()) {
            std::snprintf(m, sizeof m, "the %s program returned (attach result %d), expected it to keep calling",
                          vcpu.finished() ? vname : sname, vcpu.finished() ? plan.victim.attach_rc : plan.surv.attach_rc);
            cr.verdict.add_other(m);
            break;
        }
    }
    if (drv.ram_dead) cr.verdict.add_other(drv.dead_why);
    cr.cycles += g_bus->cycle() - c0;
    ++cr.runs;
    if (!plan.crashed) {
        ++cr.not_reached;
        if (gave_up && cr.first_not_reached.empty()) {
            std::snprintf(m, sizeof m, "the %s never reached access %u of an %s in %llu calls (%u-byte payload; "
                          "its longest call made %llu accesses, expected %u + %u)",
                          vname, k, vcall, static_cast<unsigned long long>(g_limits.crash_search_calls), size,
                          static_cast<unsigned long long>(victim_most), victim_producer ? 2u : 3u, (size + 3) / 4);
            cr.first_not_reached = m;
        }
    } else if (!cr.verdict.watchdog && !counted_violations(run.chk)) {
        uint64_t made = plan.surv.calls - plan.surv_calls_at_crash;
        cr.survivor_calls += made;
        if (made < after) {
            std::snprintf(m, sizeof m, "after the %s crashed at access %u the %s made only %llu calls, expected %llu",
                          vname, k, sname, static_cast<unsigned long long>(made), static_cast<unsigned long long>(after));
            cr.verdict.add_other(m);
        }
        if (victim_producer && !reset && run.chk.last_seq() != run.chk.newest_published_seq()) {
            std::snprintf(m, sizeof m, "frozen producer: the consumer's last value is seq %llu, expected the last published seq %llu",
                          static_cast<unsigned long long>(run.chk.last_seq()),
                          static_cast<unsigned long long>(run.chk.newest_published_seq()));
            cr.verdict.add_other(m);
        }
        if (plan.held_writes) {
            std::snprintf(m, sizeof m, "the producer wrote Buffer%u, held by the frozen consumer's ReadLocked, expected never",
                          plan.held);
            cr.verdict.add_other(m);
        }
    }
    if (run.prod.attach_rc != ALB_OK || run.cons.attach_rc != ALB_OK)
        cr.verdict.add_other("attach failed after a restart");
    cr.verdict.take(run);
    cr.verdict.take_bus();
}

// The crash runs, one per (payload, victim, frozen/reset, access point, seed);
// the enumeration stops at the first run that fails (or, for a negative test,
// once the expected checkers have fired): every run is bounded by its
// watchdogs, so the whole mode is too.

int mode_crash(const Options &o)
{
    CrashResult cr;
    const uint32_t sizes[2] = {12, 33};
    bool stop = false;
    std::printf("crash: each side frozen or reset at every access point of its call, payloads 12 and 33 bytes\n");
    for (uint32_t size : sizes) {
        unsigned words = (size + 3) / 4;
        for (int vp = 1; vp >= 0; --vp) {
            unsigned points = vp ? 2 + words : 3 + words;   // Export: 2 + W; Import (new data): 3 + W
            for (int rs = 0; rs <= 1; ++rs) {
                uint64_t before = cr.runs - cr.not_reached;
                for (unsigned k = 0; k < points && !stop; ++k)
                    for (uint64_t s = 0; s < 8 && !stop; ++s) {
                        crash_run(size, vp != 0, rs != 0, k, o.seed * 1000 + k * 10 + s, cr);
                        stop = o.expect_violation ? negative_satisfied(cr.verdict) : cr.verdict.total() != 0;
                        if (stop)
                            std::printf("  stopped at the first failing run: %s %s at access %u of %s, %u-byte payload, "
                                        "seed %llu\n", vp ? "producer" : "consumer", rs ? "reset" : "frozen", k,
                                        vp ? "Export" : "Import", size,
                                        static_cast<unsigned long long>(o.seed * 1000 + k * 10 + s));
                    }
                std::printf("  %-8s %-6s at %2u access points of %s: %llu runs crashed as planned\n",
                            vp ? "producer" : "consumer", rs ? "reset" : "frozen", points,
                            vp ? "Export" : "Import", static_cast<unsigned long long>(cr.runs - cr.not_reached - before));
                std::fflush(stdout);
                if (stop) break;
            }
            if (stop) break;
        }
        if (stop) break;
    }
    std::printf("crash: %llu runs, %llu crash points not reached, %llu survivor calls checked, %llu cycles, %llu violations\n",
                static_cast<unsigned long long>(cr.runs), static_cast<unsigned long long>(cr.not_reached),
                static_cast<unsigned long long>(cr.survivor_calls), static_cast<unsigned long long>(cr.cycles),
                static_cast<unsigned long long>(cr.verdict.total()));
    cr.verdict.print();
    if (!cr.first_not_reached.empty()) std::printf("  first crash point not reached: %s\n", cr.first_not_reached.c_str());
    if (!o.report.empty()) {
        JsonReport rep;
        rep.str("variant", o.variant).num("runs", cr.runs).num("not_reached", cr.not_reached)
            .num("survivor_calls", cr.survivor_calls).num("cycles", cr.cycles)
            .num("violations_total", cr.verdict.total()).raw("violations", cr.verdict.json())
            .str("caught_by", cr.verdict.caught_by());
        rep.write(o.report);
    }
    if (o.expect_violation || cr.verdict.total()) return verdict_status(o, cr.verdict, "crash runs", cr.runs);
    if (cr.not_reached * 10 > cr.runs) {
        std::printf("FAIL: %llu of %llu crash points were never reached, expected under 10%% (first: %s)\n",
                    static_cast<unsigned long long>(cr.not_reached), static_cast<unsigned long long>(cr.runs),
                    cr.first_not_reached.c_str());
        return 1;
    }
    return 0;
}

// -------------------------------------------------------------------- bench
int mode_bench(const Options &o)
{
    // Idle RTL: the RAM clocked with no CPU, the upper bound of the harness.
    const uint64_t idle_cycles = 20000000;
    auto t0 = std::chrono::steady_clock::now();
    for (uint64_t i = 0; i < idle_cycles; ++i) g_bus->tick();
    double idle_sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    RandomStats st;
    t0 = std::chrono::steady_clock::now();
    run_random(o.imports, o.seed, st, false, false);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double acc_rate = st.accesses / sec, cyc_rate = st.cycles / sec, idle_rate = idle_cycles / idle_sec;
    std::printf("bench: %llu RAM accesses by simulated CPUs in %.2f s: %.2f M accesses/s of wall time\n",
                static_cast<unsigned long long>(st.accesses), sec, acc_rate / 1e6);
    std::printf("bench: %.2f M simulated cycles/s with CPUs, %.2f M cycles/s idle RTL (ratio %.2f)\n",
                cyc_rate / 1e6, idle_rate / 1e6, cyc_rate / idle_rate);
    if (!o.report.empty()) {
        JsonReport rep;
        rep.num("accesses", st.accesses).num("seconds", sec).num("accesses_per_second", acc_rate)
            .num("cycles_per_second", cyc_rate).num("idle_rtl_cycles_per_second", idle_rate)
            .num("with_cpus_over_idle", cyc_rate / idle_rate).num("imports", st.imports);
        rep.write(o.report);
    }
    if (st.verdict.total()) {
        st.verdict.print();
        return verdict_status(o, st.verdict, "Imports", st.imports);
    }
    return 0;
}

int usage()
{
    std::fprintf(stderr,
                 "usage: tb_dpram exhaustive|random|crash|bench [--imports N] [--seed S] [--payload N]\n"
                 "                [--expect-violation] [--expect-caught-by CHECKER]... [--ignore CHECKER]... [--report FILE] [--variant NAME]\n"
                 "                [--trace FILE.vcd [--trace-cycles N]] [--max-schedules N]\n"
                 "checkers: mutual_exclusion definite_results actuality termination ownership\n"
                 "          driver_error byte_atomicity access_time in_channel watchdog\n");
    return 2;
}

bool parse_u64(const char *s, uint64_t &out)
{
    char *end = nullptr;
    unsigned long long v = std::strtoull(s, &end, 10);
    if (!*s || *end) return false;
    out = v;
    return true;
}

}  // namespace

int main(int argc, char **argv)
{
    if (argc < 2) return usage();
    Options o;
    o.mode = argv[1];
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i];
        uint64_t v = 0;
        auto need = [&](const char *what) -> const char * {
            if (i + 1 >= argc) { std::fprintf(stderr, "%s needs a value\n", what); std::exit(2); }
            return argv[++i];
        };
        if (a == "--imports") { if (!parse_u64(need("--imports"), v) || v == 0) { std::fprintf(stderr, "--imports: expected a positive integer\n"); return 2; } o.imports = v; }
        else if (a == "--seed") { if (!parse_u64(need("--seed"), v)) { std::fprintf(stderr, "--seed: expected an integer\n"); return 2; } o.seed = v; }
        else if (a == "--payload") { if (!parse_u64(need("--payload"), v)) { std::fprintf(stderr, "--payload: expected an integer\n"); return 2; } o.payload = static_cast<uint32_t>(v); }
        else if (a == "--report") o.report = need("--report");
        else if (a == "--max-schedules") { if (!parse_u64(need("--max-schedules"), v) || v == 0) { std::fprintf(stderr, "--max-schedules: expected a positive integer\n"); return 2; } g_limits.schedules = v; }
        else if (a == "--trace") o.trace = need("--trace");
        else if (a == "--trace-cycles") { if (!parse_u64(need("--trace-cycles"), v) || v == 0) { std::fprintf(stderr, "--trace-cycles: expected a positive integer\n"); return 2; } o.trace_cycles = v; }
        else if (a == "--variant") o.variant = need("--variant");
        else if (a == "--expect-violation") o.expect_violation = true;
        else if (a == "--expect-caught-by") {
            std::string n = need("--expect-caught-by");
            int k = 0;
            while (k < IGN_COUNT && n != ignorable_name(k)) ++k;
            if (k == IGN_COUNT) { std::fprintf(stderr, "--expect-caught-by: unknown checker %s\n", n.c_str()); return 2; }
            o.expect_violation = true;
            o.expect_caught_by.push_back(n);
        }
        else if (a == "--ignore") {
            std::string n = need("--ignore");
            int k = 0;
            while (k < IGN_COUNT && n != ignorable_name(k)) ++k;
            if (k == IGN_COUNT) { std::fprintf(stderr, "--ignore: unknown checker %s\n", n.c_str()); return 2; }
            g_ignored |= 1u << k;
        }
        else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return usage(); }
    }
    g_opts = &o;
    SimCpu::arm_handoff_watchdog(10);
    RamBus bus;
    g_bus = &bus;
    if (!o.trace.empty()) {
        if (!bus.trace(o.trace.c_str(), o.trace_cycles)) {
            std::fprintf(stderr, "--trace: cannot write %s (is this binary built with --trace?)\n", o.trace.c_str());
            return 2;
        }
        std::printf("wave: %s, the first %llu cycles\n", o.trace.c_str(), static_cast<unsigned long long>(o.trace_cycles));
    }
    if (o.mode == "exhaustive") return mode_exhaustive(o);
    if (o.mode == "random") return mode_random(o);
    if (o.mode == "crash") return mode_crash(o);
    if (o.mode == "bench") return mode_bench(o);
    return usage();
}
