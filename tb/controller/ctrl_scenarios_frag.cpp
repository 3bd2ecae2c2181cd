// ctrl_scenarios_frag.cpp -- test_controller scenario frag: a value carried
// over several runs ("fragments"; E7.frag != 0 marks the entry;
// docs/controller.md "Fragments").  One three-buffer COPY of W = 5 words runs
// once a cycle in a slot too short for the whole value (L_FRAG): a run
// stores words from its first (0 for a run that Imports; for a run that goes
// on with the value, the first word not yet stored to the destination) until
// the value's last word or until the deadline cuts the slot off, so the value
// takes RUNS = 3 runs.  The words a run carries are not written here: each
// run's first word comes from the destination's word stores the bench saw in
// the earlier runs, and a run loads consecutive words of the held source
// buffer from there and stores each to the buffer the first run picked.
// Four parts, each on its own model:
//   whole     fault-free: nothing published before the value's last word,
//             one Actual store after it, the value delivered whole (the one
//             held since the first run, not the one the producer published
//             meanwhile), taken_at of the first run's Import; the runs that
//             go on make no access to the source's control word (its
//             ReadLocked stays held) and each goes on at the first word not
//             yet stored; the next value starts with a fresh Import.
//   retry     the source board is dead in the second run's slot: that run
//             stores nothing and the next one goes on at the same word; in
//             that next run the source dies again after it stored 2 words:
//             the run, cut off by the deadline, keeps the words it stored
//             (the run after it starts after them); the value is published
//             once, whole.
//   firstcut  the source dies in the first run after the Import, before any
//             word is stored: no value goes on, the next run Imports afresh
//             and stores from word 0; the value is published once, whole.
//   reset     the controller is reset after the second run: nothing of the
//             cut value is published; the value after the reset starts with
//             a fresh Import and is delivered whole.
// Negatives (tools/mk/controller.mk): controller-negative-frag_publish_first,
// -frag_reimport, -frag_wrong_word.
// Scenario fragedge: a run that stores the value's last word and its
// taken_at but is cut off before the Actual store: the value goes on from
// word W - 1 (its load, stores and the publication again in the next run)
// and is published once, whole.  A controller that ends the value there
// instead (the next run Imports it again, Old, from word 0) repeats the
// same runs with this slot (words 0 1 | 2 3 4 and taken_at) and never
// publishes while the producer is idle: controller-negative-frag_pub_cut.
#include "ctrl_bench.h"

