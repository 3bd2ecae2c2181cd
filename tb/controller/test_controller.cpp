// test_controller -- smoke test of albatross_controller on tb/system/tb_system.v.
//
// A small, self-checking test, not the system harness (tb/system/).  Each
// scenario writes its own schedule ROM (with its CRC) to ctrl_rom.hex, the
// file the model was built to $readmemh, then builds a fresh model.  The
// schedule runs on boards 0 and 1:
//   entry 0  COPY   channel 0: board 0 @0x010 (W = 3) -> board 1 @0x020
//   entry 1  TIME   channel 1: -> board 0 @0x040, board 1 @0x040
//   entry 2  STATUS channel 2: -> board 1 @0x080 (W = 1 + 2*N_CHAN)
// The CPU ports initialise the control bytes to 1.  A C++ producer on CPU port
// 0 writes values with the three-buffer protocol, and a C++ consumer on CPU
// port 1 imports them.  Scenarios:
//   basic    values, taken_at, Actual arrive; exact fault-free timing of COPY,
//            TIME and STATUS slots (every access against the formula in the
//            controller's header, start-up time T0 included); the access
//            sequence of a COPY; TIME value and STATUS counters
//   corrupt  entry 1 invalid (TIME with W = 2, CRC resealed): rom_errors counts
//            it each cycle, the other entries still run on time; a bit flipped
//            in an entry or the header (CRC not resealed): error_o, bus idle
//   faults   fault kinds 1, 2, 3 on single accesses are retried; an Actual store
//            that landed but timed out is not published twice
//   sync     position-synchronised mode: polls every POLL clocks after the last
//            entry; a new position starts the cycle, else H1 ends it
//   dead     a board's link is down for a whole cycle: the slots still start on
//            time, no access starts after its deadline, a dead destination is
//            dropped after two failed accesses and the others are still served
// Each check prints what it expected and what it got.  Exit status 0 if all
// pass, else 64 + a bit mask of the failed groups (1 timing, 2 data, 4 rom,
// 8 faults, 16 dead).  --inject=timing makes the timing checker expect one
// clock more (its negative test: it must fail with bit 1).
// Options: --dir=DIR (work directory for the ROM file, created)  --inject=timing
//          --scenario=NAME (default: all)
#include "Vtb_system.h"
#include "verilated.h"

#include "albatross_contract.h"   // generated from rtl/albatross_contract.toml (make contract)

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

// The model is built with tb_system's ROM_FILE = "ctrl_rom.hex" (tools/mk/controller.mk):
// a path relative to the working directory, which --dir sets for each run.
static const char *const ROM_PATH = "ctrl_rom.hex";

// tb_system parameters (fixed by the port contract) and controller constants.
static const int NB = 4, AW = 10, NCH = 16, TMO = 8, ROMW = 1024;
static const int F = 7;                                   // FETCH_CYCLES
static const uint32_t AMASK = (1u << AW) - 1;

// Cycle 0 starts (rel 0) at this time_o (albatross_sequencer: the counters
// cleared in 2*N_CHAN clocks, the header read in 5, the CRC pass over the
// 4 + 8*NE words one a clock, then the check).
static uint64_t t0_of(int ne) { return 2 * NCH + 10 + 8 * (uint64_t)ne; }

// ------------------------------------------------------------------ checks
enum { G_TIMING = 1, G_DATA = 2, G_ROM = 4, G_FAULT = 8, G_DEAD = 16 };
static unsigned g_failed_groups;
static unsigned g_checks, g_fails;
static bool g_inject_timing;
static int g_argc;                // the command line, for each model's +plusargs
static char **g_argv;

static void check(unsigned group, bool ok, const char *fmt, ...) {
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
#define CHECK_EQ(group, what, exp, got)                                                        \
    check(group, (uint64_t)(exp) == (uint64_t)(got), "%s: expected %" PRIu64 ", got %" PRIu64, \
          what, (uint64_t)(exp), (uint64_t)(got))
#define CHECK_HEX(group, what, exp, got)                                                           \
    check(group, (uint64_t)(exp) == (uint64_t)(got), "%s: expected 0x%" PRIx64 ", got 0x%" PRIx64, \
          what, (uint64_t)(exp), (uint64_t)(got))

// ------------------------------------------------------------------ schedule ROM
// The ROM format comes from the contract (tb/common/albatross_contract.h).
namespace C = alb_contract;

// The channel layout this test's own CPU-side protocol code and expected
// access sequences assume (Producer, Consumer, the COPY access check below):
// Actual in byte lane 0 and ReadLocked in lane 1 of the control word,
// Buffer1..3 = 1..3 from word 1, one taken_at word after a destination value.
// A definition that drifts from them fails to compile here.
static_assert(C::OFF_ACTUAL == 0 && C::OFF_READLOCKED == 1, "test_controller: control byte lanes");
static_assert(C::OFF_BUFFERS == 1 * C::WORD_BYTES && C::WORD_BYTES == 4, "test_controller: Buffer1 at word 1");
static_assert(C::BUFFER1 == 1 && C::BUFFERS == 3 && C::INITIAL_INDEX == 1, "test_controller: buffers 1..3");
static_assert(C::TAKEN_AT_WORDS == 1 && C::dest_bytes(3) == 16, "test_controller: one taken_at word");

struct Dst { unsigned brd, base; };
struct Entry {
    unsigned kind, flags, chan, w;
    uint32_t start, len;
    unsigned sbrd, sbase;
    std::vector<Dst> dst;
};
enum { IDLE = C::KIND_IDLE, COPY = C::KIND_COPY, TIME = C::KIND_TIME, STATUS = C::KIND_STATUS };

// Word j of entry k.
static size_t rom_addr(size_t k, unsigned j) { return C::ROM_HEADER_WORDS + C::ROM_ENTRY_WORDS * k + j; }

// The CRC word of a ROM of ne entries.
static void reseal(std::vector<uint32_t> &r, size_t ne) {
    r[C::ROM_CRC_WORD] = C::rom_crc(&r[0], (int)rom_addr(ne, 0));
}

// hflags: the H0 flags field (C::HFLAG_SYNC_MODE: position-synchronised).
static std::vector<uint32_t> build_rom(uint32_t h1, unsigned hflags, const std::vector<Entry> &es) {
    std::vector<uint32_t> r(ROMW, 0);
    r[C::H0_MAGIC.word] |= C::H0_MAGIC.put(C::ROM_MAGIC);
    r[C::H0_NE.word] |= C::H0_NE.put((uint32_t)es.size());
    r[C::H0_FLAGS.word] |= C::H0_FLAGS.put(hflags);
    r[C::H1_CYCLE.word] |= C::H1_CYCLE.put(h1);
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
    }
    reseal(r, es.size());
    return r;
}

