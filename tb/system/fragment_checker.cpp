// fragment_checker.cpp -- see fragment_checker.h.
#include "fragment_checker.h"
#include <algorithm>
#include <cstdio>
#include <fstream>
#include "albatross_contract.h"
extern "C" {
#include "albatross_layout.h"
}

using namespace alb_contract;

namespace {
// Clocks an access may end after its entry's deadline S + E2: none (the
// sequencer lets an access start only if it ends by D even when it times out).
const uint64_t kWindowSlack = 0;
// The fewest clocks of one bus access: the request and the answer in the next
// clock (the compiler's bus.access_cycles).
const uint64_t kMinAccessClocks = 2;
}

FragmentChecker::FragmentChecker(const std::string &rom, const Plan &plan, SystemChecker &chk) : chk_(chk)
{
    std::ifstream in(rom);
    std::vector<uint32_t> w;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '/' || line[0] == '#') continue;
        w.push_back(static_cast<uint32_t>(std::stoul(line, nullptr, 16)));
    }
    if (w.size() < ROM_HEADER_WORDS) { why_ = "no ROM image in " + rom; return; }
    const unsigned ne = H0_NE.get(w[0]);
    if (H2_MODES.get(w[2]) != 0) { why_ = "an image with modes (not judged)"; return; }
    if (w.size() < ROM_HEADER_WORDS + ROM_ENTRY_WORDS * ne) { why_ = "a short ROM image"; return; }
    cluster_ = H2_CLUSTER.get(w[2]);
    rigid_ = (H0_FLAGS.get(w[0]) & HFLAG_SYNC_MODE) == 0;
    cycle_len_ = H1_CYCLE.get(w[1]);
    drop_run_ = std::max(2u, static_cast<unsigned>(H2_DROP_RUN.get(w[2])));
    for (unsigned k = 0; k < ne; ++k) {
        const uint32_t *e = &w[ROM_HEADER_WORDS + ROM_ENTRY_WORDS * k];
        Entry x;
        x.index = static_cast<int>(k);
        x.kind = E0_KIND.get(e[0]);
        x.flags = E0_FLAGS.get(e[0]);
        x.id = E0_ID.get(e[0]);
        x.nd = E0_ND.get(e[0]);
        x.w = E0_W.get(e[0]);
        x.start = E1_START.get(e[1]);
        x.length = E2_LENGTH.get(e[2]);
        x.base = E6_BASE.get(e[6]);
        x.rep = E6_REP.get(e[6]);
        x.frag = E7_FRAG.get(e[7]);
        entries_.push_back(x);
        if (x.kind == KIND_IDLE) continue;
        Chan &c = chans_[x.id];
        if (c.entries.empty()) {
            c.id = x.id;
            c.w = x.w;
            c.kind = x.kind;
            c.name = "channel " + std::to_string(x.id);
            for (const PlanChannel &pc : plan.channels)
                if (pc.id == static_cast<int>(x.id)) c.name = pc.name;
            c.four = (x.flags & EFLAG_FOUR_SLOT) != 0;
            if (x.kind == KIND_COPY)
                c.src = Place{static_cast<int>(E3_SRC_BOARD.get(e[3])), 4 * E3_SRC_BASE.get(e[3])};
            for (unsigned d = 0; d < x.nd && d < ROM_MAX_DESTS; ++d) {
                const Field &f = DST[d];
                const uint32_t p = f.get(e[f.word]);
                c.dst.push_back(Place{static_cast<int>(PLACE_BOARD.get(p)), 4 * PLACE_BASE.get(p)});
            }
            c.in.assign(c.dst.size(), false);
            c.bufs.assign(c.dst.size(), std::vector<DestBuf>(5));
            for (auto &bv : c.bufs)
                for (DestBuf &b : bv) b.words.assign(c.w + 1, false);
        }
        c.sync = c.sync || (x.flags & EFLAG_SYNC) != 0;
        c.entries.push_back(static_cast<int>(k));
    }
    active_ = true;
}

uint32_t FragmentChecker::inst_bytes(const Chan &c, bool dest) const
{
    const uint32_t size = 4 * (c.w + (dest ? 1 : 0));
    return c.four ? ALB_FS_CHANNEL_BYTES(size) : ALB_CHANNEL_BYTES(size);
}

