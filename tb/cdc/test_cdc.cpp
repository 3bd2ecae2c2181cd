// test_cdc -- self-checking test of albatross_dpram behind two albatross_wb_cdc
// bridges with three independent clocks (top: tb/cdc/tb_dpram_async.v).
//
// The RAM clock is fixed; the two CPU clocks drift randomly so that their
// frequency ratio wanders over 1:100..100:1.  Clocks come from this event loop
// (next edge first; coincident edges in one eval()).  Each CPU issues random
// reads and writes with random byte lanes to a few hot words, random idle gaps,
// and now and then abandons a request by dropping cyc before its ack.
//
// Checkers (each failure says what was expected and what came):
//   atomicity  every byte a CPU read returns is a value the byte held at some
//              time between stb and ack, from a reference memory built from the
//              RAM-side bus of both bridges (a torn or invented byte fails);
//   latency    every access acks within the bound documented in
//              rtl/albatross_wb_cdc.v, with Ts the longest CPU period and Tm
//              the RAM period in its window;
//   visibility every acked write is performed once on the RAM, inside its
//              window, with its own adr/sel/data; every acked read returns the
//              data of its own RAM read (also right after an abandon); a read
//              returns the CPU's own last write to a byte unless the byte was
//              written again since;
//   ram        albatross_dpram reads return the reference value, and the RAM
//              bus of each bridge follows Wishbone (stb held stable until ack);
//   coverage   the run reached the frequency ratios, collisions and abandons
//              it is meant to exercise.
// Exit status 0 if all pass, else 64 + a bit mask of the failed checkers
// (1 atomicity, 2 latency, 4 visibility, 8 ram, 16 coverage).
//
// --inject=MODE deliberately breaks one thing in this harness (never the RTL)
// to prove a checker can fail: torn (flip one byte of a read now and then),
// latency (check against a too small bound), write (drive corrupted write
// data now and then), ram (corrupt a RAM-side read sample now and then).
//
// Options: --seed=N --accesses=N --inject=MODE --json=PATH
#include "Vtb_dpram_async.h"
#include "verilated.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <random>
#include <string>
#include <sys/stat.h>
#include <vector>

#ifndef ADDR_WIDTH
#define ADDR_WIDTH 8
#endif
#ifndef SYNC_STAGES
#define SYNC_STAGES 2
#endif

static const uint32_t ADDR_MASK = (1u << ADDR_WIDTH) - 1u;
static const uint32_t NWORDS    = 1u << ADDR_WIDTH;
static const uint64_t TM        = 10000;  // RAM clock period, ps (100 MHz)
static const double   LN10      = std::log(10.0);
static const int      N         = SYNC_STAGES;

// ------------------------------------------------------------------ checkers
enum { CHK_ATOM, CHK_LAT, CHK_VIS, CHK_RAM, CHK_COV, CHK_COUNT };
static const char *const CHK_NAME[CHK_COUNT] = {"atomicity", "latency", "visibility", "ram",
                                                "coverage"};
static uint64_t g_fail[CHK_COUNT];
static uint64_t g_checks[CHK_COUNT];
static const uint64_t MAX_PRINT = 8;

static void fail(int chk, const char *fmt, ...) {
    if (g_fail[chk]++ < MAX_PRINT) {
        va_list ap;
        va_start(ap, fmt);
        std::printf("FAIL %s: ", CHK_NAME[chk]);
        std::vprintf(fmt, ap);
        std::printf("\n");
        va_end(ap);
    } else if (g_fail[chk] == MAX_PRINT + 1) {
        std::printf("FAIL %s: (further failures of this checker not printed)\n", CHK_NAME[chk]);
    }
}

// ------------------------------------------------------------------ random
static std::mt19937_64 g_rng;
static uint32_t rnd32() { return (uint32_t)g_rng(); }
static uint32_t rnd(uint32_t n) { return (uint32_t)(g_rng() % n); }           // 0..n-1
static bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(g_rng) < p; }
static double gauss() { return std::normal_distribution<double>(0, 1)(g_rng); }

// ------------------------------------------------------------------ reference memory
// Per byte, the history of its values: (time of the RAM access, value).  The
// first entry (time 0) holds the power-up value, unknown until a RAM read
// shows it.
static const uint16_t UNKNOWN = 0x100;
struct Hist {
    std::deque<std::pair<uint64_t, uint16_t>> h;
};
static std::vector<Hist> g_ref;  // NWORDS * 4

static uint16_t ref_now(uint32_t adr, int b) { return g_ref[adr * 4 + b].h.back().second; }

// Values byte (adr,b) held at some time in [t0, t1]: the value before t0 and
// every value written in [t0, t1].  Returns false if any of them is unknown.
static bool ref_allowed(uint32_t adr, int b, uint64_t t0, uint64_t t1, std::vector<uint8_t> &out) {
    const auto &h = g_ref[adr * 4 + b].h;
    out.clear();
    bool known = true;
    size_t i = 0;
    while (i + 1 < h.size() && h[i + 1].first < t0) ++i;  // h[i]: value before t0
    for (; i < h.size() && (h[i].first <= t1 || out.empty()); ++i) {
        if (h[i].second == UNKNOWN) {
            known = false;
        } else {
            out.push_back((uint8_t)h[i].second);
        }
        if (h[i].first > t1) break;
    }
    return known;
}