static void write_rom(const std::vector<uint32_t> &r) {
    FILE *f = std::fopen(ROM_PATH, "w");
    if (!f) {
        std::perror(ROM_PATH);
        std::exit(2);
    }
    for (uint32_t v : r) std::fprintf(f, "%08x\n", v);
    std::fclose(f);
}

// The schedule of this test.
static const unsigned SRC_BASE = 0x010, DST_BASE = 0x020, TIME_BASE = 0x040, STAT_BASE = 0x080;
static const unsigned W_COPY = 3, W_STAT = 1 + 2 * NCH;
static const uint32_t H1 = 400;
static const uint32_t S_COPY = 0, L_COPY = 80, S_TIME = 80, L_TIME = 60, S_STAT = 140, L_STAT = 120;
static const uint32_t TAIL = 300;   // the slots end at 260: CPU work goes into [TAIL, H1)

static std::vector<Entry> schedule() {
    return {
        {COPY, 0, 0, W_COPY, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}},
        {TIME, 0, 1, 1, S_TIME, L_TIME, 0, 0, {{0, TIME_BASE}, {1, TIME_BASE}}},
        {STATUS, 0, 2, W_STAT, S_STAT, L_STAT, 0, 0, {{1, STAT_BASE}}},
    };
}

// ------------------------------------------------------------------ simulation
struct Attempt {                 // one bus access attempt as the controller sees it
    uint64_t start = 0, end = 0; // first clock of cyc; clock of ack/err, or of cyc low again
    bool     we = false;
    uint32_t adr = 0;            // {board, word}
    int      result = 0;         // 1 ack, 2 err, 3 timeout (cyc dropped)
};
struct RamOp {                   // one access performed by a RAM's port B
    uint64_t t;                  // clock of its ack
    int      board;
    bool     we;
    uint32_t adr, sel, wdat, rdat;
};

struct Sim {
    std::unique_ptr<VerilatedContext> ctx;
    std::unique_ptr<Vtb_system> top;
    uint64_t now = 0;                          // time_o of the current clock
    std::vector<Attempt> att;                  // finished attempts
    bool in_att = false;
    Attempt cur;
    std::vector<RamOp> ram;
    std::function<int(const Attempt &)> fault; // fault kind for a new attempt
    int kind_hold = 0;                         // clocks left to hold fi_kind_i
    unsigned dead_next = 0;                    // fi_dead_i bits to set once fi_kind_i is released

    Sim() {
        ctx.reset(new VerilatedContext);
        ctx->commandArgs(g_argc, g_argv);   // no +rom=: the model reads ROM_FILE
        top.reset(new Vtb_system(ctx.get()));
        top->clk_i = 0;
        top->rst_i = 1;
        top->cpu_cyc_i = top->cpu_stb_i = top->cpu_we_i = 0;
        top->cpu_adr_i = 0;
        top->cpu_sel_i = 0;
        for (int i = 0; i < 4; ++i) top->cpu_dat_i[i] = 0;
        top->fi_kind_i = 0;
        top->fi_dead_i = 0;
        top->eval();  // every clock low before the first edge
        for (int i = 0; i < 3; ++i) edge();
        top->rst_i = 0;
        top->eval();
        now = top->time_o;
        observe();
    }
    ~Sim() { top->final(); }

