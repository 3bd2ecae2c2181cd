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
//                     value (the words' tags): never after a first fragment;
//   source_lock       from a value's first fragment (a run with the Import,
//                     its ReadLocked store) to its last, no run touches the
//                     source's control word (no ReadLocked store, no new
//                     Import), and every later fragment loads its words from
//                     the buffer fragment 0 loaded, holding the same value
//                     (the words' tags);
//   fragment_word     each run carries one fragment: words [s, min(s + frag,
//                     W)) with s a multiple of frag (E7.frag; 0: the whole
//                     value); a run with an Import starts at word 0; a run
//                     without one continues the value in progress at its next
//                     fragment (the word after the previous run's fragment,
//                     or the previous run's first word when that run was cut:
//                     a word load or store missing its ack); each word goes to
//                     the destination offset it came from (its tag's index);
//                     taken_at only with the last fragment.
// A run is "complete" when every word of its fragment was loaded from the
// source and stored at every destination with an ack.  After a run that is
// not (a fault cut it, a destination was dropped), the checker does not know
// whether the controller counts the fragment as done: it accepts either the
// same fragment again, the next one, or a fresh Import, until the next run
// with an Import resets what it knows.  Fault-free, every run is complete
// and every check is exact.
// Not judged: images with modes (a switch clears the progress; each mode has
// its own cluster), the SYNC source's polls (outside any slot).
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
    // Figures for the report: runs seen, fragments carried, values published
    // in more than one fragment, minor cycles counted.
    uint64_t runs = 0, later_fragments = 0, fragmented_publications = 0, minor_cycles = 0, incomplete_runs = 0;
    uint64_t cut_fragments = 0;          // incomplete runs of a channel whose values go in two or more fragments
    std::string json() const;
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
    struct Chan {
        unsigned id = 0, w = 0, kind = 0, frag = 0;   // frag: its first entry's E7.frag
        std::string name;
        bool four = false, sync = false;
        Place src{-1, 0};
        std::vector<Place> dst;
        std::vector<int> entries;        // indexes into entries_
        // the value in progress
        bool known = true;               // the checker knows the progress exactly
        uint32_t prog = 0;               // next word (0: no value in progress)
        uint32_t prev_s = 0, prev_e = 0; // the previous run's fragment (when !known)
        int held_buffer = 0;             // the source buffer fragment 0 loaded from
        uint32_t held_seq = ~0u;         // ... and its value's tag seq
        // the current run
        uint64_t run_cycle = ~0ull;      // minor cycle count (absolute) and entry of the run
        int run_entry = -2;              // (-2: no run yet; -1: a run in no due entry's window)
        bool run_import = false, run_words = false;
        size_t run_published = 0;        // acked publishing stores (three-buffer Actual; four-slot Actual)
        uint32_t run_s = 0, run_e = 0;   // its fragment [s, e)
        std::vector<bool> run_loaded;    // acked source loads, by word
        std::vector<std::vector<bool>> run_stored;  // acked stores, by destination and word
        std::vector<std::vector<DestBuf>> bufs;     // by destination, buffer 1..4
    };

    void violation(SystemChecker::Kind k, const std::string &m);
    Chan *find(int board, uint32_t addr, int &dest);
    uint32_t inst_bytes(const Chan &c, bool dest) const;
    void end_run(Chan &c);
    void begin_run(Chan &c, uint64_t cyc, int entry, bool import);
    const Entry *due_entry(const Chan &c, uint64_t n, uint64_t rel, uint64_t end_rel) const;

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
};