FragmentChecker::Chan *FragmentChecker::find(int board, uint32_t addr, int &dest)
{
    for (auto &kv : chans_) {
        Chan &c = kv.second;
        if (c.src.board == board && addr >= c.src.base && addr < c.src.base + inst_bytes(c, false)) {
            dest = -1;
            return &c;
        }
        for (size_t d = 0; d < c.dst.size(); ++d)
            if (c.dst[d].board == board && addr >= c.dst[d].base && addr < c.dst[d].base + inst_bytes(c, true)) {
                dest = static_cast<int>(d);
                return &c;
            }
    }
    return nullptr;
}

void FragmentChecker::tick(uint64_t cycle, bool cycle_start)
{
    if (!active_ || !cycle_start) return;
    if (started_ && rigid_ && cycle - cycle_start_ != cycle_len_) {
        char m[200];
        cur_ = nullptr;
        std::snprintf(m, sizeof m, "minor cycle %llu began %llu clocks after the one before: expected H1, %llu clocks "
                      "(a time-rigid image)", static_cast<unsigned long long>((count_ + 1) & ((1ull << cluster_) - 1)),
                      static_cast<unsigned long long>(cycle - cycle_start_), static_cast<unsigned long long>(cycle_len_));
        violation(SystemChecker::DUE_CYCLE, m);
    }
    if (started_) ++count_;
    started_ = true;
    prev_start_ = cycle_start_;
    cycle_start_ = cycle;
    ++minor_cycles;
}

// The entry of channel c due in minor cycle n whose window holds an access
// from rel to end_rel (clocks from the cycle start).
const FragmentChecker::Entry *FragmentChecker::due_entry(const Chan &c, uint64_t n, uint64_t rel, uint64_t end_rel) const
{
    for (int k : c.entries) {
        const Entry &x = entries_[k];
        if ((n & ((1ull << x.rep) - 1)) != x.base) continue;
        if (rel >= x.start && end_rel <= x.start + x.length + kWindowSlack) return &x;
    }
    return nullptr;
}

std::string FragmentChecker::dest_list(const Chan &c, const std::vector<bool> &set) const
{
    std::string r;
    for (size_t d = 0; d < set.size(); ++d)
        if (set[d]) r += (r.empty() ? "board " : ", board ") + std::to_string(c.dst[d].board);
    return r.empty() ? "none" : r;
}

// The first word from `from` on that the current run did not store (acked) to d.
uint32_t FragmentChecker::first_missing(const Chan &c, size_t d, uint32_t from) const
{
    uint32_t w = from;
    while (w < c.w && c.run_stored[d][w]) ++w;
    return w;
}

// A faulted request begun in [from, to] (unaddressed_only: one to a dead board).
bool FragmentChecker::faulted(uint64_t from, uint64_t to, bool unaddressed_only) const
{
    for (const auto &f : faults_)
        if (f.first >= from && f.first <= to && (!unaddressed_only || !f.second)) return true;
    return false;
}

void FragmentChecker::begin_run(Chan &c, uint64_t cyc, int entry, bool import)
{
    char m[400];
    c.run_cycle = cyc;
    c.run_entry = entry;
    c.run_import = import;
    c.run_words = false;
    c.run_frag = entry >= 0 ? entries_[entry].frag : 0;
    c.ld_word = c.ld_max = -1;
    c.fail_run = 0;
    c.run_ctrl.assign(c.dst.size(), false);
    c.run_dropped.assign(c.dst.size(), false);
    c.run_pub.assign(c.dst.size(), false);
    c.run_att.assign(c.dst.size(), false);
    c.run_stored.assign(c.dst.size(), std::vector<bool>(c.w + 1, false));
    ++runs;
    if (c.kind != KIND_COPY) return;
    if (import && c.on == ON_YES) {
        std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu accesses the source's control word "
                      "(an Import) while its value %u goes on at word %u of %u: the source's lock released between runs "
                      "(expected the value's next words from the held Buffer%d, no Import)",
                      c.name.c_str(), entry, static_cast<unsigned long long>(cyc & ((1ull << cluster_) - 1)), c.held_seq, c.prog, c.w,
                      c.held_buffer);
        violation(SystemChecker::SOURCE_LOCK, m);
    }
    if (import) {
        c.held_buffer = 0;
        c.held_seq = ~0u;
        c.run_p0 = 0;
        c.ld_next = 0;
    } else {
        c.run_p0 = c.prog;
        c.ld_next = (c.on == ON_YES || c.on == ON_MAYBE) ? static_cast<int64_t>(c.prog) : -1;
    }
}

