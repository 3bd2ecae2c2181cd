// tb_dpram_common.cpp -- what every mode shares: the simulated programs, the checks and the verdict.
#include "tb_dpram.h"

namespace tbd {

const char *ignorable_name(int k)
{
    if (k < ProtocolChecker::KINDS) return ProtocolChecker::kind_name(k);
    static const char *n[] = {"byte_atomicity", "access_time", "in_channel", "watchdog"};
    return n[k - ProtocolChecker::KINDS];
}

void producer_program(SimCpu &cpu)
{
    SideCtx &p = *static_cast<SideCtx *>(cpu.context);
    alignas(8) uint8_t buf[kMaxPayload + 8];
    alb_channel_t ch;
    cpu.warmup = true;
    alb_channel_setup_kind(&ch, p.chan.base, p.chan.size, static_cast<unsigned>(g_kind));
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
    alb_channel_setup_kind(&ch, c.chan.base, c.chan.size, static_cast<unsigned>(g_kind));
    // A four-slot consumer that attaches forgets the last value it read (its
    // first Import is New): on a fresh channel it starts cold instead, with
    // Buffer1's initial value counted as read, as the checker expects.
    c.attach_rc = g_kind == ALB_FOUR_SLOT && c.calls == 0 ? alb_consumer_init(&ch) : alb_consumer_attach(&ch);
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
// initial value (seq 0); the slot bytes (four-slot) and the reserved bytes 0;
// the other buffers hold garbage.
void load_image(RamBus &bus, const Channel &c)
{
    std::vector<uint8_t> img(chan_bytes(c.size), 0xEE);
    img[ALB_OFF_ACTUAL] = ALB_BUFFER1;
    img[ALB_OFF_READLOCKED] = ALB_BUFFER1;
    img[2] = img[3] = 0;
    make_value(0, &img[ALB_OFF_BUFFER(1u, c.size)], c.size);
    bus.load(c.base, img.data(), static_cast<uint32_t>(img.size()));
}

uint64_t counted_violations(const ProtocolChecker &chk)
{
    uint64_t t = 0;
    for (int k = 0; k < ProtocolChecker::KINDS; ++k)
        if (!ignored(k)) t += chk.violations[k];
    return t;
}

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

}  // namespace tbd
