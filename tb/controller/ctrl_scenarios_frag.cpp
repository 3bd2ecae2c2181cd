// ctrl_scenarios_frag.cpp -- test_controller scenario frag: a value carried
// in fragments (E7.frag; docs/controller.md "Fragments").  One three-buffer
// COPY of W = 5 words with frag = 2 runs once a cycle: fragment k (words
// [2k, min(2k + 2, 5))) in the k-th of its runs, so a value takes 3 cycles.
// Three parts, each on its own model:
//   whole   fault-free: nothing published before the last fragment, one
//           Actual store in it, the value delivered whole (the one held at
//           fragment 0, not the one the producer published meanwhile),
//           taken_at of fragment 0's Import; fragments 1 and 2 make no
//           access to the source's control word (its ReadLocked stays
//           held) and load the source words they carry from the held
//           buffer; the next value starts with a fresh Import.
//   retry   the source board is dead in fragment 1's slot: that fragment is
//           run again in the next cycle from the same word (2), the value
//           is published once, one cycle later, whole.
//   reset   the controller is reset after fragment 1: nothing of the cut
//           value is published; the value after the reset starts with a
//           fresh Import and is delivered whole.
#include "ctrl_bench.h"

namespace {

const unsigned FW = 5, FRAG = 2;     // W and words per fragment: fragments [0,2) [2,4) [4,5)

std::vector<uint32_t> fvalue(unsigned n) {
    std::vector<uint32_t> v = value(n);
    v.push_back(0xF0A90000u + n);
    v.push_back(0x0BADF00Du ^ (n << 8));
    return v;
}

// The schedule: one COPY of channel 0, W 5 in fragments of 2, every cycle.
bool write_frag_rom() {
    std::vector<Entry> es = {{COPY, 0, 0, FW, S_COPY, L_COPY, 0, SRC_BASE, {{1, DST_BASE}}, FRAG}};
    write_rom(build_rom(H1, 0, es));
    return true;
}

struct Frag {
    bool rom = write_frag_rom();      // (before the model, which reads it)
    Sim s;
    Producer prod{0, SRC_BASE, FW};
    Consumer cons{1, DST_BASE, FW + 1};
    uint64_t t0 = 0;
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
    // The word offsets in buffer b of the source loads in [from, to).
    std::vector<unsigned> src_words(size_t from, size_t to, unsigned b) const {
        std::vector<unsigned> v;
        const unsigned lo = SRC_BASE + 1 + (b - 1) * FW;
        for (size_t i = from; i < to && i < s.ram.size(); ++i) {
            const RamOp &r = s.ram[i];
            if (r.board == 0 && !r.we && r.adr >= SRC_BASE + 1) {
                if (r.adr >= lo && r.adr < lo + FW) v.push_back(r.adr - lo);
                else v.push_back(100 + r.adr);   // a word of another buffer
            }
        }
        return v;
    }
    // Run to the end of cycle c's slot work (its tail); return the RAM index there.
    size_t to_tail(unsigned c) {
        s.run_until(cyc(c) + TAIL);
        return s.ram.size();
    }
};

std::string words_str(const std::vector<unsigned> &v) {
    std::string r;
    for (unsigned x : v) r += (r.empty() ? "" : " ") + std::to_string(x);
    return r.empty() ? "none" : r;
}

void check_value(const char *what, const std::vector<uint32_t> &got, const std::vector<uint32_t> &exp) {
    bool ok = got.size() >= FW;
    for (unsigned i = 0; ok && i < FW; ++i) ok = got[i] == exp[i];
    check(G_DATA, ok, "%s: expected %08x %08x %08x %08x %08x, got %08x %08x %08x %08x %08x", what, exp[0], exp[1],
          exp[2], exp[3], exp[4], got.size() > 0 ? got[0] : 0, got.size() > 1 ? got[1] : 0, got.size() > 2 ? got[2] : 0,
          got.size() > 3 ? got[3] : 0, got.size() > 4 ? got[4] : 0);
}

void part_whole() {
    Frag f;
    std::vector<uint32_t> got;
    const unsigned b0 = f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    const size_t e0 = f.to_tail(0);
    CHECK_EQ(G_DATA, "frag whole: fragment 0 publishes nothing (Actual stores to the destination)", 0,
             f.dst_publishes(i0, e0));
    check(G_DATA, words_str(f.src_words(i0, e0, b0)) == "0 1", "frag whole: fragment 0 carries words 0 1: expected "
          "source loads of words 0 1 of buffer %u, got %s", b0, words_str(f.src_words(i0, e0, b0)).c_str());
    std::vector<Attempt> a0 = f.s.attempts(f.cyc(0), f.cyc(0) + H1);
    const uint64_t taken = a0.size() >= 3 ? a0[2].end : 0;
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after fragment 0 the consumer's Import returns Old", 0, isnew);
    const unsigned b1 = f.prod.publish(f.s, fvalue(1));   // the producer goes on: not the held buffer
    check(G_DATA, b1 != b0, "frag whole: the producer's next value avoids the held buffer: expected a buffer other "
          "than %u, got %u", b0, b1);
    const size_t i1 = f.s.ram.size();
    const size_t e1 = f.to_tail(1);
    CHECK_EQ(G_DATA, "frag whole: fragment 1 publishes nothing", 0, f.dst_publishes(i1, e1));
    CHECK_EQ(G_DATA, "frag whole: fragment 1 makes no access to the source's control word (its lock held)", 0,
             f.src_ctrl(i1, e1));
    check(G_DATA, words_str(f.src_words(i1, e1, b0)) == "2 3", "frag whole: fragment 1 resumes at word 2: expected "
          "source loads of words 2 3 of buffer %u, got %s", b0, words_str(f.src_words(i1, e1, b0)).c_str());
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after fragment 1 the consumer's Import returns Old", 0, isnew);
    const size_t i2 = f.s.ram.size();
    const size_t e2 = f.to_tail(2);
    CHECK_EQ(G_DATA, "frag whole: fragment 2 makes no access to the source's control word (its lock held)", 0,
             f.src_ctrl(i2, e2));
    check(G_DATA, words_str(f.src_words(i2, e2, b0)) == "4", "frag whole: fragment 2 resumes at word 4: expected "
          "source loads of word 4 of buffer %u, got %s", b0, words_str(f.src_words(i2, e2, b0)).c_str());
    CHECK_EQ(G_DATA, "frag whole: the last fragment publishes once (Actual stores)", 1, f.dst_publishes(i2, e2));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag whole: after the last fragment the consumer's Import returns New", 1, isnew);
    check_value("frag whole: the value delivered whole, the one held since fragment 0 (v0)", got, fvalue(0));
    CHECK_EQ(G_DATA, "frag whole: taken_at = the time of fragment 0's Import (its choosing load)", taken,
             got.size() > FW ? got[FW] : 0);
    // The next value: a fresh Import, then fragments 1 and 2.
    const size_t i3 = f.s.ram.size();
    const size_t e3 = f.to_tail(3);
    check(G_DATA, f.src_ctrl(i3, e3) > 0, "frag whole: the next value starts with a fresh Import: expected source "
          "control accesses in cycle 3, got %u", f.src_ctrl(i3, e3));
    f.to_tail(5);
    CHECK_EQ(G_DATA, "frag whole: the next value published once, in its last fragment (Actual stores, cycles 3..5)", 1,
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
    f.to_tail(0);
    f.s.top->fi_dead_i = 1u << 0;                  // the source's link is down in cycle 1's slot
    f.to_tail(1);
    f.s.top->fi_dead_i = 0;
    const size_t i2 = f.s.ram.size();
    const size_t e2 = f.to_tail(2);
    CHECK_EQ(G_DATA, "frag retry: nothing published while fragment 1 fails and runs again (Actual stores, cycles 0..2)",
             0, f.dst_publishes(i0, e2));
    check(G_DATA, words_str(f.src_words(i2, e2, b0)) == "2 3", "frag retry: fragment 1 runs again from word 2: "
          "expected source loads of words 2 3 of buffer %u in cycle 2, got %s", b0,
          words_str(f.src_words(i2, e2, b0)).c_str());
    CHECK_EQ(G_DATA, "frag retry: the rerun makes no access to the source's control word", 0, f.src_ctrl(i2, e2));
    const size_t e3 = f.to_tail(3);
    CHECK_EQ(G_DATA, "frag retry: the value published once, in cycle 3 (Actual stores)", 1, f.dst_publishes(e2, e3));
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag retry: the consumer's Import returns New", 1, isnew);
    check_value("frag retry: the value delivered whole (v0)", got, fvalue(0));
}

void part_reset() {
    Frag f;
    std::vector<uint32_t> got;
    f.prod.publish(f.s, fvalue(0));
    const size_t i0 = f.s.ram.size();
    f.to_tail(1);                                  // fragments 0 and 1 of v0
    f.s.top->rst_i = 1;
    for (int i = 0; i < 3; ++i) f.s.edge();
    f.s.top->rst_i = 0;
    f.s.top->eval();
    f.s.now = f.s.top->time_o;
    f.prod.publish(f.s, fvalue(1));                // published while the controller starts up
    const size_t r0 = f.s.ram.size();
    const size_t e0 = f.to_tail(0);
    check(G_DATA, f.src_ctrl(r0, e0) > 0, "frag reset: the first run after the reset Imports afresh: expected "
          "source control accesses, got %u", f.src_ctrl(r0, e0));
    f.to_tail(1);
    bool isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag reset: nothing of the cut value, nor of the next before its last fragment, is published "
             "(Actual stores)", 0, f.dst_publishes(i0, f.s.ram.size()));
    CHECK_EQ(G_DATA, "frag reset: the consumer's Import returns Old before the last fragment", 0, isnew);
    const size_t e2 = f.to_tail(2);
    CHECK_EQ(G_DATA, "frag reset: the value after the reset published once (Actual stores)", 1, f.dst_publishes(i0, e2));
    isnew = f.cons.import(f.s, got);
    CHECK_EQ(G_DATA, "frag reset: the consumer's Import returns New", 1, isnew);
    check_value("frag reset: the value after the reset delivered whole (v1)", got, fvalue(1));
}

}  // namespace

void scenario_frag() {
    std::printf("== frag: a value in 3 fragments (W 5, frag 2): whole, a fragment retried, a reset in the middle\n");
    part_whole();
    part_retry();
    part_reset();
}