void FragmentChecker::end_run(Chan &c)
{
    const int entry = c.run_entry;
    if (entry < -1 || c.kind != KIND_COPY) { c.run_entry = -2; return; }
    c.run_entry = -2;
    const bool hit = c.run_hit, blind = c.run_blind;   // (blind: a fault at an address not told: drops unknown)
    const size_t nd = c.dst.size();
    if (!c.run_words) {
        // Nothing carried: an Import that found nothing to send (or was cut)
        // leaves no value going on; a run going on with a value and cut
        // before its first word keeps the state.
        if (c.run_import) c.on = ON_NO;
        return;
    }
    if (hit) ++incomplete_runs;
    // V: the destinations in the value during the run (a first run: those it
    // stored word 0 to; going on: those still in it).
    std::vector<bool> v(nd, false), after(nd, false);
    bool any_after = false, any_whole = true, some_whole = false, dropped = false;
    uint32_t p = c.w;
    for (size_t d = 0; d < nd; ++d) {
        v[d] = c.run_import ? c.run_stored[d][0] : c.in[d];
        dropped = dropped || c.run_dropped[d];
        if (!v[d]) continue;
        const uint32_t fm = first_missing(c, d, c.run_p0);
        some_whole = some_whole || fm == c.w;
        any_whole = any_whole && (fm == c.w || c.run_dropped[d]);
        after[d] = !c.run_dropped[d];
        if (after[d]) any_after = true, p = std::min(p, fm);
    }
    const bool ended = some_whole && any_whole;    // the value's last word stored to all (the publication follows)
    if (!any_after) p = c.run_p0;
    const uint32_t carried = p > c.run_p0 ? p - c.run_p0 : 0;
    // The compiler's plan: at least E7.frag words per run, within its fault
    // hypothesis; judged where no fault hit the run.
    const uint32_t plan = std::min<uint32_t>(c.run_frag, c.w - std::min(c.w, c.run_p0));
    if (c.run_frag != 0 && !hit) {
        ++min_judged;
        if (!ended && carried < plan) {
            char m[400];
            std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu (clocks %llu..%llu, %s) stored words "
                          "[%u, %u) of value %u (%u words) to every destination still in it (%s), %u words, and no fault "
                          "hit it: expected at least E7.frag = %u words (the compiler plans each run for them) or the "
                          "value's end", c.name.c_str(), entry, static_cast<unsigned long long>(c.run_cycle & ((1ull << cluster_) - 1)),
                          static_cast<unsigned long long>(c.run_ws), static_cast<unsigned long long>(c.run_we),
                          c.run_import ? "an Import" : "going on", c.run_p0, p, c.held_seq, c.w, dest_list(c, after).c_str(),
                          carried, c.run_frag);
            violation(SystemChecker::FRAGMENT_WORD, m);
        }
    }
    if (hit && c.run_frag != 0 && ((!ended && carried < plan) || dropped)) ++cut_fragments;
    if (c.run_import) c.value_runs = 0;
    ++c.value_runs;
    if (!c.run_import) ++later_fragments;
    // After the run (rtl/albatross_transfer.v "Values over several runs"):
    // live, the destinations still in the value and not published (Actual
    // store acked); safe, none of them had a Slot or Actual store put on the
    // bus in this run (a begun one may have landed); counted, a word other
    // than the value's last (W - 1) whose stores ended in this run: words
    // [run_p0, pc), pc = min(p, W - 1).  The value goes on iff live is not
    // empty, safe, and the run went on with it or its entry has E7.frag != 0
    // and a word was counted; it goes on from pc (the progress stays where
    // none was counted), so a value cut off in its publication goes on from
    // word W - 1.  Else it ends (the next run Imports afresh).
    std::vector<bool> live(nd, false);
    bool any_live = false, safe = true, any_pub = false;
    for (size_t d = 0; d < nd; ++d) {
        any_pub = any_pub || (v[d] && c.run_pub[d]);
        live[d] = after[d] && !c.run_pub[d];
        if (!live[d]) continue;
        any_live = true;
        safe = safe && !c.run_att[d];
    }
    const uint32_t pc = std::min(p, c.w > 0 ? c.w - 1 : 0);
    const bool counted = any_after && pc > c.run_p0;
    if (!any_live && any_pub && c.value_runs >= 2) ++fragmented_publications;
    if (c.run_import) {
        // A first run: the value goes on if its entry has E7.frag != 0 and a
        // word was counted: certain when it began a later word (or stored
        // word 0 to every destination whose control word it accessed that was
        // not dropped); else maybe (a destination whose earlier store landed
        // leaves at its control load, silently, and word 0's stores may have
        // ended without it).
        bool certain = c.ld_max >= 1;
        bool all = true;
        for (size_t d = 0; d < nd; ++d) all = all && (!c.run_ctrl[d] || c.run_stored[d][0] || c.run_dropped[d]);
        certain = certain || all;
        if (c.run_frag == 0 || !any_live || c.w < 2) { c.on = ON_NO; return; }
        // (blind: a destination the checker thinks live may have been dropped)
        if (blind) { c.on = ON_UNKNOWN; return; }
        if (!counted || !safe) { c.on = ON_NO; return; }
        c.on = certain ? ON_YES : ON_MAYBE;
        c.in = live;
        c.prog = pc;
        return;
    }
    if (c.on == ON_UNKNOWN || (blind && any_live)) { c.on = ON_UNKNOWN; return; }
    if (!any_live || !safe) { c.on = ON_NO; return; }   // the value ends: the next run Imports afresh
    c.on = ON_YES;
    c.in = live;
    if (counted) c.prog = pc;
}

