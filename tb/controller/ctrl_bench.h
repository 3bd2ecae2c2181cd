// ctrl_bench.h -- the shared part of test_controller (tb/controller/): constants,
// the checks, the schedule ROM builder, the model wrapper Sim (bus and RAM
// observation), the CPUs' three-buffer protocol and the scenarios' entry points.
// See test_controller.cpp for what the test does.
#pragma once
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
// 4 + 8*NE words, CRC_CHUNKS clocks each, then the check).  CRC_CHUNKS is
// albatross_rom_check's 32 / CRC_BITS (the default: this bench's start-up
// checks fail on every scenario if the two disagree).
static const int CRC_CHUNKS = 8;
static inline uint64_t t0_of(int ne) { return 2 * NCH + 6 + CRC_CHUNKS * (4 + 8 * (uint64_t)ne); }

// ------------------------------------------------------------------ checks
enum { G_TIMING = 1, G_DATA = 2, G_ROM = 4, G_FAULT = 8, G_DEAD = 16, G_ABANDON = 32 };
extern unsigned g_failed_groups;
extern unsigned g_checks, g_fails;
extern bool g_inject_timing;
extern int g_argc;                // the command line, for each model's +plusargs
extern char **g_argv;

void check(unsigned group, bool ok, const char *fmt, ...);
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
    unsigned frag = 0;                  // E7.frag: not 0, the value may go over several runs (0: one run)
};
enum { IDLE = C::KIND_IDLE, COPY = C::KIND_COPY, TIME = C::KIND_TIME, STATUS = C::KIND_STATUS };

// Word j of entry k.
size_t rom_addr(size_t k, unsigned j);

// The check word of a ROM of ne entries (its CRC then 0).
void reseal(std::vector<uint32_t> &r, size_t ne);

// hflags: the H0 flags field (C::HFLAG_SYNC_MODE: position-synchronised).
// drop_run: H2's drop run K (0 = an image from before, read as 2).
std::vector<uint32_t> build_rom(uint32_t h1, unsigned hflags, const std::vector<Entry> &es, unsigned drop_run = 0);

void write_rom(const std::vector<uint32_t> &r);

// The schedule of this test.
static const unsigned SRC_BASE = 0x010, DST_BASE = 0x020, TIME_BASE = 0x040, STAT_BASE = 0x080;
static const unsigned W_COPY = 3, W_STAT = 1 + 2 * NCH;
static const uint32_t H1 = 400;
static const uint32_t S_COPY = 0, L_COPY = 80, S_TIME = 80, L_TIME = 60, S_STAT = 140, L_STAT = 120;
static const uint32_t TAIL = 300;   // the slots end at 260: CPU work goes into [TAIL, H1)

std::vector<Entry> schedule();

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
    // The RAM operations ram[from, to) on board's word adr: all of them, or the
    // stores of its byte 0 (a control word's Actual byte: a publication).
    unsigned ops_at(int board, uint32_t adr, size_t from, size_t to) const {
        unsigned n = 0;
        for (size_t i = from; i < to && i < ram.size(); ++i) n += ram[i].board == board && ram[i].adr == adr;
        return n;
    }
    unsigned actual_stores(int board, uint32_t adr, size_t from, size_t to) const {
        unsigned n = 0;
        for (size_t i = from; i < to && i < ram.size(); ++i) {
            const RamOp &r = ram[i];
            n += r.board == board && r.we && r.adr == adr && (r.sel & 1);
        }
        return n;
    }
};

// ------------------------------------------------------------------ the CPUs' three-buffer protocol
unsigned pick(unsigned a, unsigned r);

