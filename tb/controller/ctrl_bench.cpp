// ctrl_bench.cpp -- the shared helpers of test_controller declared in ctrl_bench.h:
// the checks, the schedule ROM builder and the CPU-side helpers.
#include "ctrl_bench.h"

// ------------------------------------------------------------------ checks
unsigned g_failed_groups;
unsigned g_checks, g_fails;
bool g_inject_timing;
int g_argc;
char **g_argv;

void check(unsigned group, bool ok, const char *fmt, ...) {
    ++g_checks;
    if (!ok) {
        ++g_fails;
        g_failed_groups |= group;
    }
    {
        va_list ap;
        va_start(ap, fmt);
        std::printf("%s ", ok ? "ok  " : "FAIL");
        std::vprintf(fmt, ap);
        std::printf("\n");
        va_end(ap);
    }
}

// ------------------------------------------------------------------ schedule ROM
size_t rom_addr(size_t k, unsigned j) { return C::ROM_HEADER_WORDS + C::ROM_ENTRY_WORDS * k + j; }

// The check word of a ROM of ne entries (its CRC then 0).
void reseal(std::vector<uint32_t> &r, size_t ne) {
    r[C::ROM_CRC_WORD] = C::rom_check_word(&r[0], (int)rom_addr(ne, 0));
}

// hflags: the H0 flags field (C::HFLAG_SYNC_MODE: position-synchronised).
std::vector<uint32_t> build_rom(uint32_t h1, unsigned hflags, const std::vector<Entry> &es, unsigned drop_run) {
    std::vector<uint32_t> r(ROMW, 0);
    r[C::H0_MAGIC.word] |= C::H0_MAGIC.put(C::ROM_MAGIC);
    r[C::H0_NE.word] |= C::H0_NE.put((uint32_t)es.size());
    r[C::H0_FLAGS.word] |= C::H0_FLAGS.put(hflags);
    r[C::H1_CYCLE.word] |= C::H1_CYCLE.put(h1);
    r[C::H2_DROP_RUN.word] |= C::H2_DROP_RUN.put(drop_run);
    for (size_t k = 0; k < es.size(); ++k) {
        const Entry &e = es[k];
        uint32_t *w = &r[rom_addr(k, 0)];
        w[C::E0_KIND.word] |= C::E0_KIND.put(e.kind);
        w[C::E0_FLAGS.word] |= C::E0_FLAGS.put(e.flags);
        w[C::E0_ID.word] |= C::E0_ID.put(e.chan);
        w[C::E0_ND.word] |= C::E0_ND.put((uint32_t)e.dst.size());
        w[C::E0_W.word] |= C::E0_W.put(e.w);
        w[C::E1_START.word] |= C::E1_START.put(e.start);
        w[C::E2_LENGTH.word] |= C::E2_LENGTH.put(e.len);
        w[C::E3_SRC.word] |= C::E3_SRC.put(C::place(e.sbrd, e.sbase));
        for (size_t i = 0; i < e.dst.size(); ++i)
            w[C::DST[i].word] |= C::DST[i].put(C::place(e.dst[i].brd, e.dst[i].base));
        w[C::E7_FRAG.word] |= C::E7_FRAG.put(e.frag);
    }
    reseal(r, es.size());
    return r;
}

void write_rom(const std::vector<uint32_t> &r) {
    FILE *f = std::fopen(ROM_PATH, "w");
    if (!f) {
        std::perror(ROM_PATH);
        std::exit(2);
    }
    for (uint32_t v : r) std::fprintf(f, "%08x\n", v);
    std::fclose(f);
}

std::vector<Entry> schedule() {
    return {
        {COPY, 0, 0, W_COPY, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}},
        {TIME, 0, 1, 1, S_TIME, L_TIME, 0, 0, {{0, TIME_BASE}, {1, TIME_BASE}}},
        {STATUS, 0, 2, W_STAT, S_STAT, L_STAT, 0, 0, {{1, STAT_BASE}}},
    };
}

// ------------------------------------------------------------------ the CPUs' three-buffer protocol
unsigned pick(unsigned a, unsigned r) {
    for (unsigned b = 3; b >= 1; --b)
        if (b != a && b != r) return b;
    return 1;
}

std::vector<uint32_t> value(unsigned n) {
    return {0x10000000u * (n + 1) + 0x111u, 0xC0DE0000u + n, 0x5A5A0000u ^ (n * 0x1234u)};
}

uint32_t ba(unsigned brd, unsigned word) { return brd << AW | word; }

// Exact fault-free timing of the attempts of one slot (all acked, back to back).
void check_slot_timing(const char *what, const std::vector<Attempt> &v, uint64_t S, size_t expect_n) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s: number of accesses", what);
    CHECK_EQ(G_TIMING, buf, expect_n, v.size());
    uint64_t p = S + F;
    uint64_t phi = (p % 2 == 0) ? 1 : 0;  // tb_system: port B is served at the end of odd clocks
    uint64_t skew = g_inject_timing ? 1 : 0;
    for (size_t k = 1; k <= v.size(); ++k) {
        const Attempt &a = v[k - 1];
        uint64_t exp = S + F + 2 * k + phi + skew;
        std::snprintf(buf, sizeof buf, "%s: access %zu (adr 0x%04x%s) ack sampled at edge S+%d+2*%zu+phi",
                      what, k, a.adr, a.we ? " store" : " load", F, k);
        check(G_TIMING, a.result == 1 && a.end + 1 == exp,
              "%s: expected %" PRIu64 ", got %" PRIu64 "%s", buf, exp, a.end + 1,
              a.result == 1 ? "" : " (not acked)");
    }
    if (!v.empty()) {
        std::snprintf(buf, sizeof buf, "%s: sample_offset (first Actual load done) = FETCH_CYCLES+2+phi", what);
        CHECK_EQ(G_TIMING, buf, F + 2 + phi + skew, v.front().end + 1 - S);
        std::snprintf(buf, sizeof buf, "%s: pub_offset (last access done) = FETCH_CYCLES+2A+phi, A=%zu", what,
                      expect_n);
        CHECK_EQ(G_TIMING, buf, F + 2 * expect_n + phi + skew, v.back().end + 1 - S);
    }
}