const FragmentChecker::Entry *FragmentChecker::locate(const Chan &c, uint64_t start, uint64_t end, uint64_t &cnt,
                                                      uint64_t &cs, const Entry *&x) const
{
    // The minor cycle the access began in.
    const bool before = start < cycle_start_ && count_ > 0;
    cs = before ? prev_start_ : cycle_start_;
    cnt = before ? count_ - 1 : count_;
    const uint64_t n = cnt & ((1ull << cluster_) - 1);
    const uint64_t rel = start - cs, end_rel = end - cs;
    x = due_entry(c, n, rel, end_rel);
    // A run outside every due entry is still told apart by the window that
    // holds it (an entry run in a cycle it is not due in).
    const Entry *wx = x;
    for (size_t k = 0; !wx && k < c.entries.size(); ++k) {
        const Entry &y = entries_[c.entries[k]];
        if (rel >= y.start && end_rel <= y.start + y.length + kWindowSlack) wx = &y;
    }
    return wx;
}

void FragmentChecker::switch_run(Chan &c, uint64_t cnt, uint64_t cs, const Entry *wx, bool src_control)
{
    const int entry = wx ? wx->index : -1;
    if (cnt == c.run_cycle && entry == c.run_entry) return;
    end_run(c);
    begin_run(c, cnt, entry, src_control);
    c.run_ws = wx ? cs + wx->start : cs;
    c.run_we = wx ? cs + wx->start + wx->length : cs + cycle_len_;
    c.run_hit = faulted(c.run_ws, c.run_we, false);     // (its first request may have been faulted)
    c.run_blind = faulted(c.run_ws, c.run_we, true);
}

void FragmentChecker::on_fault(uint64_t cycle, bool addressed, int board, uint32_t addr, bool we)
{
    if (!active_ || !started_) return;
    // (a run's window is at most a minor cycle: older faults are not needed)
    while (!faults_.empty() && faults_.front().first + 4 * cycle_len_ + 1024 < cycle) faults_.erase(faults_.begin());
    faults_.emplace_back(cycle, addressed);
    for (auto &kv : chans_) {               // the runs under way whose window holds it
        Chan &r = kv.second;
        if (r.run_entry < -1 || cycle < r.run_ws || cycle > r.run_we) continue;
        r.run_hit = true;
        r.run_blind = r.run_blind || !addressed;
    }
    if (!addressed) return;
    int dest = -1;
    Chan *cp = find(board, addr, dest);
    if (!cp || cp->kind != KIND_COPY || dest < 0) return;
    Chan &c = *cp;
    uint64_t cnt = 0, cs = 0;
    const Entry *x = nullptr;
    const Entry *wx = locate(c, cycle, cycle, cnt, cs, x);
    if (cnt != c.run_cycle || (wx ? wx->index : -1) != c.run_entry) return;   // (a destination access follows a source one)
    // A Slot or Actual store put on the bus (a timeout is seen only here).
    if (we && addr == c.dst[dest].base) c.run_att[dest] = true;
    // K failed attempts of one destination access in a row drop it (for the
    // rest of the value when it goes on).
    if (++c.fail_run >= drop_run_) {
        c.run_dropped[dest] = true;
        c.fail_run = 0;
    }
}