namespace {

// W, and E7.frag: not 0, the entry's value may go over several runs (the
// compiler's planned minimum of words per run; the controller does not use
// the number).
const unsigned FW = 5, FRAG = 1;
// The slot's length.  Fault-free, the accesses of a slot take 2 clocks each,
// back to back, access k (from 1) put on the bus at S + F + 2(k - 1) (phi is
// 0 here: S + F is odd in every cycle), and an access begins only if it
// would end before the deadline D = S + L even if it timed out
// (S + F + 2(k - 1) <= D - TMO - 2): a slot of 30 clocks begins 7 accesses.
// A first run: 3 for the Import of a New value (1 for an Old one), 1
// control load of the destination, then 2 per word (load, store); a run
// that goes on: 2 per word; the last run 2 more (taken_at, Actual).  So the
// first run of a New value stores 1 word (and loads word 1, cut off before
// its store), the second 3, the third the last and publishes: RUNS = 3
// (asserted by the checks on the progress and the publications below; the
// words each run carries are read from the stores the bench sees, not from
// this comment).
const uint32_t L_FRAG = 30;
const unsigned RUNS = 3;
static_assert(S_COPY + L_FRAG <= S_TIME, "frag: the COPY slot ends before the next one");

std::vector<uint32_t> fvalue(unsigned n) {
    std::vector<uint32_t> v = value(n);
    v.push_back(0xF0A90000u + n);
    v.push_back(0x0BADF00Du ^ (n << 8));
    return v;
}

// The schedule: one COPY of channel 0, W 5, a slot of L_FRAG, every cycle.
bool write_frag_rom() {
    std::vector<Entry> es = {{COPY, 0, 0, FW, S_COPY, L_FRAG, 0, SRC_BASE, {{1, DST_BASE}}, FRAG}};
    write_rom(build_rom(H1, 0, es));
    return true;
}

struct Frag {
    bool rom = write_frag_rom();      // (before the model, which reads it)
    Sim s;
    Producer prod{0, SRC_BASE, FW};
    Consumer cons{1, DST_BASE, FW + 1};
    uint64_t t0 = 0;
    ValueRuns v{s, 0, SRC_BASE, 1, DST_BASE, FW};   // the value's words per run
    Frag() {
        prod.init(s);
        s.wr(1, DST_BASE, 0x3, 0x0101);   // Actual = ReadLocked = Buffer1
        s.wr(0, SRC_BASE, 0x2, 1u << 8);  // source ReadLocked = Buffer1
        cons.rl = 1;
        t0 = t0_of(1);
    }
    uint64_t cyc(unsigned c) const { return t0 + (uint64_t)c * H1; }
    // RAM operations (index range) of the controller on the destination's Actual byte.
    unsigned dst_publishes(size_t from, size_t to) const { return s.actual_stores(1, DST_BASE, from, to); }
    unsigned src_ctrl(size_t from, size_t to) const { return s.ops_at(0, SRC_BASE, from, to); }
    // Run to the end of cycle c's slot work (its tail); return the RAM index there.
    size_t to_tail(unsigned c) {
        s.run_until(cyc(c) + TAIL);
        return s.ram.size();
    }
    // Run until the destination has n more value-word stores from ram[from]
    // (bounded: at most to the end of cycle c's slot); return how many came.
    unsigned run_to_stores(size_t from, unsigned n, unsigned c) {
        while (s.now < cyc(c) + S_COPY + L_FRAG && v.dst_words(from, s.ram.size(), v.bd).size() < n) s.tick();
        return (unsigned)v.dst_words(from, s.ram.size(), v.bd).size();
    }
};

void check_value(const char *what, const std::vector<uint32_t> &got, const std::vector<uint32_t> &exp) {
    bool ok = got.size() >= FW;
    for (unsigned i = 0; ok && i < FW; ++i) ok = got[i] == exp[i];
    check(G_DATA, ok, "%s: expected %08x %08x %08x %08x %08x, got %08x %08x %08x %08x %08x", what, exp[0], exp[1],
          exp[2], exp[3], exp[4], got.size() > 0 ? got[0] : 0, got.size() > 1 ? got[1] : 0, got.size() > 2 ? got[2] : 0,
          got.size() > 3 ? got[3] : 0, got.size() > 4 ? got[4] : 0);
}

const char *const FIRST_RUN = "word 0 (a run that Imports)";
const char *const GOES_ON = "the first word not yet stored to the destination";

void part_whole() {
    Frag f;
    std::vector<uint32_t> got;
    const unsigned b0 = f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    const size_t e0 = f.to_tail(0);
    CHECK_EQ(G_DATA, "frag whole: run 0 publishes nothing (taken_at and Actual stores to the destination)", 0,
             f.v.pub_stores(i0, e0));
    check(G_DATA, f.src_ctrl(i0, e0) > 0, "frag whole: run 0 Imports: expected source control accesses, got %u",
          f.src_ctrl(i0, e0));
    f.v.check_run("frag whole: run 0 starts", i0, e0, b0, 0, FIRST_RUN);
    const unsigned p0 = f.v.first_unstored();
    check(G_DATA, p0 > 0 && p0 < FW, "frag whole: run 0 stores a part of the value (the slot is too short for the "
          "whole): expected the first word not stored in 1..%u, got %u", FW - 1, p0);
    std::vector<Attempt> a0 = f.s.attempts(f.cyc(0), f.cyc(0) + H1);
    const uint64_t taken = a0.size() >= 3 ? a0[2].end : 0;
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after run 0 the consumer's Import returns Old", 0, isnew);
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));   // the producer goes on: not the held buffer
    check(G_DATA, b1 != b0, "frag whole: the producer's next value avoids the held buffer: expected a buffer other "
          "than %u, got %u", b0, b1);
    const size_t i1 = f.s.ram.size();
    const size_t e1 = f.to_tail(1);
    CHECK_EQ(G_DATA, "frag whole: run 1 publishes nothing (taken_at and Actual stores)", 0, f.v.pub_stores(i1, e1));
    CHECK_EQ(G_DATA, "frag whole: run 1 makes no access to the source's control word (its lock held)", 0,
             f.src_ctrl(i1, e1));
    f.v.check_run("frag whole: run 1 goes on", i1, e1, b0, p0, GOES_ON);
    const unsigned p1 = f.v.first_unstored();
    check(G_DATA, p1 > p0 && p1 < FW, "frag whole: run 1 stores more of the value but not its end (RUNS = %u): "
          "expected the first word not stored in %u..%u, got %u", RUNS, p0 + 1, FW - 1, p1);
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after run 1 the consumer's Import returns Old", 0, isnew);
    const size_t i2 = f.s.ram.size();
    const size_t e2 = f.to_tail(2);
    CHECK_EQ(G_DATA, "frag whole: run 2 makes no access to the source's control word (its lock held)", 0,
             f.src_ctrl(i2, e2));
    f.v.check_run("frag whole: run 2 goes on", i2, e2, b0, p1, GOES_ON);
    CHECK_EQ(G_DATA, "frag whole: run 2 stores the rest of the value (the first word not stored)", FW,
             f.v.first_unstored());
    CHECK_EQ(G_DATA, "frag whole: the value's last run publishes once (Actual stores)", 1, f.dst_publishes(i2, e2));
    CHECK_EQ(G_DATA, "frag whole: the value's last run stores taken_at and Actual once each (the publication's "
             "stores)", 2, f.v.pub_stores(i2, e2));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after the value's last run the consumer's Import returns New", 1, isnew);
    check_value("frag whole: the value delivered whole, the one held since run 0 (v0)", got, fvalue(0));
    CHECK_EQ(G_DATA, "frag whole: taken_at = the time of run 0's Import (its choosing load)", taken,
             got.size() > FW ? got[FW] : 0);
    // The next value: a fresh Import, from word 0, then RUNS - 1 runs that go on.
    f.v.fresh();
    const size_t i3 = f.s.ram.size();
    const size_t e3 = f.to_tail(RUNS);
    check(G_DATA, f.src_ctrl(i3, e3) > 0, "frag whole: the next value starts with a fresh Import: expected source "
          "control accesses in cycle %u, got %u", RUNS, f.src_ctrl(i3, e3));
    f.v.check_run("frag whole: the next value's first run starts", i3, e3, b1, 0, FIRST_RUN);
    f.to_tail(2 * RUNS - 1);
    CHECK_EQ(G_DATA, "frag whole: the next value published once, in its last run (Actual stores, cycles 3..5)", 1,
             f.dst_publishes(i3, f.s.ram.size()));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: the next value is New", 1, isnew);
    check_value("frag whole: the next value delivered whole (v1)", got, fvalue(1));
}