    void edge() {
        top->clk_i = 1;
        top->eval();
        top->clk_i = 0;
        top->eval();
    }
    void tick() {
        edge();
        now = top->time_o;
        observe();
    }
    // After each rising edge: record the controller's bus and every RAM's port B.
    void observe() {
        if (kind_hold > 0 && --kind_hold == 0) {
            top->fi_kind_i = 0;
            top->fi_dead_i |= dead_next;
            dead_next = 0;
        }
        bool cyc = top->bus_cyc_o;
        if (in_att) {
            if (!cyc) {                       // dropped without an answer: timeout
                cur.end = now;
                cur.result = 3;
                att.push_back(cur);
                in_att = false;
            }
        }
        if (cyc && !in_att) {                 // first clock of a new attempt
            cur = Attempt();
            cur.start = now;
            cur.we = top->bus_we_o;
            cur.adr = top->bus_adr_o;
            in_att = true;
            int k = fault ? fault(cur) : 0;
            if (k) {
                top->fi_kind_i = k;           // sampled by the injector in this clock
                kind_hold = 1;
                top->eval();
            }
        }
        if (in_att && (top->bus_ack_o || top->bus_err_o)) {
            cur.end = now;
            cur.result = top->bus_ack_o ? 1 : 2;
            att.push_back(cur);
            in_att = false;                   // the next clock may start the next one
        }
        for (int b = 0; b < NB; ++b) {
            if (top->mon_ack_o >> b & 1) {
                RamOp r;
                r.t = now;
                r.board = b;
                r.we = top->mon_we_o >> b & 1;
                r.adr = (uint32_t)(top->mon_adr_o >> (b * AW)) & AMASK;
                r.sel = top->mon_sel_o >> (4 * b) & 0xF;
                r.wdat = top->mon_wdat_o[b];
                r.rdat = top->mon_rdat_o[b];
                ram.push_back(r);
            }
        }
    }
    void run_until(uint64_t t) {
        while (now < t) tick();
    }

    // One Wishbone access on CPU port A of board b; the controller runs meanwhile.
    uint32_t cpu(int b, bool we, uint32_t adr, uint32_t sel, uint32_t dat) {
        top->cpu_cyc_i |= 1u << b;
        top->cpu_stb_i |= 1u << b;
        if (we) top->cpu_we_i |= 1u << b;
        else top->cpu_we_i &= ~(1u << b);
        top->cpu_adr_i = (top->cpu_adr_i & ~((uint64_t)AMASK << (b * AW))) | (uint64_t)(adr & AMASK) << (b * AW);
        top->cpu_sel_i = (top->cpu_sel_i & ~(0xFu << (4 * b))) | (sel & 0xF) << (4 * b);
        top->cpu_dat_i[b] = dat;
        for (int n = 0; n < 4; ++n) {
            tick();
            if (top->cpu_ack_o >> b & 1) {
                uint32_t r = top->cpu_dat_o[b];
                top->cpu_cyc_i &= ~(1u << b);
                top->cpu_stb_i &= ~(1u << b);
                return r;
            }
        }
        std::printf("FAIL cpu port %d: no ack within 4 clocks\n", b);
        std::exit(1);
    }
    uint32_t rd(int b, uint32_t adr) { return cpu(b, false, adr, 0xF, 0); }
    void wr(int b, uint32_t adr, uint32_t sel, uint32_t dat) { cpu(b, true, adr, sel, dat); }

    // Attempts that started in [t0, t1).
    std::vector<Attempt> attempts(uint64_t t0, uint64_t t1) const {
        std::vector<Attempt> v;
        for (const Attempt &a : att)
            if (a.start >= t0 && a.start < t1) v.push_back(a);
        return v;
    }
};

// ------------------------------------------------------------------ the CPUs' three-buffer protocol
static unsigned pick(unsigned a, unsigned r) {
    for (unsigned b = 3; b >= 1; --b)
        if (b != a && b != r) return b;
    return 1;
}

struct Producer {                       // Export (seed figure 4) on one board
    int board;
    unsigned base, w, actual = 1;
    void init(Sim &s) { s.wr(board, base, 0x1, 1); actual = 1; }
    unsigned publish(Sim &s, const std::vector<uint32_t> &v) {
        unsigned rl = s.rd(board, base) >> 8 & 0xFF;
        unsigned b = pick(actual, rl);
        for (unsigned i = 0; i < w; ++i) s.wr(board, base + 1 + (b - 1) * w + i, 0xF, v[i]);
        s.wr(board, base, 0x1, b);
        actual = b;
        return b;
    }
};

struct Consumer {                       // Import (seed figure 3) on one board
    int board;
    unsigned base, words, rl = 1;       // words: value + taken_at
    void init(Sim &s) { s.wr(board, base, 0x2, 1u << 8); rl = 1; }
    bool import(Sim &s, std::vector<uint32_t> &out) {
        bool isnew = false;
        unsigned a = s.rd(board, base) & 0xFF;
        while (a != rl) {
            s.wr(board, base, 0x2, a << 8);
            rl = a;
            a = s.rd(board, base) & 0xFF;
            isnew = true;
        }
        out.resize(words);
        for (unsigned i = 0; i < words; ++i) out[i] = s.rd(board, base + 1 + (rl - 1) * words + i);
        return isnew;
    }
};

static std::vector<uint32_t> value(unsigned n) {
    return {0x10000000u * (n + 1) + 0x111u, 0xC0DE0000u + n, 0x5A5A0000u ^ (n * 0x1234u)};
}

// Common set-up: ROM, control bytes, the CPUs.
struct Setup {
    Sim &s;
    Producer prod{0, SRC_BASE, W_COPY};
    Consumer cons{1, DST_BASE, W_COPY + 1};
    Consumer time0{0, TIME_BASE, 2}, time1{1, TIME_BASE, 2};
    Consumer stat{1, STAT_BASE, W_STAT + 1};
    explicit Setup(Sim &sim) : s(sim) {
        prod.init(s);
        s.wr(1, DST_BASE, 0x3, 0x0101);   // Actual = ReadLocked = Buffer1
        s.wr(0, TIME_BASE, 0x3, 0x0101);
        s.wr(1, TIME_BASE, 0x3, 0x0101);
        s.wr(1, STAT_BASE, 0x3, 0x0101);
        s.wr(0, SRC_BASE, 0x2, 1u << 8);  // source ReadLocked = Buffer1
    }
};

