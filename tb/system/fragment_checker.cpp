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
            c.frag = x.frag;
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

void FragmentChecker::begin_run(Chan &c, uint64_t cyc, int entry, bool import)
{
    char m[400];
    c.run_cycle = cyc;
    c.run_entry = entry;
    c.run_import = import;
    c.run_words = false;
    c.run_published = 0;
    c.run_s = c.run_e = 0;
    c.run_loaded.assign(c.w, false);
    c.run_stored.assign(c.dst.size(), std::vector<bool>(c.w + 1, false));
    ++runs;
    if (c.kind != KIND_COPY) return;
    if (import && c.known && c.prog > 0) {
        std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu accesses the source's control word "
                      "(an Import) while its value %u is at word %u of %u: the source's lock released between fragments "
                      "(expected the next fragment from the held Buffer%d, no Import)",
                      c.name.c_str(), entry, static_cast<unsigned long long>(cyc & ((1ull << cluster_) - 1)), c.held_seq, c.prog, c.w,
                      c.held_buffer);
        violation(SystemChecker::SOURCE_LOCK, m);
    }
    if (import) {
        c.held_buffer = 0;
        c.held_seq = ~0u;
    }
}

void FragmentChecker::end_run(Chan &c)
{
    if (c.run_entry < -1 || c.kind != KIND_COPY) return;
    if (!c.run_words) {
        // Nothing carried: an Import that found nothing to send (or was cut)
        // leaves no value in progress; a later fragment cut before its first
        // word keeps the progress.
        if (c.run_import) c.known = true, c.prog = 0;
        c.run_entry = -2;
        return;
    }
    bool complete = true;
    for (uint32_t w = c.run_s; w < c.run_e; ++w) {
        complete = complete && c.run_loaded[w];
        for (const auto &st : c.run_stored) complete = complete && st[w];
    }
    const bool last = c.run_e >= c.w;
    if (last) {   // taken_at and the publication at every destination
        for (const auto &st : c.run_stored) complete = complete && st[c.w];
        complete = complete && c.run_published >= c.dst.size();
    }
    if (!c.run_import || c.run_s > 0) ++later_fragments;
    if (last && complete && (c.run_s > 0 || !c.run_import)) ++fragmented_publications;
    if (complete) {
        c.known = true;
        c.prog = last ? 0 : c.run_e;
    } else {
        ++incomplete_runs;
        if (c.frag && c.frag < c.w) ++cut_fragments;
        c.known = false;
        c.prev_s = c.run_s;
        c.prev_e = c.run_e;
    }
    c.run_entry = -2;
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
    // The minor cycle the access began in.
    const bool before = e.start < cycle_start_ && count_ > 0;
    const uint64_t cs = before ? prev_start_ : cycle_start_, cnt = before ? count_ - 1 : count_;
    const uint64_t n = cnt & ((1ull << cluster_) - 1);
    const uint64_t rel = e.start - cs, end_rel = e.end - cs;
    const Entry *x = due_entry(c, n, rel, end_rel);
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
    // A run outside every due entry is still told apart by the window that
    // holds it (an entry run in a cycle it is not due in).
    const Entry *wx = x;
    for (size_t k = 0; !wx && k < c.entries.size(); ++k) {
        const Entry &y = entries_[c.entries[k]];
        if (rel >= y.start && end_rel <= y.start + y.length + kWindowSlack) wx = &y;
    }
    const int entry = wx ? wx->index : -1;
    if (cnt != c.run_cycle || entry != c.run_entry) {
        end_run(c);
        begin_run(c, cnt, entry, src_control);
    }
    const uint32_t frag = wx ? wx->frag : c.frag;
    if (src_control) {
        if (!c.run_import) {
            std::snprintf(m, sizeof m, "%s: a later fragment's run (entry %d, minor cycle %llu) accessed the "
                          "source's control word: expected no access to it until the value's last fragment",
                          c.name.c_str(), entry, static_cast<unsigned long long>(n));
            violation(SystemChecker::SOURCE_LOCK, m);
        }
        return;
    }
    const uint32_t base = dest < 0 ? c.src.base : c.dst[dest].base;
    const uint32_t size = 4 * (c.w + (dest < 0 ? 0 : 1));
    if (e.addr == base) {   // a destination's control word
        if (!e.we || !e.ok) return;
        unsigned buffer = 0;
        if (!c.four && (e.sel & (1u << ALB_OFF_ACTUAL))) buffer = (e.wdata >> (8 * ALB_OFF_ACTUAL)) & 0xFFu;
        if (c.four && (e.sel & 0xCu)) {
            const unsigned pair = (e.sel & 0x8u) ? 1u : 0u;
            buffer = ALB_FS_BUFFER(pair, (e.wdata >> (8 * ALB_OFF_SLOT(pair))) & 1u);
        }
        if (c.four && (e.sel & (1u << ALB_OFF_ACTUAL)) && c.run_words) ++c.run_published;
        if (buffer < 1 || buffer > (c.four ? 4u : 3u)) return;
        if (!c.four) ++c.run_published;
        const DestBuf &b = c.bufs[dest][buffer];
        uint32_t missing = 0, first = 0;
        for (uint32_t w = c.w + 1; w-- > 0;)
            if (!b.words[w]) ++missing, first = w;
        if (missing) {
            std::snprintf(m, sizeof m, "%s: the controller published Buffer%u at board %d (entry %d, minor cycle "
                          "%llu) with %u of its %u words and taken_at not stored for value %u (first missing: word %u%s): "
                          "expected every fragment stored before the publication", c.name.c_str(), buffer, e.board, entry,
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
        uint32_t s = c.run_import ? 0 : w;
        if (!c.run_import) {
            const bool aligned = frag == 0 ? s == 0 : s % frag == 0;
            const bool expected = c.known ? (c.prog > 0 && s == c.prog)
                                          : ((s == c.prev_s && s > 0) || (s == c.prev_e && s < c.w));
            if (!aligned || !expected) {
                char want[80];
                if (c.known && c.prog == 0) std::snprintf(want, sizeof want, "an Import (no value in progress)");
                else if (c.known) std::snprintf(want, sizeof want, "word %u", c.prog);
                else std::snprintf(want, sizeof want, "word %u or %u (the previous run was cut)", c.prev_s, c.prev_e);
                std::snprintf(m, sizeof m, "%s: a fragment (entry %d, minor cycle %llu, no Import) starts at word %u "
                              "of %u (fragments of %u words): expected %s", c.name.c_str(), entry, static_cast<unsigned long long>(n),
                              s, c.w, frag, want);
                violation(SystemChecker::FRAGMENT_WORD, m);
            }
        }
        c.run_s = s;
        c.run_e = frag == 0 ? c.w : std::min(s + frag, c.w);
    }
    if (w == c.w) {   // taken_at
        if (c.run_e < c.w) {
            std::snprintf(m, sizeof m, "%s: taken_at stored at board %d in a fragment [%u, %u) of a value of %u words "
                          "(entry %d, minor cycle %llu): expected it with the last fragment only", c.name.c_str(), e.board, c.run_s,
                          c.run_e, c.w, entry, static_cast<unsigned long long>(n));
            violation(SystemChecker::FRAGMENT_WORD, m);
        }
        if (e.ok) {
            c.run_stored[dest][w] = true;
            c.bufs[dest][buffer].words[w] = true;
        }
        return;
    }
    if (w < c.run_s || w >= c.run_e) {
        std::snprintf(m, sizeof m, "%s: the run of entry %d in minor cycle %llu carries words [%u, %u), yet %s word %u "
                      "at board %d", c.name.c_str(), entry, static_cast<unsigned long long>(n), c.run_s, c.run_e,
                      e.we ? "stored" : "loaded", w, e.board);
        violation(SystemChecker::FRAGMENT_WORD, m);
    }
    if (!e.ok) return;
    const uint32_t data = e.we ? e.wdata : e.rdata;
    if (dest < 0) {
        c.run_loaded[w] = true;
        const uint32_t seq = value_word_seq(data);
        if (c.run_import) {
            if (!c.held_buffer) c.held_buffer = static_cast<int>(buffer), c.held_seq = seq;
        } else if (c.held_buffer && (static_cast<int>(buffer) != c.held_buffer || seq != c.held_seq)) {
            std::snprintf(m, sizeof m, "%s: a later fragment (entry %d, minor cycle %llu) loaded word %u of value %u "
                          "from Buffer%u: expected value %u from Buffer%d, the buffer its first fragment took and holds",
                          c.name.c_str(), entry, static_cast<unsigned long long>(n), w, seq, buffer, c.held_seq, c.held_buffer);
            violation(SystemChecker::SOURCE_LOCK, m);
        }
        return;
    }
    if (value_word_index(data) != (w & 0xFFFu)) {
        std::snprintf(m, sizeof m, "%s: word %u of value %u stored at word %u of Buffer%u at board %d (entry %d, "
                      "minor cycle %llu): expected each word at its own offset", c.name.c_str(), value_word_index(data),
                      value_word_seq(data), w, buffer, e.board, entry, static_cast<unsigned long long>(n));
        violation(SystemChecker::FRAGMENT_WORD, m);
    }
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

std::string FragmentChecker::json() const
{
    char b[340];
    std::snprintf(b, sizeof b, "{\"active\": %s, \"cluster\": %u, \"minor_cycles\": %llu, \"runs\": %llu, "
                  "\"later_fragments\": %llu, \"fragmented_publications\": %llu, \"incomplete_runs\": %llu, "
                  "\"cut_fragments\": %llu}",
                  active_ ? "true" : "false", cluster_, static_cast<unsigned long long>(minor_cycles),
                  static_cast<unsigned long long>(runs), static_cast<unsigned long long>(later_fragments),
                  static_cast<unsigned long long>(fragmented_publications), static_cast<unsigned long long>(incomplete_runs),
                  static_cast<unsigned long long>(cut_fragments));
    return b;
}
