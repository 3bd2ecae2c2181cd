// cdc_cpu.cpp -- the CPU port masters of the albatross_wb_cdc bench: random
// requests, abandons and idle gaps, and the latency, visibility and atomicity
// checks made when an access is acked (declarations in cdc_tb.h).
#include "cdc_tb.h"

void Cpu::start(uint64_t t) {
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

uint64_t Cpu::bound(bool after_abandon, uint64_t ts) const {
    if (g_inject == "latency")  // deliberately wrong: no RAM time, no metastability
        return (uint64_t)(N + 2) * ts + (uint64_t)(N + 2) * TM;
    if (after_abandon) return (uint64_t)(2 * N + 4) * ts + (uint64_t)(2 * N + 10) * TM;
    return (uint64_t)(N + 4) * ts + (uint64_t)(N + 5) * TM;
}

bool Cpu::matches(const Req &r, const RamTx &x) const {
    return x.we == r.we && x.adr == r.adr && x.sel == r.sel && (!r.we || x.wdat == r.dat) &&
           x.t_go >= r.t_stb;
}

void Cpu::complete(uint64_t t, uint32_t rdata) {
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

void Cpu::check_read(uint64_t t, uint32_t rdata) {
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
void Cpu::rise(uint64_t t, bool ack, uint32_t rdata, bool stop) {
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

uint64_t Cpu::gap_pick() {
    const uint32_t r = rnd(100);
    if (r < 30) return 0;
    if (r < 70) return 1 + rnd(3);
    if (r < 95) return 4 + rnd(17);
    return 20 + rnd(180);
}