// True if byte (adr,b) was written at a time in (tw, t1].
static bool ref_written_after(uint32_t adr, int b, uint64_t tw, uint64_t t1) {
    const auto &h = g_ref[adr * 4 + b].h;
    for (size_t i = h.size(); i-- > 0;) {
        if (h[i].first <= tw) return false;
        if (h[i].first <= t1) return true;
    }
    return false;
}

// Drop history older than t (keeping the value held at t).
static void ref_prune(uint64_t t) {
    for (auto &hb : g_ref) {
        while (hb.h.size() > 1 && hb.h[1].first < t) hb.h.pop_front();
    }
}

// ------------------------------------------------------------------ options
static std::string g_inject;  // "", torn, latency, write, ram
static uint64_t g_seed = 1;
static uint64_t g_accesses = 60000;
static std::string g_json;

// ------------------------------------------------------------------ clocks
// Frequency drift: rho = ln(fA/fB) wanders in [-ln 100, ln 100], the common
// part c so that both periods stay within [TM/10, 10*TM].  Each moves at a
// randomly drifting speed, bounces off its limits and now and then turns
// round at random; one step per completed access.
static double g_turn_p;  // chance of a random turn per step
struct Walk {
    double x = 0, dir = 1, speed = 0;
    void step(double lim, double vmax) {
        speed = std::max(0.1 * vmax, std::min(vmax, speed + 0.05 * vmax * gauss()));
        if (chance(g_turn_p)) dir = -dir;
        x += dir * speed;
        if (x > lim) { x = lim; dir = -1; }
        if (x < -lim) { x = -lim; dir = 1; }
    }
};
static Walk g_rho, g_c;
static double g_vmax;
static double g_rho_min = 1e9, g_rho_max = -1e9;

static void drift_step() {
    g_rho.step(2 * LN10, g_vmax);
    g_c.step(LN10 - std::fabs(g_rho.x) / 2, g_vmax);
}

// CPU clock period in ps: A = TM * exp(c - rho/2), B = TM * exp(c + rho/2),
// so fA/fB = exp(rho).
static uint64_t cpu_period(int id) {
    double lx = g_c.x + (id == 0 ? -g_rho.x / 2 : g_rho.x / 2);
    double p = (double)TM * std::exp(lx);
    p = std::max((double)TM / 10, std::min((double)TM * 10, p));
    return (uint64_t)std::llround(p);
}

// ------------------------------------------------------------------ bus records
struct Req {
    bool     we = false;
    uint32_t adr = 0, sel = 0, dat = 0;  // dat: the data the CPU means to write
    uint64_t t_stb = 0;                  // CPU edge after which stb rose
    uint64_t edges_stb = 0, ram_edges_stb = 0;
};
struct RamTx {
    bool     we;
    uint32_t adr, sel, wdat, rdat;
    uint64_t t_go;  // RAM edge at which albatross_dpram performed the access
};
struct OwnWrite {
    bool     valid = false;
    uint8_t  val = 0;
    uint64_t t = 0;
};

struct LatStat {
    uint64_t n = 0;
    double   worst_ratio = 0;  // latency / bound
    uint64_t worst_ps = 0, worst_bound_ps = 0, worst_ts = 0;
    uint64_t worst_s_cycles = 0, worst_m_cycles = 0;  // of the worst-ratio access
    uint64_t max_s_cycles = 0, max_m_cycles = 0;      // over all accesses
};

static uint64_t g_ram_edges = 0;
static uint64_t g_completed = 0;  // accesses acked, both CPUs
static uint64_t g_issued = 0;     // requests raised, both CPUs
static uint64_t g_contended = 0;  // reads whose bytes changed during their window
static uint64_t g_unknown_reads = 0;

static const char *hexs(const std::vector<uint8_t> &v, char *buf, size_t n) {
    size_t o = 0;
    buf[0] = 0;
    for (size_t i = 0; i < v.size() && o + 6 < n; ++i)
        o += std::snprintf(buf + o, n - o, "%s0x%02x", i ? "," : "", v[i]);
    return buf;
}

// ------------------------------------------------------------------ CPU model
struct Cpu {
    int  id;
    char name;
    // clock
    bool     level = false;
    uint64_t next_edge = 0, period = 0, last_rise = 0, edges = 0;
    bool     rst = true;
    int      rst_hold = 0;  // edges left after reset before the first request
    // bus
    bool     busy = false;  // a request is presented (cyc = stb = 1)
    Req      cur;
    uint64_t waited = 0;      // edges since stb rose
    int      abandon_at = -1; // edges after which to abandon, -1 never
    uint64_t gap = 0;         // edges left with cyc low before the next request
    std::vector<Req>   abandoned;  // abandoned since the last ack
    std::deque<RamTx>  ramq;       // RAM accesses of this bridge not yet matched
    uint64_t epoch_ts_max = 0;     // longest period since the epoch start
    std::vector<OwnWrite> own;     // NWORDS * 4
    // drive values
    bool     cyc = false, we = false;
    uint32_t adr = 0, sel = 0, dat = 0;
    // stats
    uint64_t reads = 0, writes = 0, n_abandoned = 0, n_abandon_performed = 0;
    uint64_t idle_acks = 0;
    LatStat  lat_normal, lat_after_abandon;