void FragmentChecker::on_bus(const SystemSim::BusEvent &e)
{
    if (!active_ || !e.done || !started_) return;
    int dest = -1;
    Chan *cp = find(e.board, e.addr, dest);
    if (!cp) return;
    Chan &c = *cp;
    cur_ = cp;
    char m[400];
    uint64_t cnt = 0, cs = 0;
    const Entry *x = nullptr;
    const Entry *wx = locate(c, e.start, e.end, cnt, cs, x);
    const uint64_t n = cnt & ((1ull << cluster_) - 1);
    const uint64_t rel = e.start - cs, end_rel = e.end - cs;
    const bool src_control = dest < 0 && e.addr == c.src.base;
    if (!x) {
        if (c.sync && src_control && !e.we) return;   // the SYNC source's poll
        std::string list;
        for (int k : c.entries) {
            const Entry &y = entries_[k];
            char b[120];
            std::snprintf(b, sizeof b, "%s entry %d (due n mod %llu = %u, window %u..%u)", list.empty() ? "" : ",", k,
                          1ull << y.rep, y.base, y.start, y.start + y.length);
            list += b;
        }
        std::snprintf(m, sizeof m, "%s: the controller's %s of board %d addr 0x%03x at clocks %llu..%llu of minor "
                      "cycle %llu (of %llu) lies in no window of an entry of that channel due there:%s",
                      c.name.c_str(), e.we ? "store" : "load", e.board, e.addr, static_cast<unsigned long long>(rel),
                      static_cast<unsigned long long>(end_rel), static_cast<unsigned long long>(n),
                      1ull << cluster_, list.c_str());
        violation(SystemChecker::DUE_CYCLE, m);
    }
    if (c.kind != KIND_COPY) return;
    const int entry = wx ? wx->index : -1;
    switch_run(c, cnt, cs, wx, src_control);
    if (e.ok) c.fail_run = 0;       // (the controller's run of failures ends at any ack)
    if (src_control) {
        if (!c.run_import) {
            std::snprintf(m, sizeof m, "%s: a run going on with value %u (entry %d, minor cycle %llu) accessed the "
                          "source's control word: expected no access to it until the value's last word",
                          c.name.c_str(), c.held_seq, entry, static_cast<unsigned long long>(n));
            violation(SystemChecker::SOURCE_LOCK, m);
        }
        return;
    }
    const uint32_t base = dest < 0 ? c.src.base : c.dst[dest].base;
    const uint32_t size = 4 * (c.w + (dest < 0 ? 0 : 1));
    if (e.addr == base) {   // a destination's control word
        c.run_ctrl[dest] = true;
        if (e.we) c.run_att[dest] = true;   // a Slot or Actual store put on the bus (answered or not)
        if (!e.we || !e.ok) return;
        unsigned buffer = 0;
        if (!c.four && (e.sel & (1u << ALB_OFF_ACTUAL))) buffer = (e.wdata >> (8 * ALB_OFF_ACTUAL)) & 0xFFu;
        if (c.four && (e.sel & 0xCu)) {
            const unsigned pair = (e.sel & 0x8u) ? 1u : 0u;
            buffer = ALB_FS_BUFFER(pair, (e.wdata >> (8 * ALB_OFF_SLOT(pair))) & 1u);
        }
        if (c.four && (e.sel & (1u << ALB_OFF_ACTUAL)) && c.run_words) c.run_pub[dest] = true;
        if (buffer < 1 || buffer > (c.four ? 4u : 3u)) return;
        if (!c.four) c.run_pub[dest] = true;
        const DestBuf &b = c.bufs[dest][buffer];
        uint32_t missing = 0, first = 0;
        for (uint32_t w = c.w + 1; w-- > 0;)
            if (!b.words[w]) ++missing, first = w;
        if (missing) {
            std::snprintf(m, sizeof m, "%s: the controller published Buffer%u at board %d (entry %d, minor cycle "
                          "%llu) with %u of its %u words and taken_at not stored for value %u (first missing: word %u%s): "
                          "expected every word stored before the publication", c.name.c_str(), buffer, e.board, entry,
                          static_cast<unsigned long long>(n), missing, c.w, b.seq, first,
                          first == c.w ? ", taken_at" : "");
            violation(SystemChecker::FRAGMENT_PUBLISH, m);
        }
        return;
    }
    // A buffer word.
    const uint32_t stride = ALB_STRIDE(size), off = e.addr - base - ALB_OFF_BUFFERS;
    const unsigned buffer = 1 + off / stride;
    const uint32_t w = (off % stride) / 4;
    if (dest < 0 && e.we) return;   // (ownership's)
    if (w > c.w || (dest < 0 && w == c.w)) return;
    if (!c.run_words) {
        c.run_words = true;
        if (!c.run_import && c.on == ON_NO) {
            std::snprintf(m, sizeof m, "%s: a run without an Import (entry %d, minor cycle %llu) %s word %u of %u while no "
                          "value goes on: expected an Import", c.name.c_str(), entry, static_cast<unsigned long long>(n),
                          e.we ? "stores" : "loads", w, c.w);
            violation(SystemChecker::FRAGMENT_WORD, m);
        }
    }
    if (dest < 0) {   // a source word load
        if (c.ld_next >= 0 && static_cast<int64_t>(w) != c.ld_next) {
            if (c.ld_max < 0 && !c.run_import)
                std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu goes on with value %u at word %u: "
                              "expected word %u, the first word not yet stored to every destination still in the value (%s)%s",
                              c.name.c_str(), entry, static_cast<unsigned long long>(n), c.held_seq, w, c.prog,
                              dest_list(c, c.in).c_str(), c.on == ON_MAYBE ? ", or an Import" : "");
            else
                std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu loaded word %u of the source: "
                              "expected word %lld (consecutive words from word %u: after an answered load the next word, "
                              "after a failed one the same)", c.name.c_str(), entry, static_cast<unsigned long long>(n), w,
                              static_cast<long long>(c.ld_next), c.run_p0);
            violation(SystemChecker::FRAGMENT_WORD, m);
        }
        c.ld_max = std::max<int64_t>(c.ld_max, w);
        c.ld_next = e.ok ? static_cast<int64_t>(w) + 1 : static_cast<int64_t>(w);
        if (!e.ok) return;
        c.ld_word = w;
        const uint32_t seq = value_word_seq(e.rdata);
        if (c.run_import) {
            if (!c.held_buffer) c.held_buffer = static_cast<int>(buffer), c.held_seq = seq;
        } else if (c.held_buffer && (static_cast<int>(buffer) != c.held_buffer || seq != c.held_seq)) {
            std::snprintf(m, sizeof m, "%s: a run going on with a value (entry %d, minor cycle %llu) loaded word %u of "
                          "value %u from Buffer%u: expected value %u from Buffer%d, the buffer its first run took and holds",
                          c.name.c_str(), entry, static_cast<unsigned long long>(n), w, seq, buffer, c.held_seq, c.held_buffer);
            violation(SystemChecker::SOURCE_LOCK, m);
        }
        return;
    }
    if (w == c.w) {   // taken_at
        if (c.ld_word + 1 != static_cast<int64_t>(c.w)) {
            std::snprintf(m, sizeof m, "%s: taken_at stored at board %d (entry %d, minor cycle %llu) when the run's last "
                          "word loaded is %lld of a value of %u words: expected it after the value's last word only",
                          c.name.c_str(), e.board, entry, static_cast<unsigned long long>(n), static_cast<long long>(c.ld_word), c.w);
            violation(SystemChecker::FRAGMENT_WORD, m);
        }
        if (e.ok) {
            c.run_stored[dest][w] = true;
            c.bufs[dest][buffer].words[w] = true;
        }
        return;
    }
    if (static_cast<int64_t>(w) != c.ld_word) {
        std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu stored word %u at board %d when the word "
                      "it loaded last is %lld: expected each word stored after its load", c.name.c_str(), entry,
                      static_cast<unsigned long long>(n), w, e.board, static_cast<long long>(c.ld_word));
        violation(SystemChecker::FRAGMENT_WORD, m);
    } else if (!c.run_import && (c.on == ON_YES || c.on == ON_MAYBE) && !c.in[dest]) {
        std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu goes on with value %u and stored word %u "
                      "at board %d, a destination no longer in the value (in it: %s)", c.name.c_str(), entry,
                      static_cast<unsigned long long>(n), c.held_seq, w, e.board, dest_list(c, c.in).c_str());
        violation(SystemChecker::FRAGMENT_WORD, m);
    }
    const uint32_t data = e.wdata;
    if (value_word_index(data) != (w & 0xFFFu)) {
        std::snprintf(m, sizeof m, "%s: word %u of value %u stored at word %u of Buffer%u at board %d (entry %d, "
                      "minor cycle %llu): expected each word at its own offset", c.name.c_str(), value_word_index(data),
                      value_word_seq(data), w, buffer, e.board, entry, static_cast<unsigned long long>(n));
        violation(SystemChecker::FRAGMENT_WORD, m);
    }
    if (!e.ok) return;
    c.run_stored[dest][w] = true;
    DestBuf &b = c.bufs[dest][buffer];
    if (b.seq != value_word_seq(data)) {
        b.seq = value_word_seq(data);
        std::fill(b.words.begin(), b.words.end(), false);
    }
    b.words[w] = true;
}

