// board_program.cpp -- see board_program.h.
#include "board_program.h"
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include "alb_port.h"   // the faulty producer writes a control byte itself
#include "fresh_scenario.h"
#include "system_modes.h"

namespace tbsys {

SystemSim *g_sim = nullptr;
const Options *g_opts = nullptr;
bool g_corrupted = false;
SystemChecker *g_chk = nullptr;
const Plan *g_plan = nullptr;
StatusSeen g_status;

namespace {
uint64_t now() { return g_sim->cycle(); }

bool parse_num(const char *s, double &out)
{
    char *end = nullptr;
    out = std::strtod(s, &end);
    return *s && !*end;
}

int usage(const char *why)
{
    std::fprintf(stderr, "tb_system: %s\n"
                 "usage: tb_system --plan DIR [--cycles N] [--seed S] [--fault-rate R] [--burst L]\n"
                 "                 [--fault-clocking access|clock] [--land-actual P] [--land-kind 3|1|13]\n"
                 "                 [--require-landed-same 1] [--producer-interval CH:CLOCKS[:BURST]]\n"
                 "                 [--producer-stop CH|all:CYCLE] [--stretch-export CH:CLOCKS]\n"
                 "                 [--require-late-publication CH] [--require-skipped CH] [--require-fragments N|plan]\n"
                 "                 [--bounds-at-target FILE] [--require-cut-fragments N]\n"
                 "                 [--stretch-import CH:BOARD:CLOCKS] [--dead-board B --dead-at C]\n"
                 "                 [--corrupt-entry K] [--flip-rom-bit WORD:BIT] [--rom FILE] [--report FILE] [--label NAME]\n"
                 "                 [--ages FILE] [--handoff-watchdog S] [--cpu-start C]\n"
                 "                 [--latency-scale F] [--expect-caught-by CHECKER]... [--expect-failure TEXT]...\n", why);
    return 2;
}
}  // namespace

void board_program(SimCpu &cpu)
{
    BoardCtx &b = *static_cast<BoardCtx *>(cpu.context);
    alignas(8) uint8_t buf[1100];
    for (Role &r : b.roles) {
        const PlanChannel &c = g_plan->channels[r.chan];
        // A four-slot channel's sides are set up with its kind.  A four-slot
        // consumer starts cold (alb_consumer_init: Buffer1 counts as read);
        // attach would forget the last value read and make the first Import
        // New even if the image's value is all there is (docs/four_slot.md).
        const unsigned kind = c.four_slot ? ALB_FOUR_SLOT : ALB_THREE_BUFFER;
        if (r.dest < 0) {
            alb_channel_setup_kind(&r.ch, c.src_base, c.size, kind);
            if (alb_producer_attach(&r.ch) != ALB_OK) ++b.attach_errors;
        } else {
            alb_channel_setup_kind(&r.ch, c.dests[r.dest].base, c.dest_size(), kind);
            if ((c.four_slot ? alb_consumer_init(&r.ch) : alb_consumer_attach(&r.ch)) != ALB_OK) ++b.attach_errors;
        }
    }
    for (;;) {
        bool called = false;
        for (Role &r : b.roles) {
            const PlanChannel &c = g_plan->channels[r.chan];
            called = called || r.dest >= 0 || (now() >= r.next_due && !producer_stopped(*g_plan, *g_opts, c, now()));
            if (r.dest < 0) {
                if (!g_corrupted && r.chan == g_opts->corrupt_channel && now() >= g_opts->corrupt_at) {
                    g_corrupted = true;   // a faulty producer: an out-of-range Actual,
                    alb_wr8(c.src_base + ALB_OFF_ACTUAL, 7);   // left there for two cycles
                    r.next_due = now() + 2 * g_plan->cycle;
                }
                if (now() < r.next_due || producer_stopped(*g_plan, *g_opts, c, now())) continue;
                ++r.seq;
                channel_value(c.id, r.seq, buf, c.size);
                const bool request = g_modes && g_modes->active() && c.id == g_plan->mode_request;
                if (request) {   // a mode request: the mode's number (system_modes.h)
                    const uint32_t mode = g_modes->pick(b.rng);
                    std::memcpy(buf, &mode, sizeof mode);
                    g_modes->requested(mode);
                }
                int rc = alb_export(&r.ch, buf);
                if (rc == ALB_OK) g_chk->exported(r.chan, r.seq);
                const bool more = ++r.burst_done < r.burst;   // the next of a burst: at once
                if (!more) r.burst_done = 0;
                r.next_due = now() + (more ? 0 : request ? g_modes->interval(b.rng)
                                                         : r.interval_lo + b.rng() % (r.interval_hi - r.interval_lo + 1));
            } else {
                uint64_t begin = now();
                // A four-slot value is aged from the Import's start (its first
                // control-word load): actuality holds from there.
                const uint32_t time_at_begin = b.global_time + static_cast<uint32_t>(begin - b.global_at);
                int rc = alb_import(&r.ch, buf);
                if (r.status_channel && rc == ALB_NEW) {
                    uint32_t w[1 + 2 * 32] = {};
                    std::memcpy(w, buf, std::min<size_t>(sizeof w, 4 * c.words));
                    uint64_t t = 0, re = 0, ab = 0, co = 0;
                    for (uint32_t k = 0; 1 + 2 * k + 1 < c.words; ++k) {
                        t += w[1 + 2 * k] >> 16;
                        re += w[1 + 2 * k] & 0xFFFFu;
                        ab += w[2 + 2 * k] >> 16;
                        co += w[2 + 2 * k] & 0xFFFFu;
                    }
                    ++g_status.imports;
                    g_status.transfers = std::max(g_status.transfers, t);
                    g_status.retries = std::max(g_status.retries, re);
                    g_status.abandoned = std::max(g_status.abandoned, ab);
                    g_status.corrupt = std::max(g_status.corrupt, co);
                    g_status.rom_errors = std::max<uint64_t>(g_status.rom_errors, w[0] >> 16);
                    if (g_modes && g_modes->active()) {   // the rejected requests it counts (system_modes.h)
                        uint32_t taken_at = 0;
                        std::memcpy(&taken_at, buf + c.taken_at_offset(), 4);
                        g_modes->status_read(taken_at, co);
                    }
                }
                if (g_modes && c.id == g_plan->mode_info && rc == ALB_NEW) {
                    uint32_t w[2];
                    std::memcpy(w, buf, sizeof w);
                    g_modes->mode_imported(b.board, w[0], w[1]);
                }
                if (r.time_channel && rc == ALB_NEW) {
                    std::memcpy(&b.global_time, buf, 4);
                    b.global_at = now();
                }
                uint32_t local_time = c.four_slot ? time_at_begin
                                                  : b.global_time + static_cast<uint32_t>(now() - b.global_at);
                g_chk->imported(r.chan, r.dest, rc, buf, begin, now(), local_time);
            }
        }
        if (!called) cpu.idle();   // nothing due: let a clock pass
    }
}

void load_images(const Plan &plan)
{
    for (const PlanChannel &c : plan.channels) {
        if (c.copy()) {
            std::vector<uint8_t> img(instance_bytes(c, c.size), 0);
            img[0] = img[1] = ALB_BUFFER1;
            channel_value(c.id, 0, &img[ALB_OFF_BUFFER(1u, c.size)], c.size);
            g_sim->load(c.src_board, c.src_base, img.data(), static_cast<uint32_t>(img.size()));
        }
        for (const PlanDest &d : c.dests) {
            std::vector<uint8_t> img(instance_bytes(c, c.dest_size()), 0);
            img[0] = img[1] = ALB_BUFFER1;
            if (c.copy()) channel_value(c.id, 0, &img[ALB_OFF_BUFFER(1u, c.dest_size())], c.size);
            g_sim->load(d.board, d.base, img.data(), static_cast<uint32_t>(img.size()));
        }
    }
}

bool entry_exists(const std::string &rom, int k)
{
    std::ifstream in(rom);
    std::string h0;
    if (!std::getline(in, h0)) return false;
    uint32_t ne = (static_cast<uint32_t>(std::strtoul(h0.c_str(), nullptr, 16)) >> 8) & 0xFFu;
    return k >= 0 && static_cast<uint32_t>(k) < ne;
}

int parse_options(int argc, char **argv, Options &o)
{
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (i + 1 >= argc) return usage(("missing value for " + a).c_str());
        const char *v = argv[++i];
        double x = 0;
        bool num = parse_num(v, x);
        if (a == "--plan") o.plan_dir = v;
        else if (a == "--rom") o.rom = v;
        else if (a == "--report") o.report = v;
        else if (a == "--ages") o.ages = v;
        else if (a == "--label") o.label = v;
        else if (a == "--cycles" && num && x >= 1000) o.cycles = static_cast<uint64_t>(x);
        else if (a == "--seed" && num && x >= 0) o.seed = static_cast<uint64_t>(x);
        else if (a == "--cpu-start" && num && x >= 0) o.cpu_start = static_cast<uint64_t>(x);
        else if (a == "--handoff-watchdog" && num && x >= 1 && x <= 3600)
            o.handoff_watchdog_s = static_cast<unsigned>(x);
        else if (a == "--fault-rate" && num && x >= 0 && x < 1) o.fault_rate = x;
        else if (a == "--burst" && num) o.burst = x;
        else if (a == "--fault-clocking" && (std::string(v) == "access" || std::string(v) == "clock"))
            o.fault_per_clock = std::string(v) == "clock";
        else if (a == "--expect-failure") o.expect_failure.push_back(v);
        else if (a == "--land-actual" && num && x >= 0 && x <= 1) o.land_actual = x;
        else if (a == "--land-kind" && num && (x == 1 || x == 3 || x == 13)) o.land_kind = static_cast<int>(x);
        else if (a == "--require-landed-same" && num) o.require_landed_same = x != 0;
        else if (a == "--require-late-publication") o.require_late = v;
        else if (a == "--require-skipped") o.require_skipped.push_back(v);
        else if (a == "--bounds-at-target") o.bounds_at_target = v;
        else if (a == "--require-cut-fragments" && num && x >= 0) o.require_cut = static_cast<uint64_t>(x);
        else if (a == "--require-fragments" && std::string(v) == "plan") o.require_fragments_plan = true;
        else if (a == "--require-fragments" && num && x >= 0) o.require_fragments = static_cast<uint64_t>(x);
        else if (a == "--producer-interval") {
            char name[64] = {};
            unsigned long long clk = 0, burst = 1;
            const int n = std::sscanf(v, "%63[^:]:%llu:%llu", name, &clk, &burst);
            if (n < 2 || clk == 0 || burst == 0 || burst > 64)
                return usage("--producer-interval needs CHANNEL:CLOCKS[:BURST] (BURST 1..64)");
            o.slow_channel = name;
            o.slow_interval = clk;
            o.slow_burst = burst;
        }
        else if (a == "--producer-stop" || a == "--stretch-export") {
            char name[64] = {};
            unsigned long long n = 0;
            if (std::sscanf(v, "%63[^:]:%llu", name, &n) != 2 || (a == "--stretch-export" && (n == 0 || n > 100000)))
                return usage((a + " needs CHANNEL:" + (a == "--producer-stop" ? "CYCLE" : "CLOCKS (1..100000)")).c_str());
            (a == "--producer-stop" ? o.stop_channel : o.stretch_export_channel) = name;
            (a == "--producer-stop" ? o.stop_at : o.stretch_export_clocks) = n;
        }
        else if (a == "--stretch-import") {
            char name[64] = {};
            unsigned long long bd = 0, clk = 0;
            if (std::sscanf(v, "%63[^:]:%llu:%llu", name, &bd, &clk) != 3 || bd >= SystemSim::kBoards || clk == 0)
                return usage("--stretch-import needs CHANNEL:BOARD:CLOCKS");
            o.stretch_channel = name;
            o.stretch_board = static_cast<int>(bd);
            o.stretch_clocks = clk;
        }
        else if (a == "--dead-board" && num && x >= 0 && x < SystemSim::kBoards) o.dead_board = static_cast<int>(x);
        else if (a == "--dead-at" && num && x >= 0) o.dead_at = static_cast<uint64_t>(x);
        else if (a == "--corrupt-entry" && num && x >= 0) o.corrupt_entry = static_cast<int>(x);
        else if (a == "--flip-rom-bit") {
            if (std::sscanf(v, "%d:%d", &o.flip_word, &o.flip_bit) != 2 || o.flip_word < 0 || o.flip_bit < 0 ||
                o.flip_bit > 31)
                return usage("--flip-rom-bit needs WORD:BIT (BIT 0..31)");
        }
        else if (a == "--corrupt-actual") {
            unsigned long long ch = 0, at = 0;
            if (std::sscanf(v, "%llu:%llu", &ch, &at) != 2) return usage("--corrupt-actual needs CHANNEL:CYCLE");
            o.corrupt_channel = static_cast<int>(ch);
            o.corrupt_at = at;
        }
        else if (a == "--latency-scale" && num && x > 0) o.latency_scale = x;
        else if (a == "--trace-bus" && std::sscanf(v, "%llu:%llu", reinterpret_cast<unsigned long long *>(&o.trace_from),
                                                   reinterpret_cast<unsigned long long *>(&o.trace_to)) == 2) {}
        else if (a == "--expect-caught-by") {
            int k = 0;
            while (k < SystemChecker::KINDS && std::string(v) != SystemChecker::kind_name(k)) ++k;
            if (k == SystemChecker::KINDS) return usage(("unknown checker " + std::string(v)).c_str());
            o.expect_caught_by.push_back(v);
        }
        else return usage(("bad option or value: " + a + " " + v).c_str());
    }
    if (o.plan_dir.empty()) return usage("--plan is required");
    const std::string bad = FaultModel::invalid(o.fault_rate, o.burst);
    if (!bad.empty()) return usage(bad.c_str());
    return -1;
}

}  // namespace tbsys