    void start(uint64_t t) {
        if (abandoned.empty()) epoch_ts_max = 0;  // new epoch: nothing in flight
        Req r;
        // after an abandon, often the same word with the other operation
        if (!abandoned.empty() && chance(0.5)) {
            r.adr = abandoned.back().adr;
            r.we = !abandoned.back().we;
        } else {
            r.adr = chance(0.85) ? rnd(4) * (NWORDS / 4 + 1) % NWORDS : rnd(NWORDS);
            r.we = chance(0.5);
        }
        r.adr &= ADDR_MASK;
        r.sel = 1 + rnd(15);
        r.dat = rnd32();
        r.t_stb = t;
        r.edges_stb = edges;
        r.ram_edges_stb = g_ram_edges;
        cur = r;
        busy = true;
        waited = 0;
        abandon_at = chance(0.03) ? (int)(1 + rnd(10)) : -1;
        cyc = true;
        we = r.we;
        adr = r.adr;
        sel = r.sel;
        dat = r.dat;
        if (g_inject == "write" && r.we && chance(0.01)) dat ^= 0x01010101u;  // fault
        ++g_issued;
    }

    uint64_t bound(bool after_abandon, uint64_t ts) const {
        if (g_inject == "latency")  // deliberately wrong: no RAM time, no metastability
            return (uint64_t)(N + 2) * ts + (uint64_t)(N + 2) * TM;
        if (after_abandon) return (uint64_t)(2 * N + 4) * ts + (uint64_t)(2 * N + 10) * TM;
        return (uint64_t)(N + 4) * ts + (uint64_t)(N + 5) * TM;
    }

    bool matches(const Req &r, const RamTx &x) const {
        return x.we == r.we && x.adr == r.adr && x.sel == r.sel && (!r.we || x.wdat == r.dat) &&
               x.t_go >= r.t_stb;
    }

    void complete(uint64_t t, uint32_t rdata) {
        const bool after_abandon = !abandoned.empty();
        // ---- latency
        const uint64_t L = t - cur.t_stb;
        const uint64_t ts = epoch_ts_max;
        const uint64_t bnd = bound(after_abandon, ts);
        const uint64_t ns = edges - cur.edges_stb, nm = g_ram_edges - cur.ram_edges_stb;
        LatStat &ls = after_abandon ? lat_after_abandon : lat_normal;
        ++ls.n;
        ++g_checks[CHK_LAT];
        double ratio = (double)L / (double)bnd;
        if (ratio > ls.worst_ratio) {
            ls.worst_ratio = ratio;
            ls.worst_ps = L;
            ls.worst_bound_ps = bnd;
            ls.worst_ts = ts;
            ls.worst_s_cycles = ns;
            ls.worst_m_cycles = nm;
        }
        ls.max_s_cycles = std::max(ls.max_s_cycles, ns);
        ls.max_m_cycles = std::max(ls.max_m_cycles, nm);
        if (L > bnd)
            fail(CHK_LAT,
                 "CPU %c %s adr 0x%02x at t=%" PRIu64 " ps: expected ack within %" PRIu64
                 " ps (%s bound, Ts=%" PRIu64 " Tm=%" PRIu64 "), came after %" PRIu64
                 " ps (%" PRIu64 " CPU cycles, %" PRIu64 " RAM cycles)",
                 name, cur.we ? "write" : "read", cur.adr, cur.t_stb, bnd,
                 after_abandon ? "after-abandon" : "normal", ts, TM, L, ns, nm);

        // ---- visibility: own RAM access (and those of abandoned requests)
        ++g_checks[CHK_VIS];
        const RamTx *own_tx = nullptr;
        if (ramq.empty()) {
            fail(CHK_VIS,
                 "CPU %c %s adr 0x%02x sel 0x%x dat 0x%08x acked at t=%" PRIu64
                 ": expected its RAM access, came none",
                 name, cur.we ? "write" : "read", cur.adr, cur.sel, cur.dat, t);
        } else {
            const RamTx &x = ramq.back();
            if (!matches(cur, x) || x.t_go > t) {
                fail(CHK_VIS,
                     "CPU %c acked at t=%" PRIu64 ": expected RAM access %s adr 0x%02x sel 0x%x"
                     " wdat 0x%08x at t>=%" PRIu64 ", came %s adr 0x%02x sel 0x%x wdat 0x%08x"
                     " at t=%" PRIu64,
                     name, t, cur.we ? "write" : "read", cur.adr, cur.sel, cur.dat, cur.t_stb,
                     x.we ? "write" : "read", x.adr, x.sel, x.wdat, x.t_go);
            } else {
                own_tx = &x;
            }
            size_t ai = 0;
            for (size_t i = 0; i + 1 < ramq.size(); ++i) {
                while (ai < abandoned.size() && !matches(abandoned[ai], ramq[i])) ++ai;
                if (ai == abandoned.size()) {
                    fail(CHK_VIS,
                         "CPU %c: expected no RAM access but its own and abandoned ones,"
                         " came %s adr 0x%02x sel 0x%x wdat 0x%08x at t=%" PRIu64,
                         name, ramq[i].we ? "write" : "read", ramq[i].adr, ramq[i].sel,
                         ramq[i].wdat, ramq[i].t_go);
                    break;
                }
                ++n_abandon_performed;
                ++ai;
            }
        }
        if (!cur.we) {
            if (own_tx && rdata != own_tx->rdat)
                fail(CHK_VIS,
                     "CPU %c read adr 0x%02x acked at t=%" PRIu64 "%s: expected the data of"
                     " its own RAM read 0x%08x, came 0x%08x",
                     name, cur.adr, t, after_abandon ? " (after abandon)" : "", own_tx->rdat,
                     rdata);
            check_read(t, rdata);
            ++reads;
        } else {
            const uint64_t tw = own_tx ? own_tx->t_go : t;
            for (int b = 0; b < 4; ++b)
                if (cur.sel >> b & 1) {
                    OwnWrite &o = own[cur.adr * 4 + b];
                    o.valid = true;
                    o.val = (uint8_t)(cur.dat >> (8 * b));
                    o.t = tw;
                }
            ++writes;
        }
        ramq.clear();
        abandoned.clear();
        busy = false;
        cyc = false;
        ++g_completed;
        drift_step();
    }