static uint32_t ba(unsigned brd, unsigned word) { return brd << AW | word; }

// Exact fault-free timing of the attempts of one slot (all acked, back to back).
static void check_slot_timing(const char *what, const std::vector<Attempt> &v, uint64_t S, size_t expect_n) {
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

// ------------------------------------------------------------------ scenarios
static void scenario_basic() {
    std::printf("== basic: delivery, exact COPY timing, TIME, STATUS\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);  // cycle 0

    CHECK_EQ(G_DATA, "error_o after a valid header", 0, s.top->error_o);
    CHECK_EQ(G_ROM, "rom_errors_o with a valid ROM", 0, s.top->rom_errors_o);
    std::vector<Attempt> c0 = s.attempts(T0, T0 + L_COPY);
    check(G_TIMING, !c0.empty() && c0[0].start == T0 + S_COPY + F,
          "cycle 0 COPY: first access on the bus at cycle start + E1 + FETCH_CYCLES: expected %" PRIu64
          ", got %" PRIu64, T0 + S_COPY + F, c0.empty() ? 0 : c0[0].start);
    // first transfer after reset: the destination Actual copy is unknown, read back
    check_slot_timing("cycle 0 COPY (new, Actual copy unknown)", c0, T0 + S_COPY, 3 + W_COPY + 1 * (W_COPY + 3) + 1);

    std::vector<uint32_t> got;
    bool isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 0: consumer Import on board 1 returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char b[64];
        std::snprintf(b, sizeof b, "cycle 0: value word %u", i);
        CHECK_HEX(G_DATA, b, value(0)[i], got[i]);
    }
    if (c0.size() >= 3) CHECK_EQ(G_DATA, "cycle 0: taken_at = time_o in the ack clock of the final Actual load",
                                 c0[2].end, got[W_COPY]);
    CHECK_EQ(G_DATA, "cycle 0: destination Actual = last buffer neither Actual(1) nor ReadLocked(1)", 3,
             s.rd(1, DST_BASE) & 0xFF);

    // cycle 1: steady state, a new value
    u.prod.publish(s, value(1));
    const uint64_t C1 = T0 + H1;
    s.run_until(C1 + TAIL);
    std::vector<Attempt> c1 = s.attempts(C1, C1 + L_COPY);
    const size_t A = 3 + W_COPY + 1 * (W_COPY + 3);
    check_slot_timing("cycle 1 COPY (new, steady state)", c1, C1 + S_COPY, A);
    if (c1.size() == A) {
        // the access sequence: Import, Export control, streamed words, taken_at, Actual
        unsigned sb = u.prod.actual, db = pick(3, 3);   // dest Actual copy 3, ReadLocked 3 (consumer)
        std::vector<std::pair<bool, uint32_t>> exp = {
            {false, ba(0, SRC_BASE)}, {true, ba(0, SRC_BASE)}, {false, ba(0, SRC_BASE)},
            {false, ba(1, DST_BASE)}};
        for (unsigned i = 0; i < W_COPY; ++i) {
            exp.push_back({false, ba(0, SRC_BASE + 1 + (sb - 1) * W_COPY + i)});
            exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + i)});
        }
        exp.push_back({true, ba(1, DST_BASE + 1 + (db - 1) * (W_COPY + 1) + W_COPY)});
        exp.push_back({true, ba(1, DST_BASE)});
        for (size_t k = 0; k < A; ++k) {
            char b[96];
            std::snprintf(b, sizeof b, "cycle 1 COPY access %zu: {we, board, word}", k + 1);
            CHECK_HEX(G_DATA, b, (uint64_t)exp[k].first << 16 | exp[k].second,
                      (uint64_t)c1[k].we << 16 | c1[k].adr);
        }
    }
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1: consumer Import returns New", 1, isnew);
    for (unsigned i = 0; i < W_COPY; ++i) {
        char b[64];
        std::snprintf(b, sizeof b, "cycle 1: value word %u", i);
        CHECK_HEX(G_DATA, b, value(1)[i], got[i]);
    }
    if (c1.size() >= 3) CHECK_EQ(G_DATA, "cycle 1: taken_at", c1[2].end, got[W_COPY]);
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1: a second Import returns Old", 0, isnew);

    // TIME: value = taken_at = time at the slot start, on both boards
    for (int b = 0; b < 2; ++b) {
        Consumer &c = b ? u.time1 : u.time0;
        isnew = c.import(s, got);
        char m[96];
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: Import New", b);
        CHECK_EQ(G_DATA, m, 1, isnew);
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: value = slot start", b);
        CHECK_EQ(G_DATA, m, C1 + S_TIME, got[0]);
        std::snprintf(m, sizeof m, "cycle 1 TIME on board %d: taken_at = slot start", b);
        CHECK_EQ(G_DATA, m, C1 + S_TIME, got[1]);
    }
    std::vector<Attempt> t1 = s.attempts(C1 + S_TIME, C1 + S_TIME + L_TIME);
    check_slot_timing("cycle 1 TIME (2 destinations)", t1, C1 + S_TIME, 2 * (1 + 3));

    // STATUS: {rom_errors, cycles}, then {transfers, retries}, {abandoned, corrupt} per channel
    isnew = u.stat.import(s, got);
    CHECK_EQ(G_DATA, "cycle 1 STATUS: Import New", 1, isnew);
    CHECK_HEX(G_DATA, "cycle 1 STATUS word 0 {rom_errors, cycles}", 0u << 16 | 2u, got[0]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 0 {transfers, retries}", 2u << 16 | 0u, got[1]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 0 {abandoned, corrupt}", 0u, got[2]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 1 {transfers, retries}", 4u << 16 | 0u, got[3]);
    CHECK_HEX(G_DATA, "cycle 1 STATUS channel 2 {transfers, retries}", 1u << 16 | 0u, got[5]);
    CHECK_EQ(G_DATA, "cycle 1 STATUS taken_at = slot start", C1 + S_STAT, got[W_STAT]);
    std::vector<Attempt> st = s.attempts(C1 + S_STAT, C1 + S_STAT + L_STAT);
    check_slot_timing("cycle 1 STATUS", st, C1 + S_STAT, W_STAT + 3);
}