void FragmentChecker::violation(SystemChecker::Kind k, const std::string &m)
{
    chk_.report(k, m);
    ++caught_[std::string(SystemChecker::kind_name(k)) + " " + (cur_ ? cur_->name : "(the cycle starts)")];
}

std::string FragmentChecker::by_channel() const
{
    std::string r;
    for (const auto &kv : caught_) r += (r.empty() ? "" : ", ") + kv.first + " " + std::to_string(kv.second);
    return r;
}

uint64_t FragmentChecker::values_over_runs(const Plan &plan, uint64_t clocks, std::string &why) const
{
    uint64_t total = 0;
    why.clear();
    for (const auto &kv : chans_) {
        const Chan &c = kv.second;
        if (c.kind != KIND_COPY) continue;
        unsigned frag = 0, longest = 0;
        for (int k : c.entries) frag = std::max(frag, entries_[k].frag), longest = std::max(longest, entries_[k].length);
        const uint64_t least = kMinAccessClocks * (1 + c.dst.size()) * c.w;
        if (frag == 0 || least <= longest) continue;
        for (const PlanChannel &pc : plan.channels) {
            if (pc.id != static_cast<int>(c.id) || pc.period == 0) continue;
            const uint64_t n = clocks / pc.period > 0 ? clocks / pc.period - 1 : 0;
            total += n;
            char b[160];
            std::snprintf(b, sizeof b, "%s%s %llu (a value needs over %llu clocks, its longest slot %u; period %llu)",
                          why.empty() ? "" : ", ", c.name.c_str(), static_cast<unsigned long long>(n),
                          static_cast<unsigned long long>(least), longest, static_cast<unsigned long long>(pc.period));
            why += b;
        }
    }
    return total;
}

std::string FragmentChecker::json() const
{
    char b[420];
    std::snprintf(b, sizeof b, "{\"active\": %s, \"cluster\": %u, \"minor_cycles\": %llu, \"runs\": %llu, "
                  "\"later_fragments\": %llu, \"fragmented_publications\": %llu, \"incomplete_runs\": %llu, "
                  "\"cut_fragments\": %llu, \"planned_words_judged\": %llu}",
                  active_ ? "true" : "false", cluster_, static_cast<unsigned long long>(minor_cycles),
                  static_cast<unsigned long long>(runs), static_cast<unsigned long long>(later_fragments),
                  static_cast<unsigned long long>(fragmented_publications), static_cast<unsigned long long>(incomplete_runs),
                  static_cast<unsigned long long>(cut_fragments), static_cast<unsigned long long>(min_judged));
    return b;
}