// ------------------------------------------------------------------ values over several runs
std::string words_str(const std::vector<unsigned> &v) {
    std::string r;
    for (unsigned x : v) r += (r.empty() ? "" : " ") + std::to_string(x);
    return r.empty() ? "none" : r;
}

std::vector<unsigned> ValueRuns::src_words(size_t from, size_t to, unsigned b) const {
    std::vector<unsigned> v;
    const unsigned lo = sbase + 1 + (b - 1) * w;
    for (size_t i = from; i < to && i < s.ram.size(); ++i) {
        const RamOp &r = s.ram[i];
        // (the buffers, and a buffer's length either side: a buffer index 0 or 4)
        if (r.board != sb || r.we || r.adr == sbase || r.adr + w < sbase + 1 || r.adr >= sbase + 1 + 4 * w) continue;
        v.push_back(b != 0 && r.adr >= lo && r.adr < lo + w ? r.adr - lo : 100 + r.adr);
    }
    return v;
}

unsigned ValueRuns::dst_buf(size_t from, size_t to) const {
    for (size_t i = from; i < to && i < s.ram.size(); ++i) {
        const RamOp &r = s.ram[i];
        if (r.board == db && r.we && r.adr > dbase && r.adr < dbase + 1 + 3 * (w + 1) &&
            (r.adr - dbase - 1) % (w + 1) < w)
            return (r.adr - dbase - 1) / (w + 1) + 1;
    }
    return 0;
}

std::vector<unsigned> ValueRuns::dst_words(size_t from, size_t to, unsigned b) const {
    std::vector<unsigned> v;
    const unsigned lo = dbase + 1 + (b - 1) * (w + 1);
    for (size_t i = from; i < to && i < s.ram.size(); ++i) {
        const RamOp &r = s.ram[i];
        if (r.board != db || !r.we || r.adr <= dbase || r.adr >= dbase + 1 + 3 * (w + 1)) continue;
        if (b != 0 && r.adr >= lo && r.adr < lo + w) v.push_back(r.adr - lo);
        else if ((r.adr - dbase - 1) % (w + 1) < w) v.push_back(100 + r.adr);
    }
    return v;
}

unsigned ValueRuns::taken_stores(size_t from, size_t to) const {
    unsigned n = 0;
    for (size_t i = from; i < to && i < s.ram.size(); ++i) {
        const RamOp &r = s.ram[i];
        n += r.board == db && r.we && r.adr > dbase && r.adr < dbase + 1 + 3 * (w + 1) &&
             (r.adr - dbase - 1) % (w + 1) == w;
    }
    return n;
}

unsigned ValueRuns::pub_stores(size_t from, size_t to) const {
    unsigned n = 0, off = ~0u;
    uint32_t dat = 0;
    for (size_t i = from; i < to && i < s.ram.size(); ++i) {
        const RamOp &r = s.ram[i];
        if (r.board == sb && !r.we && r.adr > sbase && r.adr < sbase + 1 + 3 * w) {
            off = (r.adr - sbase - 1) % w;          // a source word load: its offset and word
            dat = r.rdat;
        } else if (r.board == db && r.we && r.adr == dbase) {
            n += r.sel & 1;                         // an Actual store
        } else if (r.board == db && r.we && r.adr > dbase && r.adr < dbase + 1 + 3 * (w + 1)) {
            n += !((r.adr - dbase - 1) % (w + 1) == off && r.wdat == dat);
        }
    }
    return n;
}

unsigned ValueRuns::first_unstored() const {
    unsigned k = 0;
    while (k < w && stored[k]) ++k;
    return k;
}

void ValueRuns::fresh() {
    stored.assign(w, false);
    bd = 0;
}

unsigned ValueRuns::check_run(const char *what, size_t from, size_t to, unsigned b, unsigned first, const char *why) {
    const std::vector<unsigned> ld = src_words(from, to, b);
    std::vector<unsigned> exp;
    for (unsigned i = 0; i < ld.size() || exp.empty(); ++i) exp.push_back(first + i);
    check(G_DATA, ld == exp, "%s at %s: expected source loads of consecutive words of buffer %u from word %u, got %s",
          what, why, b, first, words_str(ld).c_str());
    if (bd == 0) bd = dst_buf(from, to);
    const std::vector<unsigned> st = dst_words(from, to, bd);
    const bool ok = st.size() <= ld.size() && st.size() + 1 >= ld.size() && std::equal(st.begin(), st.end(), ld.begin());
    check(G_DATA, ok, "%s stores each word it loads to the destination's buffer %u (a last load cut off by the "
          "deadline may have no store): expected stores of words %s (or all but the last), got %s", what, bd,
          words_str(ld).c_str(), words_str(st).c_str());
    for (unsigned x : st)
        if (x < w) stored[x] = true;
    return (unsigned)st.size();
}