    void check_read(uint64_t t, uint32_t rdata) {
        std::vector<uint8_t> allowed;
        bool contended = false;
        for (int b = 0; b < 4; ++b) {
            const uint8_t got = (uint8_t)(rdata >> (8 * b));
            // atomicity
            ++g_checks[CHK_ATOM];
            const bool known = ref_allowed(cur.adr, b, cur.t_stb, t, allowed);
            if (allowed.size() > 1) contended = true;
            if (!known) {
                ++g_unknown_reads;
            } else if (std::find(allowed.begin(), allowed.end(), got) == allowed.end()) {
                char buf[256];
                fail(CHK_ATOM,
                     "CPU %c read adr 0x%02x byte %d (t=%" PRIu64 "..%" PRIu64 " ps): expected"
                     " one of {%s}, came 0x%02x",
                     name, cur.adr, b, cur.t_stb, t, hexs(allowed, buf, sizeof buf), got);
            }
            // visibility of this CPU's own last write to the byte
            const OwnWrite &o = own[cur.adr * 4 + b];
            if (o.valid && !ref_written_after(cur.adr, b, o.t, t)) {
                ++g_checks[CHK_VIS];
                if (got != o.val)
                    fail(CHK_VIS,
                         "CPU %c read adr 0x%02x byte %d at t=%" PRIu64 ": expected its own"
                         " write 0x%02x (RAM t=%" PRIu64 ", not overwritten), came 0x%02x",
                         name, cur.adr, b, t, o.val, o.t, got);
            }
        }
        if (contended) ++g_contended;
    }

    // Rising edge at t, after eval(); ack/rdata were sampled before the edge.
    void rise(uint64_t t, bool ack, uint32_t rdata, bool stop) {
        if (rst) return;
        if (busy) {
            ++waited;
            if (ack) {
                if (g_inject == "torn" && !cur.we && chance(0.005))
                    rdata ^= 0x5au << (8 * rnd(4));  // fault: one invented byte
                complete(t, rdata);
                const uint64_t g = gap_pick();
                if (g == 0 && !stop) start(t); else gap = g;
                return;
            }
            if (abandon_at >= 0 && waited >= (uint64_t)abandon_at) {
                abandoned.push_back(cur);
                ++n_abandoned;
                busy = false;
                cyc = false;
                gap = 1 + gap_pick();  // cyc low for at least one edge
            }
            return;
        }
        if (ack) ++idle_acks;  // ack in a cycle with cyc low: ignored by Wishbone
        if (rst_hold > 0) { --rst_hold; return; }
        if (gap > 0) --gap;
        if (gap == 0 && !stop) start(t);
    }

    static uint64_t gap_pick() {
        const uint32_t r = rnd(100);
        if (r < 30) return 0;
        if (r < 70) return 1 + rnd(3);
        if (r < 95) return 4 + rnd(17);
        return 20 + rnd(180);
    }
};

// ------------------------------------------------------------------ RAM-side monitor
struct MonSample {
    bool     cyc, stb, we, ack;
    uint32_t adr, sel, wdat, rdat;
};
struct Mon {
    char      name;
    MonSample prev{};
    uint64_t  n_tx = 0;
};

