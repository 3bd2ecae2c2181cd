// cdc_tb.h -- shared declarations of the albatross_wb_cdc bench (tb/cdc/):
// constants, checker bookkeeping, random source, reference memory, options,
// clock drift, bus records, the CPU port master and the RAM-side monitor.
// test_cdc.cpp has the description of the test; the pieces live in
// cdc_model.cpp (checkers, reference memory, clocks), cdc_cpu.cpp (CPU port
// masters), cdc_ram.cpp (RAM-side monitor) and test_cdc.cpp (main, report).
#ifndef CDC_TB_H
#define CDC_TB_H


#include <algorithm>
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
extern uint64_t g_fail[CHK_COUNT];
extern uint64_t g_checks[CHK_COUNT];
static const uint64_t MAX_PRINT = 8;

void fail(int chk, const char *fmt, ...);

// ------------------------------------------------------------------ random
extern std::mt19937_64 g_rng;
inline uint32_t rnd32() { return (uint32_t)g_rng(); }
inline uint32_t rnd(uint32_t n) { return (uint32_t)(g_rng() % n); }           // 0..n-1
inline bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(g_rng) < p; }
inline double gauss() { return std::normal_distribution<double>(0, 1)(g_rng); }

// ------------------------------------------------------------------ reference memory
// Per byte, the history of its values: (time of the RAM access, value).  The
// first entry (time 0) holds the power-up value, unknown until a RAM read
// shows it.
static const uint16_t UNKNOWN = 0x100;
struct Hist {
    std::deque<std::pair<uint64_t, uint16_t>> h;
};
extern std::vector<Hist> g_ref;  // NWORDS * 4

uint16_t ref_now(uint32_t adr, int b);

// Values byte (adr,b) held at some time in [t0, t1]: the value before t0 and
bool ref_allowed(uint32_t adr, int b, uint64_t t0, uint64_t t1, std::vector<uint8_t> &out);
// True if byte (adr,b) was written at a time in (tw, t1].
bool ref_written_after(uint32_t adr, int b, uint64_t tw, uint64_t t1);
// Drop history older than t (keeping the value held at t).
void ref_prune(uint64_t t);

// ------------------------------------------------------------------ options
extern std::string g_inject;  // "", torn, latency, write, ram
extern uint64_t g_seed;
extern uint64_t g_accesses;
extern std::string g_json;

// ------------------------------------------------------------------ clocks
// Frequency drift: rho = ln(fA/fB) wanders in [-ln 100, ln 100], the common
// part c so that both periods stay within [TM/10, 10*TM].  Each moves at a
// randomly drifting speed, bounces off its limits and now and then turns
// round at random; one step per completed access.
extern double g_turn_p;  // chance of a random turn per step
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
extern Walk g_rho, g_c;
extern double g_vmax;
extern double g_rho_min, g_rho_max;

void drift_step();

// CPU clock period in ps: A = TM * exp(c - rho/2), B = TM * exp(c + rho/2),
uint64_t cpu_period(int id);

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

extern uint64_t g_ram_edges;
extern uint64_t g_completed;  // accesses acked, both CPUs
extern uint64_t g_issued;     // requests raised, both CPUs
extern uint64_t g_contended;  // reads whose bytes changed during their window
extern uint64_t g_unknown_reads;

const char *hexs(const std::vector<uint8_t> &v, char *buf, size_t n);

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


    void start(uint64_t t);
    uint64_t bound(bool after_abandon, uint64_t ts) const;
    bool matches(const Req &r, const RamTx &x) const;
    void complete(uint64_t t, uint32_t rdata);
    void check_read(uint64_t t, uint32_t rdata);
    // Rising edge at t, after eval(); ack/rdata were sampled before the edge.
    void rise(uint64_t t, bool ack, uint32_t rdata, bool stop);
    static uint64_t gap_pick();
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

void ram_access(Cpu &cpu, Mon &m, const MonSample &s, uint64_t t_go, uint64_t t, bool in_reset);

#endif