void part_retry() {
    Frag f;
    std::vector<uint32_t> got;
    const unsigned b0 = f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    const size_t e0 = f.to_tail(0);
    f.v.check_run("frag retry: run 0 starts", i0, e0, b0, 0, FIRST_RUN);
    const unsigned p0 = f.v.first_unstored();
    // Cycle 1: the source's link is down for the whole slot.
    f.s.top->fi_dead_i = 1u << 0;
    const size_t e1 = f.to_tail(1);
    f.s.top->fi_dead_i = 0;
    CHECK_EQ(G_DATA, "frag retry: the run with the source dead stores nothing (value-word stores to the destination)",
             0, f.v.dst_words(e0, e1, f.v.bd).size());
    // Cycle 2: the run goes on at the same word; the source dies once it has
    // stored CUT words (2: the run after it then has room for the rest and
    // the publication; 1 would leave it the value's last words and taken_at
    // but not Actual: scenario fragedge).
    const unsigned CUT = 2;
    const size_t i2 = f.s.ram.size();
    const unsigned n2 = f.run_to_stores(i2, CUT, 2);
    f.s.top->fi_dead_i = 1u << 0;
    const size_t e2 = f.to_tail(2);
    f.s.top->fi_dead_i = 0;
    CHECK_EQ(G_DATA, "frag retry: nothing published while the source fails (Actual stores, cycles 0..2)", 0,
             f.dst_publishes(i0, e2));
    CHECK_EQ(G_DATA, "frag retry: the run after the failed one makes no access to the source's control word", 0,
             f.src_ctrl(e0, e2));
    const unsigned c2 = f.v.check_run("frag retry: the run after the failed one goes on", i2, e2, b0, p0,
                                    "the word the failed run was to store");
    check(G_DATA, n2 == CUT && c2 == CUT && f.v.first_unstored() < FW, "frag retry: the run cut off by the source's "
          "death stores %u words and leaves the value unfinished: expected %u words stored before the source died, "
          "%u in the run, a word not stored; got %u, %u, the first word not stored %u", CUT, CUT, CUT, n2, c2,
          f.v.first_unstored());
    // Cycle 3: the run after the cut one starts after the words it stored.
    const unsigned p2 = f.v.first_unstored();
    check(G_DATA, p2 == p0 + c2, "frag retry: the cut run keeps the words it stored: expected the first word not "
          "stored %u (after them), got %u", p0 + c2, p2);
    const size_t i3 = f.s.ram.size();
    const size_t e3 = f.to_tail(3);
    f.v.check_run("frag retry: the run after the cut one goes on", i3, e3, b0, p2, GOES_ON);
    CHECK_EQ(G_DATA, "frag retry: the run after the cut one stores the rest (the first word not stored)", FW,
             f.v.first_unstored());
    CHECK_EQ(G_DATA, "frag retry: the value published once, in cycle 3 (Actual stores)", 1, f.dst_publishes(e2, e3));
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag retry: the consumer's Import returns New", 1, isnew);
    check_value("frag retry: the value delivered whole (v0)", got, fvalue(0));
}