static void ram_access(Cpu &cpu, Mon &m, const MonSample &s, uint64_t t_go, uint64_t t,
                       bool in_reset) {
    if (in_reset) {  // registers may still hold power-up garbage
        m.prev = s;
        return;
    }
    ++g_checks[CHK_RAM];
    if (s.cyc != s.stb)
        fail(CHK_RAM, "bridge %c RAM bus at t=%" PRIu64 ": expected cyc == stb, came cyc=%d stb=%d",
             m.name, t, s.cyc, s.stb);
    if (s.ack && !s.stb)
        fail(CHK_RAM, "RAM port %c at t=%" PRIu64 ": expected no ack without stb, came ack",
             m.name, t);
    if (m.prev.stb && !m.prev.ack) {  // a cycle in progress must hold its request
        if (!s.stb || s.we != m.prev.we || s.adr != m.prev.adr || s.sel != m.prev.sel ||
            (s.we && s.wdat != m.prev.wdat))
            fail(CHK_RAM,
                 "bridge %c RAM bus at t=%" PRIu64 ": expected request held until ack (stb=1 we=%d"
                 " adr=0x%02x sel=0x%x), came stb=%d we=%d adr=0x%02x sel=0x%x",
                 m.name, t, m.prev.we, m.prev.adr, m.prev.sel, s.stb, s.we, s.adr, s.sel);
    }
    if (s.stb && s.ack) {
        RamTx x{s.we, s.adr, s.sel, s.wdat, s.rdat, t_go};
        ++m.n_tx;
        for (int b = 0; b < 4; ++b) {
            Hist &hb = g_ref[x.adr * 4 + b];
            if (x.we) {
                if (x.sel >> b & 1) hb.h.emplace_back(t_go, (uint16_t)((x.wdat >> (8 * b)) & 0xff));
            } else {
                const uint8_t got = (uint8_t)(x.rdat >> (8 * b));
                if (hb.h.back().second == UNKNOWN) {
                    hb.h.back().second = got;  // power-up value, now known
                } else if (hb.h.back().second != got) {
                    fail(CHK_RAM,
                         "RAM port %c read adr 0x%02x byte %d at t=%" PRIu64 ": expected 0x%02x,"
                         " came 0x%02x",
                         m.name, x.adr, b, t_go, hb.h.back().second, got);
                }
            }
        }
        cpu.ramq.push_back(x);
    }
    m.prev = s;
}

// ------------------------------------------------------------------ JSON
static void mkdirs(const std::string &path) {
    for (size_t i = 1; i < path.size(); ++i)
        if (path[i] == '/') mkdir(path.substr(0, i).c_str(), 0777);
}

static void json_lat(FILE *f, const char *key, const LatStat &l, const char *formula, bool last) {
    std::fprintf(f,
                 "      \"%s\": {\"count\": %" PRIu64 ", \"bound_formula\": \"%s\", "
                 "\"worst_ratio_to_bound\": %.4f, \"worst_latency_ps\": %" PRIu64
                 ", \"bound_at_worst_ps\": %" PRIu64 ", \"cpu_period_at_worst_ps\": %" PRIu64
                 ", \"cpu_cycles_at_worst\": %" PRIu64 ", \"ram_cycles_at_worst\": %" PRIu64
                 ", \"max_cpu_cycles\": %" PRIu64 ", \"max_ram_cycles\": %" PRIu64 "}%s\n",
                 key, l.n, formula, l.worst_ratio, l.worst_ps, l.worst_bound_ps, l.worst_ts,
                 l.worst_s_cycles, l.worst_m_cycles, l.max_s_cycles, l.max_m_cycles,
                 last ? "" : ",");
}