struct Producer {                       // Export (the paper, figure 4) on one board
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

struct Consumer {                       // Import (the paper, figure 3) on one board
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

// ------------------------------------------------------------------ the CPUs' four-slot protocol
// The four-slot layout (rtl/albatross_contract.toml [layout.four_slot]):
// Actual, ReadLocked, Slot0, Slot1 in byte lanes 0..3 of the control word,
// Buffer1..4 from word 1; buffer b is pair (b-1)>>1, slot (b-1)&1.
static inline unsigned fs_buf(unsigned p, unsigned s) { return 1 + 2 * p + s; }
static inline unsigned fs_pair(unsigned b) { return (b - 1) >> 1; }

struct Producer4 {                      // the four-slot Export on one board
    int board;
    unsigned base, w;
    void init(Sim &s) { s.wr(board, base, 0xF, 0x00000101); }   // Actual = ReadLocked = 1, slots 0
    unsigned publish(Sim &s, const std::vector<uint32_t> &v) {
        uint32_t c = s.rd(board, base);
        unsigned r = c >> 8 & 0xFF;
        unsigned p = 1 - fs_pair(r), sl = 1 - (c >> (16 + 8 * p) & 1);
        unsigned b = fs_buf(p, sl);
        for (unsigned i = 0; i < w; ++i) s.wr(board, base + 1 + (b - 1) * w + i, 0xF, v[i]);
        s.wr(board, base, 1u << (2 + p), sl << (16 + 8 * p));   // Slot_p := s
        s.wr(board, base, 0x1, b);                              // Actual := b
        return b;
    }
};

struct Consumer4 {                      // the four-slot Import on one board: wait-free
    int board;
    unsigned base, words, l = 0;        // words: value + taken_at; l: the buffer read last (0 none)
    unsigned accesses = 0;              // control accesses of the last Import
    void init(Sim &s) { s.wr(board, base, 0xF, 0x00000101); l = 0; }
    bool import(Sim &s, std::vector<uint32_t> &out) {
        uint32_t c = s.rd(board, base);
        unsigned a = c & 0xFF, pa = fs_pair(a);
        bool isnew = fs_buf(pa, c >> (16 + 8 * pa) & 1) != l;
        accesses = 1;
        if (isnew) {
            s.wr(board, base, 0x2, a << 8);                     // ReadLocked := A
            c = s.rd(board, base);
            l = fs_buf(pa, c >> (16 + 8 * pa) & 1);
            accesses = 3;
        }
        out.resize(words);
        for (unsigned i = 0; i < words; ++i) out[i] = s.rd(board, base + 1 + (l - 1) * words + i);
        return isnew;
    }
};

std::vector<uint32_t> value(unsigned n);

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

uint32_t ba(unsigned brd, unsigned word);

// Exact fault-free timing of the attempts of one slot (all acked, back to back).
void check_slot_timing(const char *what, const std::vector<Attempt> &v, uint64_t S, size_t expect_n);

// ------------------------------------------------------------------ values over several runs
// A three-buffer COPY of W words whose value goes over several runs
// (scenarios frag, fragswitch): the words a run loads from the source's
// buffers and stores to the (one) destination's, and the words of the value
// stored so far.  A run's first word is what the controller's rule makes it:
// 0 for a run that Imports, else the first word not yet stored to the
// destination; check_run checks a run against it from the stores seen.
std::string words_str(const std::vector<unsigned> &v);   // "0 1 2", "none"

struct ValueRuns {
    const Sim &s;
    int sb;                       // source board and control word
    unsigned sbase;
    int db;                       // destination board and control word
    unsigned dbase, w;
    std::vector<bool> stored;     // words of the value stored to the destination
    unsigned bd = 0;              // the destination buffer of the value's word stores (0: none yet)
    ValueRuns(const Sim &sim, int sboard, unsigned sb_, int dboard, unsigned db_, unsigned words)
        : s(sim), sb(sboard), sbase(sb_), db(dboard), dbase(db_), w(words), stored(words, false) {}
    // The word offsets in source buffer b of the loads in ram[from, to) of
    // the source's buffers (100 + address: a word of another buffer, or
    // within a buffer's length of them).
    std::vector<unsigned> src_words(size_t from, size_t to, unsigned b) const;
    // The destination's buffer of the first value-word store in ram[from, to) (0: none).
    unsigned dst_buf(size_t from, size_t to) const;
    // The word offsets in destination buffer b of the value-word stores in
    // ram[from, to) (100 + address: another buffer's; taken_at not counted).
    std::vector<unsigned> dst_words(size_t from, size_t to, unsigned b) const;
    // taken_at stores to the destination in ram[from, to).
    unsigned taken_stores(size_t from, size_t to) const;
    // The stores of a publication in ram[from, to): stores of the
    // destination's Actual byte, and stores to its buffers of anything but
    // the source word just loaded at the same offset (taken_at, wherever it
    // goes).
    unsigned pub_stores(size_t from, size_t to) const;
    // The first word of the value not yet stored to the destination (w: all).
    unsigned first_unstored() const;
    void fresh();                 // a new value: nothing of it stored yet
    // Check one run in ram[from, to) whose first word is `first` (why: what
    // makes it so), source buffer b: its source loads are consecutive words
    // of b from `first`, its destination stores the same words in order to
    // the buffer of the value's first store (all, or all but a last load cut
    // off by the deadline before its store).  Records the words stored;
    // returns how many.  Failure messages start with `what`.
    unsigned check_run(const char *what, size_t from, size_t to, unsigned b, unsigned first, const char *why);
};

// ------------------------------------------------------------------ scenarios
// ctrl_scenarios_data.cpp
void scenario_basic();
void scenario_corrupt();
void scenario_four();
// ctrl_scenarios_cold.cpp
void scenario_cold();
// ctrl_scenarios_faults.cpp
void scenario_faults();
void scenario_dead();
void scenario_droprun();
void scenario_sync();
void scenario_abandon();
// ctrl_scenarios_modes.cpp
void scenario_modes();
// ctrl_scenarios_race.cpp
void scenario_deadline();
void scenario_race4();
// ctrl_scenarios_frag.cpp
void scenario_frag();
void scenario_fragedge();
// ctrl_scenarios_fragswitch.cpp
void scenario_fragswitch();
