// cdc_model.cpp -- the albatross_wb_cdc bench's checker bookkeeping, random
// source, reference memory and CPU clock drift (declarations in cdc_tb.h).
#include "cdc_tb.h"

// ------------------------------------------------------------------ checkers
uint64_t g_fail[CHK_COUNT];
uint64_t g_checks[CHK_COUNT];

void fail(int chk, const char *fmt, ...) {
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
std::mt19937_64 g_rng;

// ------------------------------------------------------------------ reference memory
std::vector<Hist> g_ref;  // NWORDS * 4

uint16_t ref_now(uint32_t adr, int b) { return g_ref[adr * 4 + b].h.back().second; }

// Values byte (adr,b) held at some time in [t0, t1]: the value before t0 and
// every value written in [t0, t1].  Returns false if any of them is unknown.
bool ref_allowed(uint32_t adr, int b, uint64_t t0, uint64_t t1, std::vector<uint8_t> &out) {
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
bool ref_written_after(uint32_t adr, int b, uint64_t tw, uint64_t t1) {
    const auto &h = g_ref[adr * 4 + b].h;
    for (size_t i = h.size(); i-- > 0;) {
        if (h[i].first <= tw) return false;
        if (h[i].first <= t1) return true;
    }
    return false;
}

// Drop history older than t (keeping the value held at t).
void ref_prune(uint64_t t) {
    for (auto &hb : g_ref) {
        while (hb.h.size() > 1 && hb.h[1].first < t) hb.h.pop_front();
    }
}

std::string g_inject;  // "", torn, latency, write, ram
uint64_t g_seed = 1;
uint64_t g_accesses = 60000;
std::string g_json;

// ------------------------------------------------------------------ clocks
double g_turn_p;
Walk g_rho, g_c;
double g_vmax;
double g_rho_min = 1e9, g_rho_max = -1e9;

void drift_step() {
    g_rho.step(2 * LN10, g_vmax);
    g_c.step(LN10 - std::fabs(g_rho.x) / 2, g_vmax);
}

// CPU clock period in ps: A = TM * exp(c - rho/2), B = TM * exp(c + rho/2),
// so fA/fB = exp(rho).
uint64_t cpu_period(int id) {
    double lx = g_c.x + (id == 0 ? -g_rho.x / 2 : g_rho.x / 2);
    double p = (double)TM * std::exp(lx);
    p = std::max((double)TM / 10, std::min((double)TM * 10, p));
    return (uint64_t)std::llround(p);
}

// ------------------------------------------------------------------ counters
uint64_t g_ram_edges = 0;
uint64_t g_completed = 0;  // accesses acked, both CPUs
uint64_t g_issued = 0;     // requests raised, both CPUs
uint64_t g_contended = 0;  // reads whose bytes changed during their window
uint64_t g_unknown_reads = 0;

const char *hexs(const std::vector<uint8_t> &v, char *buf, size_t n) {
    size_t o = 0;
    buf[0] = 0;
    for (size_t i = 0; i < v.size() && o + 6 < n; ++i)
        o += std::snprintf(buf + o, n - o, "%s0x%02x", i ? "," : "", v[i]);
    return buf;
}

