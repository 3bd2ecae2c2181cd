// system_checker.h -- the paper's proof points end to end, across boards.
//
// On every RAM, for every channel instance (a source, where the board's CPU
// produces and the controller consumes, or a destination, where the
// controller produces and the CPU consumes):
//   mutual exclusion  the producer never writes a buffer while the consumer
//                     reads it (first to last read of one buffer);
//   ownership         the producer writes only Actual and buffers (and, in a
//                     four-slot instance, the Slot bytes 2 and 3), the
//                     consumer only ReadLocked; the controller touches
//                     nothing outside a channel (a four-slot instance has
//                     four buffers).
// A four-slot destination's value counts as there from its Slot store
// (complete: a four-slot Import may return it, docs/four_slot.md), as
// published from its Actual store: actuality is judged against the values
// published when an Import began (its first control-word load).
// End to end, for every channel:
//   definite results  every value the controller publishes is one complete
//                     value its producer exported (or, for TIME, the time),
//                     taken after the producer published it (a four-slot
//                     source: completed it, at its Slot store); every value a
//                     consumer imports is one complete value the controller
//                     published there;
//   taken_at          exactness: every value the controller publishes is the
//                     value of its source's last take, and carries as
//                     taken_at the controller's time_o in the ack clock of
//                     that take's final load of the source Actual.  A take
//                     is seen on the controller's bus (acked accesses only,
//                     as the controller sees them, on_bus): a load of the
//                     source's Actual, after an acked store of its
//                     ReadLocked since the previous such load, that returns
//                     the index stored (four-slot: the control-word load
//                     after the ReadLocked store);
//   landed stores     an Actual store the RAM performed counts as published
//                     even when its answer was lost (fault kinds 1 and 3):
//                     the same value published there again is reported
//                     as such (duplicate_new);
//   new twice         at the consumer: an Import never returns New for a
//                     source value this consumer already got as New (or an
//                     older one) -- what a republished landed store would do;
//   actuality         a destination never gets an older or the same value
//                     again (so redundancy never makes one value New twice);
//                     a consumer never goes back, and New exactly when newer;
//   latency           producer's publication -> a value at least as new
//                     published at each destination, against the compiler's
//                     bound (a violation only where the run claims no fault),
//                     measured when such a value is published there;
//   freshness         (the paper's actuality, at the destinations) a source
//                     value that stays its source's newest for longer than
//                     the channel's bound (no later Actual store by then)
//                     has been published at each destination (its Actual
//                     store; it or a newer value) within that bound; judged
//                     in the clock the bound runs out (tick), so a value
//                     withheld for good is seen too: the last value of a
//                     producer that stops (fault-free runs, like latency;
//                     a schedule mode without the channel: not judged);
//   ages              consumers age every value with taken_at.
// On the controller's bus, from the ROM image (tb/system/fragment_checker.h):
//   due_cycle, fragment_publish, source_lock, fragment_word (multi-rate
//   schedules and values carried in fragments).
#pragma once
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>
#include "plan.h"
#include "system_sim.h"
extern "C" {
#include "albatross_layout.h"
}

// The bytes of one instance of channel c with payload size bytes: 4 + 3*S,
// or 4 + 4*S for the four-slot kind.
inline uint32_t instance_bytes(const PlanChannel &c, uint32_t size)
{
    return c.four_slot ? ALB_FS_CHANNEL_BYTES(size) : ALB_CHANNEL_BYTES(size);
}

// The value a producer exports as its seq-th value of channel id: word i
// (32-bit, little-endian) is value_word(id, seq, i), so every word names its
// value and its place (fragment_checker.h); a last partial word keeps the
// low bytes of its tag.
inline uint32_t value_word(int channel_id, uint64_t seq, uint32_t i)
{
    return static_cast<uint32_t>(seq & 0xFFFFu) << 16 | (static_cast<uint32_t>(channel_id) & 0xFu) << 12 | (i & 0xFFFu);
}
inline uint32_t value_word_seq(uint32_t w) { return w >> 16; }        // seq mod 2^16
inline uint32_t value_word_index(uint32_t w) { return w & 0xFFFu; }   // i mod 2^12
void channel_value(int channel_id, uint64_t seq, uint8_t *out, uint32_t size);