static void scenario_corrupt() {
    std::printf("== corrupt: an invalid entry is flagged and skipped; a flipped ROM bit stops the controller\n");
    std::vector<Entry> es = schedule();
    std::vector<uint32_t> rom = build_rom(H1, 0, es);
    rom[rom_addr(1, C::E0_W.word)] ^= C::E0_W.put(3);   // entry 1 (TIME): W = 2, CRC resealed
    reseal(rom, es.size());
    write_rom(rom);
    {
        Sim s;
        Setup u(s);
        const uint64_t T0 = t0_of((int)es.size());
        u.prod.publish(s, value(0));
        for (unsigned c = 0; c < 3; ++c) {
            uint64_t C = T0 + c * H1;
            s.run_until(C + TAIL);
            char m[128];
            std::snprintf(m, sizeof m, "cycle %u: rom_errors_o counts the bad entry once per cycle", c);
            CHECK_EQ(G_ROM, m, c + 1, s.top->rom_errors_o);
            std::vector<Attempt> cp = s.attempts(C + S_COPY, C + S_COPY + L_COPY);
            std::snprintf(m, sizeof m, "cycle %u: COPY first access at its slot start + FETCH_CYCLES", c);
            CHECK_EQ(G_ROM, m, C + S_COPY + F, cp.empty() ? 0 : cp[0].start);
            std::vector<Attempt> tm = s.attempts(C + S_TIME, C + S_TIME + L_TIME);
            std::snprintf(m, sizeof m, "cycle %u: the skipped TIME entry makes no access", c);
            CHECK_EQ(G_ROM, m, 0, tm.size());
            std::vector<Attempt> st = s.attempts(C + S_STAT, C + S_STAT + L_STAT);
            std::snprintf(m, sizeof m, "cycle %u: STATUS first access at its slot start + FETCH_CYCLES", c);
            CHECK_EQ(G_ROM, m, C + S_STAT + F, st.empty() ? 0 : st[0].start);
            std::vector<uint32_t> got;
            bool isnew = u.cons.import(s, got);
            std::snprintf(m, sizeof m, "cycle %u: COPY still delivers (New, word 0)", c);
            check(G_ROM, isnew && got[0] == value(c)[0], "%s: expected New 0x%08x, got %s 0x%08x", m,
                  value(c)[0], isnew ? "New" : "Old", got[0]);
            isnew = u.stat.import(s, got);
            std::snprintf(m, sizeof m, "cycle %u: STATUS word 0 {rom_errors, cycles}", c);
            CHECK_HEX(G_ROM, m, (c + 1) << 16 | (c + 1), got[0]);
            u.prod.publish(s, value(c + 1));
        }
        size_t n0 = s.att.size();
        s.run_until(s.now + 3 * H1);
        check(G_ROM, s.att.size() - n0 >= 3 * (W_STAT + 3 + 1),
              "no hang: 3 more cycles of COPY (1 access) and STATUS (%u): expected >= %zu accesses, got %zu",
              W_STAT + 3, (size_t)(3 * (W_STAT + 3 + 1)), s.att.size() - n0);
    }
    // a flipped bit in the header, or in an entry: the CRC fails, error_o, and the bus stays idle
    for (size_t word : {(size_t)C::H1_CYCLE.word, rom_addr(1, C::E1_START.word), rom_addr(2, 7)}) {
        rom = build_rom(H1, 0, es);
        rom[word] ^= 1u << 5;   // the CRC (H3) no longer matches
        write_rom(rom);
        Sim s;
        s.run_until(4 * H1);
        char m[96];
        std::snprintf(m, sizeof m, "bit flipped in ROM word %zu: error_o", word);
        CHECK_EQ(G_ROM, m, 1, s.top->error_o);
        std::snprintf(m, sizeof m, "bit flipped in ROM word %zu: bus accesses", word);
        CHECK_EQ(G_ROM, m, 0, s.att.size() + (s.in_att ? 1 : 0));
    }
}