// ------------------------------------------------------------------ main
int main(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!std::strncmp(a, "--seed=", 7)) g_seed = std::strtoull(a + 7, nullptr, 0);
        else if (!std::strncmp(a, "--accesses=", 11)) g_accesses = std::strtoull(a + 11, nullptr, 0);
        else if (!std::strncmp(a, "--inject=", 9)) g_inject = a + 9;
        else if (!std::strncmp(a, "--json=", 7)) g_json = a + 7;
        else if (a[0] == '+') { /* Verilator plusargs */ }
        else { std::fprintf(stderr, "test_cdc: unknown option %s\n", a); return 2; }
    }
    if (!g_inject.empty() && g_inject != "torn" && g_inject != "latency" && g_inject != "write" &&
        g_inject != "ram") {
        std::fprintf(stderr, "test_cdc: unknown --inject=%s\n", g_inject.c_str());
        return 2;
    }
    std::printf("test_cdc: seed=%" PRIu64 " accesses=%" PRIu64 " SYNC_STAGES=%d ADDR_WIDTH=%d%s%s\n",
                g_seed, g_accesses, N, ADDR_WIDTH, g_inject.empty() ? "" : " inject=",
                g_inject.c_str());
    g_rng.seed(g_seed);
    const auto wall0 = std::chrono::steady_clock::now();

    Verilated::commandArgs(argc, argv);
    Verilated::randReset(2);
    Verilated::randSeed((int)(g_seed & 0x7fffffff));
    Vtb_dpram_async *top = new Vtb_dpram_async;

    g_ref.resize(NWORDS * 4);
    for (auto &hb : g_ref) hb.h.emplace_back(0, UNKNOWN);

    // drift: the ratio sweeps its full range a few times over the run
    g_vmax = 6 * 2 * (4 * LN10) / (double)std::max<uint64_t>(g_accesses, 1000);
    g_turn_p = 8.0 / (double)std::max<uint64_t>(g_accesses, 1000);
    g_rho.x = (2 * rnd32() / 4294967296.0 - 1) * 2 * LN10;
    g_rho.dir = rnd32() & 1 ? 1 : -1;
    g_rho.speed = g_c.speed = g_vmax / 2;

    Cpu cpu[2];
    Mon mon[2];
    for (int i = 0; i < 2; ++i) {
        cpu[i].id = i;
        cpu[i].name = mon[i].name = (char)('A' + i);
        cpu[i].own.resize(NWORDS * 4);
        cpu[i].rst_hold = 4;
    }
    bool     ram_level = false, ram_rst = true;
    uint64_t ram_next = 1 + rnd((uint32_t)TM), ram_last_rise = 0;
    cpu[0].next_edge = 1 + rnd(100000);
    cpu[1].next_edge = 1 + rnd(100000);

    // everything low, resets high, one eval before the first edge
    top->ram_clk_i = 0; top->a_clk_i = 0; top->b_clk_i = 0;
    top->ram_rst_i = 1; top->a_rst_i = 1; top->b_rst_i = 1;
    top->a_cyc_i = 0; top->a_stb_i = 0; top->a_we_i = 0; top->a_adr_i = 0; top->a_sel_i = 0; top->a_dat_i = 0;
    top->b_cyc_i = 0; top->b_stb_i = 0; top->b_we_i = 0; top->b_adr_i = 0; top->b_sel_i = 0; top->b_dat_i = 0;
    top->eval();

    const uint64_t RESET_UNTIL = 40 * TM * 10;  // > 20 edges of the slowest clock
    uint64_t t = 0, evals = 0, next_prune = 0;
    bool stop = false;
    uint64_t stop_time = 0;
    bool aborted = false;
    // Progress watchdog: the per-access one above covers a request that waits
    // for its ack, not one abandoned and retried for ever, nor CPUs that stop
    // issuing.  Until the last access, some access must complete at least
    // every PROGRESS_PS: an access needs at most 4 * ((2N + 4) * 10 * TM +
    // (2N + 10) * TM) with the slowest CPU (10 * TM), a gap at most 200 of its
    // edges, far below 100000 RAM cycles.
    const uint64_t PROGRESS_PS = 100000 * TM;
    uint64_t progress_t = 0, progress_n = 0;

    for (;;) {
        t = std::min(ram_next, std::min(cpu[0].next_edge, cpu[1].next_edge));
        const bool ram_edge = ram_next == t, ram_rise = ram_edge && !ram_level;
        bool cpu_edge[2], cpu_rise[2], ack_s[2];
        uint32_t dat_s[2];
        MonSample ms[2];
        for (int i = 0; i < 2; ++i) {
            cpu_edge[i] = cpu[i].next_edge == t;
            cpu_rise[i] = cpu_edge[i] && !cpu[i].level;
        }
        // sample what each rising edge sees
        if (cpu_rise[0]) { ack_s[0] = top->a_ack_o; dat_s[0] = top->a_dat_o; }
        if (cpu_rise[1]) { ack_s[1] = top->b_ack_o; dat_s[1] = top->b_dat_o; }
        if (ram_rise) {
            ms[0] = {(bool)top->mon_a_cyc_o, (bool)top->mon_a_stb_o, (bool)top->mon_a_we_o,
                     (bool)top->mon_a_ack_o, top->mon_a_adr_o, top->mon_a_sel_o,
                     top->mon_a_wdat_o, top->mon_a_rdat_o};
            ms[1] = {(bool)top->mon_b_cyc_o, (bool)top->mon_b_stb_o, (bool)top->mon_b_we_o,
                     (bool)top->mon_b_ack_o, top->mon_b_adr_o, top->mon_b_sel_o,
                     top->mon_b_wdat_o, top->mon_b_rdat_o};
            for (int i = 0; i < 2; ++i)
                if (g_inject == "ram" && ms[i].ack && !ms[i].we && chance(0.005))
                    ms[i].rdat ^= 0x80u << (8 * rnd(4));  // fault: corrupt a RAM read sample
        }
        // advance the clocks
        if (ram_edge) {
            ram_level = !ram_level;
            top->ram_clk_i = ram_level;
            ram_next = t + TM / 2;
        }
        for (int i = 0; i < 2; ++i) {
            if (!cpu_edge[i]) continue;
            Cpu &c = cpu[i];
            c.level = !c.level;
            if (c.level) {
                if (c.edges > 0) {
                    const uint64_t p = t - c.last_rise;
                    c.epoch_ts_max = std::max(c.epoch_ts_max, p);
                }
                c.last_rise = t;
                ++c.edges;
                c.period = cpu_period(i);
                c.next_edge = t + c.period / 2;
            } else {
                c.next_edge = c.last_rise + c.period;
            }
        }
        top->a_clk_i = cpu[0].level;
        top->b_clk_i = cpu[1].level;
        top->eval();
        ++evals;

        if (ram_rise) {
            ++g_ram_edges;
            for (int i = 0; i < 2; ++i) ram_access(cpu[i], mon[i], ms[i], ram_last_rise, t, ram_rst);
            ram_last_rise = t;
            if (ram_rst && t >= RESET_UNTIL) { ram_rst = false; top->ram_rst_i = 0; }
        }
        for (int i = 0; i < 2; ++i) {
            if (!cpu_rise[i]) continue;
            Cpu &c = cpu[i];
            if (c.rst && t >= RESET_UNTIL) { c.rst = false; }
            else c.rise(t, ack_s[i], dat_s[i], stop);
            // watchdog: far beyond the bound means a hang
            if (c.busy && !c.rst) {
                const uint64_t wd = 4 * ((uint64_t)(2 * N + 4) * std::max(c.epoch_ts_max, c.period) +
                                         (uint64_t)(2 * N + 10) * TM);
                if (t - c.cur.t_stb > wd) {
                    fail(CHK_LAT, "CPU %c %s adr 0x%02x from t=%" PRIu64 ": expected an ack, came"
                         " none after %" PRIu64 " ps (hang); aborting",
                         c.name, c.cur.we ? "write" : "read", c.cur.adr, c.cur.t_stb, t - c.cur.t_stb);
                    aborted = true;
                }
            }
        }
        top->a_rst_i = cpu[0].rst;
        top->b_rst_i = cpu[1].rst;
        top->a_cyc_i = cpu[0].cyc; top->a_stb_i = cpu[0].cyc; top->a_we_i = cpu[0].we;
        top->a_adr_i = cpu[0].adr & ADDR_MASK; top->a_sel_i = cpu[0].sel & 0xfu; top->a_dat_i = cpu[0].dat;
        top->b_cyc_i = cpu[1].cyc; top->b_stb_i = cpu[1].cyc; top->b_we_i = cpu[1].we;
        top->b_adr_i = cpu[1].adr & ADDR_MASK; top->b_sel_i = cpu[1].sel & 0xfu; top->b_dat_i = cpu[1].dat;

        // track the ratio reached (while traffic runs)
        if (!stop && ram_rise && !ram_rst) {
            const double r = std::log((double)cpu[1].period / (double)cpu[0].period);  // ln(fA/fB)
            g_rho_min = std::min(g_rho_min, r);
            g_rho_max = std::max(g_rho_max, r);
        }
        if (ram_rise && t >= next_prune) {
            uint64_t oldest = t;
            for (auto &c : cpu) {
                if (c.busy) oldest = std::min(oldest, c.cur.t_stb);
                for (auto &r : c.abandoned) oldest = std::min(oldest, r.t_stb);
            }
            ref_prune(oldest);
            next_prune = t + 1000 * TM;
        }
        if (!stop && !ram_rst && ram_rise) {
            if (g_completed != progress_n || progress_t == 0) { progress_n = g_completed; progress_t = t; }
            else if (t - progress_t > PROGRESS_PS) {
                fail(CHK_LAT, "expected an access to complete at least every %" PRIu64 " ps, came none from t=%"
                     PRIu64 " to t=%" PRIu64 " (%" PRIu64 " of %" PRIu64 " accesses done; CPU A %s, CPU B %s);"
                     " aborting", PROGRESS_PS, progress_t, t, g_completed, g_accesses,
                     cpu[0].busy ? "waiting for an ack" : "idle", cpu[1].busy ? "waiting for an ack" : "idle");
                aborted = true;
            }
        }
        if (aborted) break;
        if (!stop && g_completed >= g_accesses) { stop = true; stop_time = t; }
        if (stop && !cpu[0].busy && !cpu[1].busy && t > stop_time + 400 * TM * 10) break;
    }

    // abandoned requests at the end: their RAM accesses must match them
    for (auto &c : cpu) {
        size_t ai = 0;
        for (const RamTx &x : c.ramq) {
            while (ai < c.abandoned.size() && !c.matches(c.abandoned[ai], x)) ++ai;
            if (ai == c.abandoned.size()) {
                fail(CHK_VIS, "CPU %c at the end: expected no RAM access but abandoned ones, came"
                     " %s adr 0x%02x at t=%" PRIu64, c.name, x.we ? "write" : "read", x.adr, x.t_go);
                break;
            }
            ++c.n_abandon_performed;
            ++ai;
        }
    }

    // coverage: what the run is meant to exercise
    const double ratio_lo = std::exp(g_rho_min), ratio_hi = std::exp(g_rho_max);
    uint64_t n_ab = cpu[0].n_abandoned + cpu[1].n_abandoned;
    uint64_t n_abp = cpu[0].n_abandon_performed + cpu[1].n_abandon_performed;
    uint64_t n_after = cpu[0].lat_after_abandon.n + cpu[1].lat_after_abandon.n;
    if (!aborted && g_accesses >= 20000) {
        ++g_checks[CHK_COV];
        if (ratio_lo > 1.0 / 50 || ratio_hi < 50)
            fail(CHK_COV, "expected fA/fB to reach 1:50 and 50:1, came %.4g..%.4g", ratio_lo, ratio_hi);
        if (g_contended < g_accesses / 200)
            fail(CHK_COV, "expected at least %" PRIu64 " reads with a byte changing in their window,"
                 " came %" PRIu64, g_accesses / 200, g_contended);
        if (n_abp < 10 || n_after < 10)
            fail(CHK_COV, "expected at least 10 abandoned-and-performed accesses and 10 accesses"
                 " after an abandon, came %" PRIu64 " and %" PRIu64, n_abp, n_after);
    }

    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    char fn[128], fa[128];
    std::snprintf(fn, sizeof fn, "(N+4)*Ts + (N+5)*Tm = %d*Ts + %d*Tm", N + 4, N + 5);
    std::snprintf(fa, sizeof fa, "(2N+4)*Ts + (2N+10)*Tm = %d*Ts + %d*Tm", 2 * N + 4, 2 * N + 10);
    std::printf("test_cdc: simulated %.3f ms, %" PRIu64 " RAM cycles, %" PRIu64 " evals, %.2f s wall\n",
                t / 1e9, g_ram_edges, evals, wall);
    std::printf("test_cdc: fA/fB ranged %.4g..%.4g (1:%.1f..%.1f:1), RAM period %" PRIu64 " ps\n",
                ratio_lo, ratio_hi, 1 / ratio_lo, ratio_hi, TM);
    for (auto &c : cpu) {
        std::printf("test_cdc: CPU %c: %" PRIu64 " reads, %" PRIu64 " writes, %" PRIu64
                    " abandoned (%" PRIu64 " still performed on the RAM), %" PRIu64 " acks after abandon ignored\n",
                    c.name, c.reads, c.writes, c.n_abandoned, c.n_abandon_performed, c.idle_acks);
        const LatStat *ls[2] = {&c.lat_normal, &c.lat_after_abandon};
        const char *lab[2] = {fn, fa};
        for (int k = 0; k < 2; ++k)
            std::printf("test_cdc: CPU %c latency %s: %" PRIu64 " accesses, worst %.1f%% of bound"
                        " (%" PRIu64 " ps of %" PRIu64 " ps, Ts=%" PRIu64 " ps: %" PRIu64
                        " CPU + %" PRIu64 " RAM cycles); max %" PRIu64 " CPU / %" PRIu64 " RAM cycles\n",
                        c.name, k ? "after abandon" : "normal", ls[k]->n, 100 * ls[k]->worst_ratio,
                        ls[k]->worst_ps, ls[k]->worst_bound_ps, ls[k]->worst_ts, ls[k]->worst_s_cycles,
                        ls[k]->worst_m_cycles, ls[k]->max_s_cycles, ls[k]->max_m_cycles);
        (void)lab;
    }
    std::printf("test_cdc: RAM accesses A %" PRIu64 " B %" PRIu64 ", reads with a byte changing in"
                " their window %" PRIu64 ", bytes read before first known %" PRIu64 "\n",
                mon[0].n_tx, mon[1].n_tx, g_contended, g_unknown_reads);
    int mask = 0;
    for (int k = 0; k < CHK_COUNT; ++k) {
        std::printf("test_cdc: checker %-10s %10" PRIu64 " checks, %" PRIu64 " failures\n",
                    CHK_NAME[k], g_checks[k], g_fail[k]);
        if (g_fail[k]) mask |= 1 << k;
    }

    if (!g_json.empty()) {
        mkdirs(g_json);
        FILE *f = std::fopen(g_json.c_str(), "w");
        if (!f) { std::perror(g_json.c_str()); return 2; }
        std::fprintf(f, "{\n  \"test\": \"cdc\",\n  \"seed\": %" PRIu64 ",\n  \"accesses\": %" PRIu64
                     ",\n  \"inject\": \"%s\",\n  \"sync_stages\": %d,\n  \"addr_width\": %d,\n"
                     "  \"ram_period_ps\": %" PRIu64 ",\n  \"cpu_period_range_ps\": [%" PRIu64 ", %" PRIu64 "],\n"
                     "  \"freq_ratio_a_to_b_range\": [%.6g, %.6g],\n"
                     "  \"simulated_ps\": %" PRIu64 ",\n  \"ram_cycles\": %" PRIu64 ",\n  \"evals\": %" PRIu64
                     ",\n  \"wall_s\": %.3f,\n  \"reads_contended\": %" PRIu64 ",\n",
                     g_seed, g_accesses, g_inject.c_str(), N, ADDR_WIDTH, TM, TM / 10, TM * 10,
                     ratio_lo, ratio_hi, t, g_ram_edges, evals, wall, g_contended);
        std::fprintf(f, "  \"cpus\": {\n");
        for (int i = 0; i < 2; ++i) {
            Cpu &c = cpu[i];
            std::fprintf(f, "    \"%c\": {\"reads\": %" PRIu64 ", \"writes\": %" PRIu64
                         ", \"abandoned\": %" PRIu64 ", \"abandoned_performed\": %" PRIu64
                         ", \"ram_accesses\": %" PRIu64 ",\n    \"latency\": {\n",
                         c.name, c.reads, c.writes, c.n_abandoned, c.n_abandon_performed, mon[i].n_tx);
            json_lat(f, "normal", c.lat_normal, fn, false);
            json_lat(f, "after_abandon", c.lat_after_abandon, fa, true);
            std::fprintf(f, "    }}%s\n", i ? "" : ",");
        }
        std::fprintf(f, "  },\n  \"checkers\": {");
        for (int k = 0; k < CHK_COUNT; ++k)
            std::fprintf(f, "%s\"%s\": {\"checks\": %" PRIu64 ", \"failures\": %" PRIu64 "}",
                         k ? ", " : "", CHK_NAME[k], g_checks[k], g_fail[k]);
        std::fprintf(f, "},\n  \"pass\": %s\n}\n", mask ? "false" : "true");
        std::fclose(f);
        std::printf("test_cdc: report %s\n", g_json.c_str());
    }

    top->final();
    delete top;
    if (mask) {
        std::printf("test_cdc: FAILED (checkers:");
        for (int k = 0; k < CHK_COUNT; ++k)
            if (mask >> k & 1) std::printf(" %s", CHK_NAME[k]);
        std::printf("), exit %d\n", 64 | mask);
        return 64 | mask;
    }
    std::printf("test_cdc: PASSED %" PRIu64 " accesses, all checkers clean\n", g_completed);
    return 0;
}
