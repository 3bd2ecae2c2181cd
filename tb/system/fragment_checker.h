// fragment_checker.h -- multi-rate schedules and fragments, judged on the
// controller's bus against the schedule ROM image (docs/controller.md
// "Fragments", rtl/albatross_contract.toml E6, E7).
//
// It reads the image itself (entries, E1 start, E2 length, E6 rep/base, E7
// frag, places) and counts the minor cycles from the controller's cycle
// starts (the probe cycle_o of tb/system/tb_system.v): the first cycle after
// start-up has n = 0, n wraps at 2^H2.cluster.  Every access the controller
// makes on its bus is given to the run it belongs to: the entry of its
// channel id that is due in that minor cycle and whose window [S, S + E2]
// (S = cycle start + E1) holds the access (a time-rigid image's cycle starts
// must be H1 apart: due_cycle too).  Four named checks
// (SystemChecker kinds):
//   due_cycle         every access to a channel's instance lies in the window
//                     of an entry of that channel that is due in that minor
//                     cycle (n mod 2^rep = base): an entry run in a wrong
//                     cycle, or with a repetition read one bit short (twice
//                     as many cycles), is seen at its first wrong run;
//   fragment_publish  a destination's buffer is published (three-buffer:
//                     the Actual store; four-slot: the Slot store that
//                     completes it) only when every word of the value and
//                     taken_at have been stored into that buffer, all of one
//                     value (the words' tags): nothing is published before
//                     the value's last word (a run cut off in the
//                     publication may have published some destinations; the
//                     value goes on for the others only, from word W - 1);
//   source_lock       from a value's first run (the one with the Import, its
//                     ReadLocked store) to its last, no run touches the
//                     source's control word (no ReadLocked store, no new
//                     Import), and every run that goes on with the value
//                     loads its words from the buffer the first run loaded,
//                     holding the same value (the words' tags);
//   fragment_word     a run loads consecutive words of the source buffer
//                     (a failed load again, else the next): from word 0 in a
//                     run with an Import, from p in a run that goes on with
//                     a value (p below); it stores only the word it loaded
//                     last, to its own offset (its tag's index), and, going
//                     on with a value, only to the destinations still in it
//                     (not dropped, not published); taken_at only after the
//                     value's last word (in any run that loaded it: one that
//                     goes on from W - 1 too); a run without an Import only
//                     while a value goes on; and a run of an entry with
//                     E7.frag = F != 0 that no
//                     fault hit stores at least F words to every destination
//                     still in the value, unless the value ends first (the
//                     compiler plans each run for at least F words under its
//                     fault hypothesis; judged in every run with no faulted
//                     access in its window, so in every run of a fault-free
//                     scenario).
// The value in progress, as the controller keeps it (rtl/albatross_transfer.v
// "Values over several runs"), is derived from what the checker saw: a run
// stores words until the value's last or until its deadline; a destination
// is out of the value once one of its accesses failed K = H2.drop_run times
// in a row (tb_system gives the checker every faulted request, on_fault,
// timeouts included) or once it is published (its Actual store acked).
// After a run: live, the destinations still in the value and not published;
// safe, none of them had a Slot or Actual store put on the bus in the run
// (answered or not: a begun one may have landed, which only a fresh
// Import's control load can tell); a word is counted when it is not the
// value's last (W - 1) and the run stored it to every destination still in
// the value (or dropped them).  The value goes on iff live is not empty,
// safe, and the run went on with it or its entry has E7.frag != 0 and a
// word was counted; its progress p is then 1 + the last word counted in the
// run (unchanged if none was), so a value cut off in its publication (after
// its last word, before a Slot or Actual store for a destination not
// published) goes on from word W - 1: the next run loads it, stores it,
// taken_at, and publishes.  Else the value ends and the next run Imports
// afresh.  Where a first run stored word 0 and nothing after it, without
// storing it to every destination it had loaded the control word of, the
// checker cannot tell whether word 0's stores ended (a destination whose
// earlier store landed leaves silently): it accepts an Import, or a run
// going on from the p that those stores give.  A faulted access whose
// address the checker is not told (a dead board) leaves the progress
// unknown until the next Import (no judgement of where runs start, or of
// Imports, until then).
// Not judged: images with modes (each mode has its own cluster), the SYNC
// source's polls (outside any slot).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>
#include "system_checker.h"
#include "system_sim.h"