class SystemChecker : public SystemObserver {
public:
    enum Kind { MUTEX, DEFINITE, ACTUALITY, DUPLICATE, LATENCY, OWNERSHIP, IN_CHANNEL, DRIVER_ERROR, TIME, TAKEN_AT,
                NEW_TWICE, FRESHNESS, DUE_CYCLE, FRAGMENT_PUBLISH, SOURCE_LOCK, FRAGMENT_WORD, KINDS };
    static const char *kind_name(int k);

    SystemChecker(const Plan &plan, SystemSim &sim, uint64_t time_offset);
    void on_access(int board, const Access &a) override;
    // Every access the controller saw answered (ack or err), after the tick.
    void on_bus(const SystemSim::BusEvent &e);

    // From the CPU programs.
    void exported(int channel, uint64_t seq);                 // after alb_export returned
    // After alb_import returned on a destination: payload = value + taken_at.
    void imported(int channel, int dest, int rc, const uint8_t *payload, uint64_t begin, uint64_t end,
                  uint32_t consumer_time);
    void set_latency_is_checked(bool on) { latency_checked_ = on; }
    // Schedule modes: the bounds (fault-free, with retries) of channel chan for
    // a value from cycle 'from' (a copy's publication; a time/status value's
    // take) measured at cycle 'to'; false: not judged (system_modes.h).
    // Without it every value is judged by the plan's bounds.
    using BoundFn = std::function<bool(int chan, uint64_t from, uint64_t to, uint64_t &bound, uint64_t &bound_retry)>;
    void set_bound_fn(BoundFn f) { bound_fn_ = std::move(f); }
    // Every take the controller makes of a copy source (a New Import: its
    // buffer, and time_o in the ack clock of its final control load).
    using TakeFn = std::function<void(int chan, uint8_t buffer, uint32_t time)>;
    void set_take_fn(TakeFn f) { take_fn_ = std::move(f); }
    // Values published before this cycle are not measured (the controller's
    // first cycle after reset follows its scan of the ROM).
    void set_latency_from(uint64_t cycle) { latency_from_ = cycle; }
    uint64_t latency_from() const { return latency_from_; }
    // Every measured latency (copy) or age (time, status) is also written
    // to f as "channel,board,cycle,age" (tb_system --ages; the fault-rate
    // check tools/fault_rates.py compares their distribution with the
    // compiler's probabilistic bounds).
    void set_ages_file(std::FILE *f) { ages_ = f; }
    void end_of_run();                                         // close open read windows
    // Every clock, after the model's tick: the freshness deadlines due now.
    void tick(uint64_t cycle);

    uint64_t violations[KINDS] = {};
    std::string first_message[KINDS];
    uint64_t total() const;
    // A violation found by a checker outside this class (fragment_checker.h).
    void report(Kind k, const std::string &msg) { violation(k, msg); }