void part_firstcut() {
    Frag f;
    std::vector<uint32_t> got;
    f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    // Cycle 0: the source dies once the destination's control load is done
    // (the Import made, no word loaded yet).
    while (f.s.now < f.cyc(0) + S_COPY + L_FRAG && f.s.ops_at(1, DST_BASE, i0, f.s.ram.size()) == 0) f.s.tick();
    f.s.top->fi_dead_i = 1u << 0;
    const size_t e0 = f.to_tail(0);
    f.s.top->fi_dead_i = 0;
    check(G_DATA, f.src_ctrl(i0, e0) > 0 && f.s.ops_at(1, DST_BASE, i0, e0) == 1,
          "frag firstcut: run 0 Imports and loads the destination's control word: expected source control accesses "
          "and 1 destination control load, got %u and %u", f.src_ctrl(i0, e0), f.s.ops_at(1, DST_BASE, i0, e0));
    CHECK_EQ(G_DATA, "frag firstcut: run 0 stores no word (value-word stores to the destination)", 0,
             f.v.dst_words(i0, e0, 0).size());
    // The producer publishes v1 (the next run's Import takes it: New, so its
    // runs are as in part whole; Imported again Old, the value would be cut
    // where scenario fragedge shows).
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));
    // Cycle 1: no value goes on: a fresh Import, words from 0.
    const size_t e1 = f.to_tail(1);
    check(G_DATA, f.src_ctrl(e0, e1) > 0, "frag firstcut: the run after a first run that stored no word Imports "
          "afresh: expected source control accesses, got %u", f.src_ctrl(e0, e1));
    f.v.check_run("frag firstcut: the run after it starts", e0, e1, b1, 0, FIRST_RUN);
    const size_t e3 = f.to_tail(RUNS);
    CHECK_EQ(G_DATA, "frag firstcut: the value published once, in cycles 1..3 (Actual stores)", 1,
             f.dst_publishes(i0, e3));
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag firstcut: the consumer's Import returns New", 1, isnew);
    check_value("frag firstcut: the value delivered whole (v1)", got, fvalue(1));
}

void part_reset() {
    Frag f;
    std::vector<uint32_t> got;
    f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    f.to_tail(1);                                  // runs 0 and 1 of v0
    check(G_DATA, f.v.dst_buf(i0, f.s.ram.size()) != 0, "frag reset: runs 0 and 1 store words of v0: expected value-"
          "word stores to the destination, got none");
    f.s.top->rst_i = 1;
    for (int i = 0; i < 3; ++i) f.s.edge();
    f.s.top->rst_i = 0;
    f.s.top->eval();
    f.s.now = f.s.top->time_o;
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));   // published while the controller starts up
    f.v.fresh();
    const size_t r0 = f.s.ram.size();
    const size_t e0 = f.to_tail(0);
    check(G_DATA, f.src_ctrl(r0, e0) > 0, "frag reset: the first run after the reset Imports afresh: expected "
          "source control accesses, got %u", f.src_ctrl(r0, e0));
    f.v.check_run("frag reset: the first run after the reset starts", r0, e0, b1, 0, FIRST_RUN);
    f.to_tail(RUNS - 2);
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag reset: nothing of the cut value, nor of the next before its last run, is published "
             "(Actual stores)", 0, f.dst_publishes(i0, f.s.ram.size()));
    CHECK_EQ(G_DATA, "frag reset: the consumer's Import returns Old before the value's last run", 0, isnew);
    const size_t e2 = f.to_tail(RUNS - 1);
    CHECK_EQ(G_DATA, "frag reset: the value after the reset published once (Actual stores)", 1, f.dst_publishes(i0, e2));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag reset: the consumer's Import returns New", 1, isnew);
    check_value("frag reset: the value after the reset delivered whole (v1)", got, fvalue(1));
}