// Fault kinds 1..3 on single accesses of the COPY slot, one cycle each.
static void scenario_faults() {
    std::printf("== faults: kinds 1, 2, 3 are retried; a landed Actual store is not published twice\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);

    struct Plan { int kind; size_t nth; const char *what; };   // nth: attempt of the slot, 1-based
    const Plan plans[3] = {{1, 1, "source Actual load"}, {2, 2, "source ReadLocked store"}, {3, 6, "first word store"}};
    for (unsigned c = 1; c <= 3; ++c) {
        const Plan &pl = plans[c - 1];
        const uint64_t C = T0 + c * H1;
        u.prod.publish(s, value(c));
        size_t seen = 0;
        s.fault = [&](const Attempt &a) {
            if (a.start < C || a.start >= C + L_COPY) return 0;
            return ++seen == pl.nth ? pl.kind : 0;
        };
        s.run_until(C + TAIL);
        s.fault = nullptr;
        std::vector<Attempt> v = s.attempts(C, C + L_COPY);
        char m[160];
        if (v.size() < pl.nth + 1) {
            check(G_FAULT, false, "kind %d on the %s: expected a retry, got %zu attempts", pl.kind, pl.what, v.size());
            continue;
        }
        const Attempt &f = v[pl.nth - 1], &r = v[pl.nth];
        int exp_res = pl.kind == 1 ? 2 : 3;
        std::snprintf(m, sizeof m, "kind %d on the %s: the attempt ends with %s", pl.kind, pl.what,
                      exp_res == 2 ? "err" : "a timeout (1 ack, 2 err, 3 timeout)");
        CHECK_EQ(G_FAULT, m, exp_res, f.result);
        if (exp_res == 3) {
            std::snprintf(m, sizeof m, "kind %d: cyc dropped after TIMEOUT clocks without ack", pl.kind);
            CHECK_EQ(G_FAULT, m, TMO, f.end - f.start);
        }
        std::snprintf(m, sizeof m, "kind %d: the same access is retried (we, board, word)", pl.kind);
        CHECK_HEX(G_FAULT, m, (uint64_t)f.we << 16 | f.adr, (uint64_t)r.we << 16 | r.adr);
        std::snprintf(m, sizeof m, "kind %d: cyc low at least one clock before the retry (gap)", pl.kind);
        check(G_FAULT, r.start >= f.end + (f.result == 3 ? 1 : 2), "%s: expected retry start >= %" PRIu64
              ", got %" PRIu64, m, f.end + (f.result == 3 ? 1 : 2), r.start);
        size_t performed = 0;
        for (const RamOp &op : s.ram)
            if (op.t >= f.start && op.t <= f.end + 1 && op.board == (int)(f.adr >> AW) &&
                op.adr == (f.adr & AMASK) && op.we == f.we)
                ++performed;
        std::snprintf(m, sizeof m, "kind %d: the RAM performed the faulted access (1) or not (0)", pl.kind);
        CHECK_EQ(G_FAULT, m, pl.kind == 2 ? 0 : 1, performed);
        bool isnew = u.cons.import(s, got);
        std::snprintf(m, sizeof m, "kind %d: the value still arrives (New, all words)", pl.kind);
        check(G_FAULT, isnew && got[0] == value(c)[0] && got[1] == value(c)[1] && got[2] == value(c)[2],
              "%s: expected New %08x %08x %08x, got %s %08x %08x %08x", m, value(c)[0], value(c)[1], value(c)[2],
              isnew ? "New" : "Old", got[0], got[1], got[2]);
    }
    bool isnew = u.stat.import(s, got);
    CHECK_HEX(G_FAULT, "STATUS after the three faults: channel 0 {transfers, retries}", 4u << 16 | 3u, got[1]);

    // kind 3 on the final Actual store, then the link is down to the slot end:
    // the store landed, so the next cycle reads it back and publishes nothing.
    const uint64_t C4 = T0 + 4 * H1;
    u.prod.publish(s, value(4));
    size_t seen = 0;
    const size_t A = 3 + W_COPY + (W_COPY + 3);
    s.fault = [&](const Attempt &a) {
        if (a.start < C4 || a.start >= C4 + L_COPY) return 0;
        if (++seen == A) {
            s.dead_next = 1u << 1;   // link down from the attempt's second clock on
            return 3;
        }
        return 0;
    };
    s.run_until(C4 + L_COPY);
    s.fault = nullptr;
    s.top->fi_dead_i = 0;
    s.run_until(C4 + TAIL);
    uint32_t act4 = s.rd(1, DST_BASE) & 0xFF;
    isnew = u.cons.import(s, got);
    check(G_FAULT, isnew && got[0] == value(4)[0],
          "landed Actual store: the consumer sees the value once: expected New 0x%08x, got %s 0x%08x",
          value(4)[0], isnew ? "New" : "Old", got[0]);
    const uint64_t C5 = C4 + H1;
    s.run_until(C5 + TAIL);
    std::vector<Attempt> v5 = s.attempts(C5, C5 + L_COPY);
    CHECK_EQ(G_FAULT, "next cycle: 2 accesses (source Actual load, read-back of the destination Actual)", 2,
             v5.size());
    if (v5.size() >= 2) CHECK_HEX(G_FAULT, "next cycle: access 2 reads back the destination Actual",
                                  (uint64_t)ba(1, DST_BASE), v5[1].adr);
    CHECK_EQ(G_FAULT, "next cycle: the destination Actual is unchanged", act4, s.rd(1, DST_BASE) & 0xFF);
    isnew = u.cons.import(s, got);
    CHECK_EQ(G_FAULT, "next cycle: the consumer's Import returns Old (not published twice)", 0, isnew);
    isnew = u.stat.import(s, got);
    CHECK_EQ(G_FAULT, "STATUS: channel 0 transfers (the landed store counted once, in the next cycle)", 5,
             got[1] >> 16);
    check(G_FAULT, (got[1] & 0xFFFF) > 4, "STATUS: channel 0 retries: expected > 4 (3 faults, then the dead link), got %u",
          got[1] & 0xFFFF);
    CHECK_EQ(G_FAULT, "STATUS: channel 0 abandoned (the slot of the landed store)", 1, got[2] >> 16);
}

// A board's link is down for a whole cycle: first board 1 (COPY's and STATUS's
// destination, TIME's second), then board 0 (COPY's source, TIME's first).
static void scenario_dead() {
    std::printf("== dead: a board link down for a cycle; slots stay on time, the others are served\n");
    std::vector<Entry> es = schedule();
    write_rom(build_rom(H1, 0, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    u.cons.import(s, got);
    u.time0.import(s, got);
    u.time1.import(s, got);
    u.prod.publish(s, value(1));
    const uint32_t starts[3] = {S_COPY, S_TIME, S_STAT}, lens[3] = {L_COPY, L_TIME, L_STAT};
    const char *names[3] = {"COPY", "TIME", "STATUS"};
    for (int dead = 1; dead >= 0; --dead) {
        const uint64_t C = T0 + (dead ? 1 : 3) * H1;
        s.run_until(C);
        s.top->fi_dead_i = 1u << dead;
        s.run_until(C + H1);
        s.top->fi_dead_i = 0;
        for (int e = 0; e < 3; ++e) {
            uint64_t S = C + starts[e], D = S + lens[e];
            std::vector<Attempt> v = s.attempts(S, D);
            char m[160];
            std::snprintf(m, sizeof m, "board %d dead, %s: first access at slot start + FETCH_CYCLES", dead, names[e]);
            CHECK_EQ(G_DEAD, m, S + F, v.empty() ? 0 : v[0].start);
            uint64_t last_start = 0, last_end = 0;
            size_t to_dead = 0, failed = 0;
            for (const Attempt &a : v) {
                last_start = std::max(last_start, a.start);
                last_end = std::max(last_end, a.end);
                to_dead += (a.adr >> AW) == (unsigned)dead;
                failed += a.result == 3;
            }
            std::snprintf(m, sizeof m, "board %d dead, %s: no access starts after D-TIMEOUT-2 (D = %" PRIu64 ")",
                          dead, names[e], D);
            check(G_DEAD, last_start <= D - TMO - 2, "%s: expected last start <= %" PRIu64 ", got %" PRIu64, m,
                  D - TMO - 2, last_start);
            std::snprintf(m, sizeof m, "board %d dead, %s: every access ends before the deadline", dead, names[e]);
            check(G_DEAD, last_end < D, "%s: expected last end < %" PRIu64 ", got %" PRIu64, m, D, last_end);
            bool source = dead == 0 && e == 0;   // COPY from the dead board: retried until the deadline
            if (source) {
                std::snprintf(m, sizeof m, "board %d dead, %s: only the source is tried, every try times out", dead,
                              names[e]);
                check(G_DEAD, to_dead == v.size() && failed == v.size() && v.size() > 2,
                      "%s: expected > 2 attempts, all to board %d and all timed out, got %zu attempts, %zu to it, "
                      "%zu timed out", m, dead, v.size(), to_dead, failed);
            } else if (!(dead == 0 && e == 2)) {   // STATUS does not touch board 0
                std::snprintf(m, sizeof m, "board %d dead, %s: the dead destination is tried twice, then dropped",
                              dead, names[e]);
                check(G_DEAD, to_dead == 2 && failed == 2, "%s: expected 2 attempts to it, both timed out, got %zu, "
                      "%zu timed out", m, to_dead, failed);
            }
        }
        // TIME still reaches the healthy board, whether the dead one comes first or second
        int live = 1 - dead;
        bool isnew = (live ? u.time1 : u.time0).import(s, got);
        char m[128];
        std::snprintf(m, sizeof m, "board %d dead: TIME still published to board %d (New, value = slot start)", dead,
                      live);
        check(G_DEAD, isnew && got[0] == C + S_TIME, "%s: expected New %" PRIu64 ", got %s %u", m, C + S_TIME,
              isnew ? "New" : "Old", got[0]);
        (dead ? u.time0 : u.time1).import(s, got);   // catch up with the other one
        if (dead == 1) {
            const uint64_t C2 = C + H1;
            s.run_until(C2 + TAIL);
            std::vector<Attempt> v2 = s.attempts(C2, C2 + L_COPY);
            CHECK_EQ(G_DEAD, "link back: COPY starts on time", C2 + F, v2.empty() ? 0 : v2[0].start);
            isnew = u.cons.import(s, got);
            check(G_DEAD, isnew && got[0] == value(1)[0],
                  "link back: the abandoned value is delivered: expected New 0x%08x, got %s 0x%08x", value(1)[0],
                  isnew ? "New" : "Old", got[0]);
            isnew = u.stat.import(s, got);
            CHECK_HEX(G_DEAD, "STATUS: channel 0 {abandoned, corrupt}", 1u << 16 | 0u, got[2]);
            CHECK_HEX(G_DEAD, "STATUS: channel 1 (TIME) {abandoned, corrupt}: only the dead destination", 1u << 16,
                      got[4]);
            CHECK_HEX(G_DEAD, "STATUS: channel 1 (TIME) {transfers, retries}: 2 + 1 + 2, 2 retries", 5u << 16 | 2u,
                      got[3]);
            u.time0.import(s, got);
            u.time1.import(s, got);
        }
    }
}

// Position-synchronised mode: entry 0 is the SYNC COPY.  After the last entry the
// controller polls the SYNC source's Actual every POLL clocks; a new value starts
// the next cycle in the clock after the poll's ack, else the cycle ends at H1.
static void scenario_sync() {
    std::printf("== sync: polls every POLL clocks, a new position starts the cycle, else H1 does\n");
    const int POLL = 16;
    std::vector<Entry> es = schedule();
    es[0].flags = C::EFLAG_SYNC;     // SYNC
    es.pop_back();                   // COPY, TIME
    write_rom(build_rom(H1, C::HFLAG_SYNC_MODE, es));
    Sim s;
    Setup u(s);
    const uint64_t T0 = t0_of((int)es.size());
    u.prod.publish(s, value(0));
    s.run_until(T0 + TAIL);
    std::vector<uint32_t> got;
    bool isnew = u.cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(0)[0], "sync cycle 0: the position arrives: expected New 0x%08x, got %s 0x%08x",
          value(0)[0], isnew ? "New" : "Old", got[0]);
    // polls: loads of the source's control word after the last slot
    auto polls = [&](uint64_t t0, uint64_t t1) {
        std::vector<Attempt> v;
        for (const Attempt &a : s.attempts(t0, t1))
            if (!a.we && a.adr == ba(0, SRC_BASE)) v.push_back(a);
        return v;
    };
    std::vector<Attempt> p0 = polls(T0 + S_TIME + L_TIME, T0 + TAIL);
    check(G_DATA, p0.size() >= 5, "sync cycle 0: the source is polled after the last slot: expected >= 5 polls, got %zu",
          p0.size());
    for (size_t i = 1; i < p0.size() && i < 4; ++i) {
        char m[96];
        std::snprintf(m, sizeof m, "sync cycle 0: poll %zu starts POLL clocks after poll %zu", i + 1, i);
        CHECK_EQ(G_TIMING, m, p0[i - 1].start + POLL, p0[i].start);
    }
    // a new position: the next cycle starts in the clock after the poll that sees it
    u.prod.publish(s, value(1));
    const uint64_t t_pub = s.now;
    s.run_until(T0 + H1 + TAIL);
    std::vector<Attempt> p1 = polls(t_pub, T0 + H1);
    uint64_t c1 = 0;
    for (const Attempt &a : p1)
        if (a.start > t_pub) { c1 = a.end + 1; break; }    // the first poll after the Actual store
    std::vector<Attempt> v1 = s.attempts(c1, c1 + L_COPY);
    check(G_TIMING, c1 && !v1.empty() && v1[0].start == c1 + S_COPY + F,
          "sync: a new position starts the cycle in the clock after the poll's ack (%" PRIu64
          "): SYNC COPY first access: expected %" PRIu64 ", got %" PRIu64, c1, c1 + S_COPY + F,
          v1.empty() ? 0 : v1[0].start);
    check(G_TIMING, c1 && c1 < T0 + H1, "sync: the cycle started early: expected before the H1 end %" PRIu64
          ", got %" PRIu64, T0 + H1, c1);
    if (c1) check_slot_timing("sync cycle 1 SYNC COPY (new)", v1, c1 + S_COPY, 3 + W_COPY + 1 * (W_COPY + 3));
    isnew = u.cons.import(s, got);
    check(G_DATA, isnew && got[0] == value(1)[0], "sync cycle 1: the new position arrives: expected New 0x%08x, got %s 0x%08x",
          value(1)[0], isnew ? "New" : "Old", got[0]);
    // no new position: the cycle ends at H1
    s.run_until(c1 + H1 + TAIL);
    std::vector<Attempt> v2 = s.attempts(c1 + H1, c1 + H1 + L_COPY);
    CHECK_EQ(G_TIMING, "sync: without a new position the next cycle starts at H1: first access", c1 + H1 + S_COPY + F,
             v2.empty() ? 0 : v2[0].start);
    std::vector<Attempt> p2 = polls(c1 + S_TIME + L_TIME, c1 + H1);
    uint64_t last_end = 0;
    for (const Attempt &a : p2) last_end = std::max(last_end, a.end);
    check(G_TIMING, !p2.empty() && last_end <= c1 + H1, "sync: polls until the cycle end: expected polls ending by %"
          PRIu64 ", got %zu polls, last end %" PRIu64, c1 + H1, p2.size(), last_end);
}

// ------------------------------------------------------------------ main
int main(int argc, char **argv) {
    g_argc = argc;
    g_argv = argv;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!std::strcmp(a, "--inject=timing")) g_inject_timing = true;
        else if (!std::strncmp(a, "--scenario=", 11)) only = a + 11;
        else if (!std::strncmp(a, "--dir=", 6)) {
            mkdir(a + 6, 0777);
            if (chdir(a + 6) != 0) {
                std::perror(a + 6);
                return 2;
            }
        }
        else {
            std::fprintf(stderr, "usage: %s [--dir=DIR] [--inject=timing] [--scenario=basic|corrupt|faults|dead|sync]\n",
                         argv[0]);
            return 2;
        }
    }
    if (g_inject_timing) std::printf("injected: the timing checker expects every completion one clock late\n");
    struct { const char *name; void (*fn)(); } sc[] = {
        {"basic", scenario_basic}, {"corrupt", scenario_corrupt}, {"faults", scenario_faults}, {"dead", scenario_dead},
        {"sync", scenario_sync}};
    for (auto &x : sc)
        if (only.empty() || only == x.name) x.fn();
    std::printf("test_controller: %u checks, %u failed%s\n", g_checks, g_fails,
                g_fails ? "" : " -- PASS");
    return g_fails ? 64 + (int)g_failed_groups : 0;
}