    struct DestStats {
        uint64_t publications = 0, imports = 0, imports_new = 0;
        uint64_t latency_max = 0, latency_sum = 0, latency_n = 0, latency_over = 0;
        uint64_t latency_skipped = 0;                       // of latency_n: values skipped (never published
                                                            // here), measured at a newer one's publication
        uint64_t over_retry_bound = 0;                      // beyond the with-retries bound too
        uint64_t max_age_seen = 0, last_age_seen = 0;       // by the consumer, via taken_at
        uint64_t max_taken_minus_publish = 0;               // time/position correlation
        uint64_t landed_unanswered = 0;                     // Actual stores performed, answer lost (err or
                                                            // none), seen at the next store
        uint64_t landed_same_later = 0;                     // a take of the value this destination holds
                                                            // from a landed, unanswered store (a later slot
                                                            // carrying the same source value)
        uint64_t landed_same_read = 0;                      // ... whose consumer had already read it New
        uint64_t max_overtakes = 0;                         // most publications here during one Import
        uint64_t late_publications = 0;                     // four-slot: an Actual store that publishes a value
                                                            // completed before the controller's last load of the
                                                            // control word (its Slot store landed in an earlier slot)
        uint64_t imports_overtaken4 = 0;                    // Imports overtaken by 4 or more publications
        uint64_t fresh_judged = 0;                          // source values newest for longer than the bound
        uint64_t fresh_late = 0;                            // ... not published here within it
    };
    struct ChannelStats {
        uint64_t exports = 0;
        uint64_t exports_overtaken = 0;                     // Exports during which the controller stored the
                                                            // source's ReadLocked (a take overtook them)
        std::vector<DestStats> dests;
    };
    std::vector<ChannelStats> stats;                          // by plan channel index
    uint64_t controller_accesses_outside = 0;

private:
    struct Instance {
        int chan = 0;          // index into plan.channels
        int dest = -1;         // -1: the source instance
        int board = 0;
        uint32_t base = 0, size = 0;
        int producer_port = 0; // 0: CPU, 1: controller
        // Consumer's open read window.
        int win_buffer = 0;
        uint64_t win_first = 0, win_last = 0;
        bool four_slot = false;
        std::vector<uint64_t> writes[5];   // producer writes per buffer (1..4)
    };
    struct DestPub {
        uint64_t cycle, seq;               // cycle: complete (three-buffer: published)
        uint64_t pub_cycle = 0;            // its Actual store (~0: not yet)
        uint8_t buffer = 0;                // the buffer that holds it
        uint32_t taken_at;
        std::vector<uint8_t> bytes;        // the published payload
    };
    struct DestState {
        std::vector<DestPub> pubs;         // pubs[0]: the RAM image
        uint64_t pending = 0;              // first source seq not yet reached at this dest
        int64_t last_read = 0;             // consumer: index of the last pub read
        uint8_t actual = 0;                // the destination's Actual, as last stored
                                           // (four-slot: the buffer last completed)
        uint64_t new_seq = ~0ull;          // consumer: the source value of its last New read (copy
                                           // channels, publications after the image; ~0: none)
        bool unanswered = false;           // the last Actual store was performed, its ack not seen
        bool loaded = false;               // four-slot: a controller control load since its last Slot store
        uint64_t unanswered_cycle = 0;     // ... performed at this cycle
        uint64_t reached = 0;              // copy: the newest source value published here (Actual store)
        uint64_t fresh_seq = 0;            // freshness: the source value judged next ...
        uint64_t fresh_due = 0;            // ... in no clock before this one
        bool fresh_done = true;            // ... or judged already
    };
    struct SourceState {
        std::vector<uint64_t> publish_cycle;   // by seq (0: the image)
        uint64_t pending_publish = 0;          // edge of the CPU's last Actual store
        std::vector<uint64_t> complete_cycle;  // by seq: complete, may be taken from here (the
        uint64_t pending_complete = 0;         // Actual store; four-slot: the Slot store before it)
        int rl_stored = -1;                    // acked ReadLocked store since the last Actual load
        bool taken = false;                    // a take has been seen:
        uint64_t take_seq = 0, take_cycle = 0; // the value it read, its final Actual load's ack
        uint32_t take_time = 0;                // ... and time_o then
        bool exporting = false;                // the producer's Export runs (its control load .. Actual store)
        bool overtaken = false;                // ... and a ReadLocked store came during it
    };

    void violation(Kind k, const std::string &msg);
    Instance *find(int board, uint32_t addr);
    void close_window(Instance &in);
    void dest_published(Instance &in, uint64_t cycle, uint8_t buffer);
    void dest_actual_stored(Instance &in, uint64_t cycle, uint8_t buffer);   // four-slot
    void measure(Instance &in, const DestPub &p, const DestPub &prev, bool prev_is_image, uint64_t cycle);
    // The seq of the value in buffer b of channel c's source, or -1.
    int64_t source_seq(int chan, uint8_t b);

    const Plan &plan_;
    SystemSim &sim_;
    uint64_t time_offset_;             // cycle = controller time + time_offset
    bool latency_checked_ = true;
    BoundFn bound_fn_;
    TakeFn take_fn_;
    uint64_t latency_from_ = ~0ull;
    std::FILE *ages_ = nullptr;
    std::vector<Instance> inst_;
    std::vector<SourceState> src_;
    std::vector<std::vector<DestState>> dst_;
    std::vector<uint8_t> scratch_;
};