// One line per cycle c in [c0, c1]: the words the run stored, its taken_at
// and Actual stores to the destination, and whether it Imported.
std::string run_summary(Frag &f, unsigned c0, unsigned c1) {
    std::string r;
    for (unsigned c = c0; c <= c1; ++c) {
        size_t from = 0, to = f.s.ram.size();
        for (size_t i = 0; i < f.s.ram.size(); ++i) {
            if (f.s.ram[i].t < f.cyc(c)) from = i + 1;
            if (f.s.ram[i].t < f.cyc(c) + H1) to = i + 1;
        }
        const unsigned bd = f.v.dst_buf(from, to);
        const unsigned tkn = f.v.taken_stores(from, to);
        char b[160];
        std::snprintf(b, sizeof b, "%scycle %u: %s, words %s, taken_at %u, Actual %u", r.empty() ? "" : "; ", c,
                      f.src_ctrl(from, to) ? "Import" : "goes on", words_str(f.v.dst_words(from, to, bd)).c_str(), tkn,
                      f.dst_publishes(from, to));
        r += b;
    }
    return r;
}

// Scenario fragedge: a value whose run stores its last word and begins its
// publication (taken_at) but is cut off before the Actual store.  The value
// goes on from word W - 1, and the next run publishes it.  (Were it to end
// there, the next run would Import afresh and send an Old value again from
// word 0; with a fixed slot the runs would repeat the same words and a value
// Imported Old would never be published while the producer is idle.)  Two
// ways in: a first run cut before its first word (the value Imported again,
// Old: runs of words 0 1 | 2 3 4 and taken_at), and a run cut by the
// source's death after one word (part retry with CUT = 1).  The checks
// expect the value published within 2 * RUNS cycles (negative:
// controller-negative-frag_pub_cut).
void edge_check(Frag &f, const char *what, unsigned c0, unsigned c1) {
    const size_t e = f.to_tail(c1);
    std::vector<uint32_t> got;
    const unsigned pubs = f.dst_publishes(0, e);
    const bool isnew = f.cons.import(f.s, got);
    check(G_DATA, pubs == 1 && isnew, "frag edge %s: expected the value published once by cycle %u (Actual stores, "
          "the consumer's Import New), got %u Actual stores, Import %s; runs: %s", what, c1, pubs,
          isnew ? "New" : "Old", run_summary(f, c0, c1).c_str());
    if (isnew) check_value("frag edge: the value delivered whole (v0)", got, fvalue(0));
}

void edge_firstcut() {
    Frag f;
    f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    while (f.s.now < f.cyc(0) + S_COPY + L_FRAG && f.s.ops_at(1, DST_BASE, i0, f.s.ram.size()) == 0) f.s.tick();
    f.s.top->fi_dead_i = 1u << 0;
    f.to_tail(0);
    f.s.top->fi_dead_i = 0;
    edge_check(f, "firstcut (the value Imported again, Old)", 0, 2 * RUNS);
}

void edge_retry() {
    Frag f;
    f.prod.publish(f.s, fvalue(0));
    f.to_tail(0);
    f.s.top->fi_dead_i = 1u << 0;
    f.to_tail(1);
    f.s.top->fi_dead_i = 0;
    const size_t i2 = f.s.ram.size();
    f.v.bd = f.v.dst_buf(0, i2);
    f.run_to_stores(i2, 1, 2);
    f.s.top->fi_dead_i = 1u << 0;
    f.to_tail(2);
    f.s.top->fi_dead_i = 0;
    edge_check(f, "retry (a run cut after 1 word)", 0, 2 + 2 * RUNS);
}

}  // namespace

void scenario_fragedge() {
    std::printf("== fragedge: a run cut off between the value's taken_at and Actual stores (W %u, a slot of %u "
                "clocks): the value must still be published\n", FW, L_FRAG);
    edge_firstcut();
    edge_retry();
}

void scenario_frag() {
    std::printf("== frag: a value over %u runs (W %u, a slot of %u clocks): whole, a run failed and one cut off, a "
                "first run cut, a reset in the middle\n", RUNS, FW, L_FRAG);
    part_whole();
    part_retry();
    part_firstcut();
    part_reset();
}