class FragmentChecker {
public:
    // rom: the image file the controller runs ($readmemh words).
    // plan: for the channels' names in messages.
    FragmentChecker(const std::string &rom, const Plan &plan, SystemChecker &chk);
    bool active() const { return active_; }
    const std::string &why_inactive() const { return why_; }
    // After every tick: cycle_start = the probe (a minor cycle starts now).
    void tick(uint64_t cycle, bool cycle_start);
    // Every access the controller saw answered (ok or not).
    void on_bus(const SystemSim::BusEvent &e);
    // A request of the controller that the injector faulted (any kind, a
    // timeout too: on_bus never sees one), begun at clock cycle, a store if
    // we; addressed false: to a dead board, address not known.  Call after
    // on_bus for the same clock.
    void on_fault(uint64_t cycle, bool addressed, int board, uint32_t addr, bool we);
    // Figures for the report: runs seen, runs that went on with a value,
    // values published after two or more runs, minor cycles counted, runs
    // a fault hit.
    uint64_t runs = 0, later_fragments = 0, fragmented_publications = 0, minor_cycles = 0, incomplete_runs = 0;
    uint64_t cut_fragments = 0;          // runs of E7.frag != 0 entries that faults cut short: fewer than their
                                         // planned words and the value not ended, or a destination dropped
    uint64_t min_judged = 0;             // runs whose planned words (E7.frag) were judged (no fault hit them)
    std::string json() const;
    // The values the plan guarantees to publish in `clocks` clocks that must
    // go over two or more runs: for every channel with an entry of E7.frag
    // != 0 whose whole value cannot go in its longest slot (one source load
    // and a store per destination for each word, kMinAccessClocks each, more
    // than E2), floor(clocks / its guaranteed period) - 1 (the plan's
    // period, within its fault hypothesis; one lost to the start-up).  why:
    // the channels and counts.
    uint64_t values_over_runs(const Plan &plan, uint64_t clocks, std::string &why) const;
    // The violations of the four checks by channel: "check channel count, ..." ("" if none).
    std::string by_channel() const;

private:
    struct Entry {
        int index = 0;
        unsigned kind = 0, flags = 0, id = 0, nd = 0, w = 0, start = 0, length = 0, rep = 0, base = 0, frag = 0;
    };
    struct Place { int board; uint32_t base; };
    struct DestBuf {                     // what the controller stored into one buffer of a destination
        uint32_t seq = ~0u;              // the value whose words it holds (tag seq)
        std::vector<bool> words;         // words 0..W-1 stored, and taken_at (index W)
    };
    // Whether a value goes on after the last run: no; yes (in, prog exact);
    // maybe (an Import, or going on from prog to in); unknown (a fault at an
    // address not told: nothing judged until the next Import).
    enum On { ON_NO, ON_YES, ON_MAYBE, ON_UNKNOWN };
    struct Chan {
        unsigned id = 0, w = 0, kind = 0;
        std::string name;
        bool four = false, sync = false;
        Place src{-1, 0};
        std::vector<Place> dst;
        std::vector<int> entries;        // indexes into entries_
        // the value in progress
        On on = ON_NO;
        uint32_t prog = 0;               // p: the first word not yet stored to every destination in it
        std::vector<bool> in;            // the destinations still in it
        unsigned value_runs = 0;         // runs that carried it so far
        int held_buffer = 0;             // the source buffer its first run loaded from
        uint32_t held_seq = ~0u;         // ... and its value's tag seq
        // the current run
        uint64_t run_cycle = ~0ull;      // minor cycle count (absolute) and entry of the run
        int run_entry = -2;              // (-2: no run yet; -1: a run in no due entry's window)
        unsigned run_frag = 0;           // its entry's E7.frag
        uint64_t run_ws = 0, run_we = 0; // its window [S, S + E2] in clocks
        bool run_hit = false;            // a faulted request began in its window
        bool run_blind = false;          // ... one whose address the checker was not told
        bool run_import = false, run_words = false;
        uint32_t run_p0 = 0;             // its first word (0, or p going on)
        int64_t ld_next = -1;            // the word its next source load must be (-1: not known)
        int64_t ld_word = -1;            // the word its last acked source load took (-1: none)
        int64_t ld_max = -1;             // the highest word it began to load
        unsigned fail_run = 0;           // faulted destination accesses in a row
        std::vector<bool> run_ctrl;      // destinations whose control word it accessed
        std::vector<bool> run_dropped;   // destinations dropped (K failures in a row)
        std::vector<bool> run_pub;       // destinations whose publishing store was acked
        std::vector<bool> run_att;       // destinations with a Slot or Actual store put on the bus
        std::vector<std::vector<bool>> run_stored;  // acked word stores, by destination and word
        std::vector<std::vector<DestBuf>> bufs;     // by destination, buffer 1..4
    };

    void violation(SystemChecker::Kind k, const std::string &m);
    Chan *find(int board, uint32_t addr, int &dest);
    uint32_t inst_bytes(const Chan &c, bool dest) const;
    void end_run(Chan &c);
    void begin_run(Chan &c, uint64_t cyc, int entry, bool import);
    const Entry *due_entry(const Chan &c, uint64_t n, uint64_t rel, uint64_t end_rel) const;
    // The run an access begun at start and ended at end belongs to: minor
    // cycle count cnt (n = cnt mod 2^cluster), the due entry x (or null),
    // the entry whose window holds it (or null), the cycle's start cs.
    const Entry *locate(const Chan &c, uint64_t start, uint64_t end, uint64_t &cnt, uint64_t &cs, const Entry *&x) const;
    void switch_run(Chan &c, uint64_t cnt, uint64_t cs, const Entry *wx, bool src_control);
    uint32_t first_missing(const Chan &c, size_t d, uint32_t from) const;   // in the current run
    std::string dest_list(const Chan &c, const std::vector<bool> &set) const;
    bool faulted(uint64_t from, uint64_t to, bool unaddressed_only) const;

    SystemChecker &chk_;
    std::map<std::string, uint64_t> caught_;   // "check channel" -> violations
    const Chan *cur_ = nullptr;                // the channel on_bus judges
    bool active_ = false;
    std::string why_;
    std::vector<Entry> entries_;
    std::map<unsigned, Chan> chans_;     // by channel id
    unsigned cluster_ = 0;
    bool rigid_ = true;                  // time-rigid: every minor cycle is H1 long
    uint64_t cycle_len_ = 0;
    bool started_ = false;
    uint64_t cycle_start_ = 0;           // the edge of the running minor cycle's start
    uint64_t prev_start_ = 0;            // ... and of the one before
    uint64_t count_ = 0;                 // its count since start-up (n = count mod 2^cluster)
    unsigned drop_run_ = 2;              // K (H2.drop_run; below 2: 2)
    std::vector<std::pair<uint64_t, bool>> faults_;   // recent faulted requests: clock, address told
};
