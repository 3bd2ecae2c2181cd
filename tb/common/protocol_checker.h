// protocol_checker.h -- the paper's four proof points (its section 3.1), checked on
// every Import of one channel from what happens at the RAM ports:
//   mutual exclusion  the producer never writes a byte of the buffer the
//                     consumer is reading (between its first and last
//                     payload read), and an Import reads one buffer only;
//   definite results  each value returned is exactly one complete exported
//                     value, published before the consumer's last load of
//                     Actual: never torn, never unpublished;
//   actuality         never older than the newest value published when the
//                     Import began, never older than the previous one, New
//                     exactly when newer than the last one read;
//   termination       Export takes exactly 2 + payload words accesses;
//                     Import's loop iterations and accesses are recorded
//                     against the writer/reader speed ratio (it is
//                     lock-free, not wait-free), and bounded by a caller's
//                     limit where one applies (a crashed partner).
// Plus: each side writes only what it owns, and the driver reports no error
// while the control bytes are valid.
//
// The four-slot kind (kind = ALB_FOUR_SLOT, docs/four_slot.md) is checked the
// same way, with these differences: four buffers; the producer owns Actual
// and the slot bytes; a value is complete at its Slot store (definite: the
// value returned was complete before the consumer's last control-word load)
// and published at its Actual store (actuality: not older than the newest
// published when the Import began); Export takes exactly 3 + W accesses,
// and every Import exactly 1 + W or 3 + W (wait-free: termination names the
// count otherwise).  An Export without a Slot store on a four-slot channel
// is named as a kind mismatch (a three-buffer producer).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>
#include "ram_bus.h"

// The exported values: every byte depends on the sequence number, and the
// first word holds it, so a mix of two values is never a value.
void make_value(uint64_t seq, uint8_t *out, uint32_t size);

class ProtocolChecker : public AccessObserver {
public:
    enum Kind { MUTEX, DEFINITE, ACTUALITY, TERMINATION, OWNERSHIP, DRIVER_ERROR, KINDS };
    static const char *kind_name(int k);

    ProtocolChecker(uint32_t base, uint32_t size, int producer_port, int consumer_port, int kind = 0);
    int kind() const { return kind_; }

    // The bytes of the seq-th exported value (make_value unless a bench's
    // producer exports other values, e.g. the pair test's sequence number
    // and check words: tb/endpoint/).
    typedef void (*ValueFn)(uint64_t seq, uint8_t *out, uint32_t size);
    ValueFn value_fn = make_value;

    void on_access(const Access &a) override;

    // Called by the programs on the simulated CPUs.
    void export_begin(uint64_t seq);
    void export_end(int rc);
    void import_begin(uint64_t now, int log_ratio_bucket);
    void import_end(int rc, const uint8_t *value, uint64_t now);
    void producer_restarted();   // its unfinished Export is abandoned
    void consumer_restarted();   // its memory of the last value is gone
    // From now on every Import that begins must finish within this many loop
    // iterations (a frozen producer: 1).  -1: no limit, lifted at once also
    // for the Import under way (the producer is back).
    void set_import_iteration_limit(int limit) {
        iteration_limit_ = limit;
        if (limit < 0) imp_limit_ = -1;
    }

    // Results.
    uint64_t violations[KINDS] = {};
    std::string first_message[KINDS];
    uint64_t total_violations() const;
    // The last accesses of both sides before the first violation, one per line.
    std::string first_context;
    uint64_t imports = 0, imports_new = 0, exports = 0, published = 0;
    uint64_t worst_import_accesses = 0, worst_import_iterations = 0;
    uint64_t export_accesses = 0;       // the fixed count, once seen
    // Accesses beyond the payload of every Import that returned a value.
    uint64_t import_ctl_sum = 0, import_ctl_worst = 0, imports_counted = 0;
    static const int kBuckets = 8;      // log10(writer/reader speed) from -2 to 2
    uint64_t bucket_imports[kBuckets] = {}, bucket_worst_iter[kBuckets] = {};
    uint64_t bucket_worst_accesses[kBuckets] = {}, bucket_iter_sum[kBuckets] = {};
    // Accesses beyond the payload in calls the partner did not disturb (no
    // partner access during the call): [min, max] per kind.
    enum { IMPORT_OLD, IMPORT_NEW, EXPORT, CALL_KINDS };
    uint64_t overhead_min[CALL_KINDS] = {~0ull, ~0ull, ~0ull}, overhead_max[CALL_KINDS] = {};
    uint64_t newest_published_seq() const { return newest_pub_; }
    uint64_t newest_complete_seq() const { return newest_complete_; }
    uint64_t last_seq() const { return last_seq_; }
    // Producer writes to buffer b at or after the given edge.
    bool producer_wrote_since(int b, uint64_t edge) const {
        return !buffer_writes_[b].empty() && buffer_writes_[b].back() >= edge;
    }

private:
    void violation(Kind k, const std::string &msg);
    int buffer_of(uint32_t addr) const;   // 1..3 (four-slot 1..4), 0 control word, -1 outside

    uint32_t base_, size_, words_;
    int prod_, cons_, kind_;
    uint32_t bytes_;                               // the channel's bytes
    std::map<uint64_t, uint64_t> complete_cycle_;  // four-slot: seq -> edge of its Slot store
    uint64_t newest_complete_ = 0, exp_slot_stores_ = 0;
    // Producer side.
    uint64_t cur_seq_ = 0;
    bool exporting_ = false;
    uint64_t export_acc_ = 0;
    std::map<uint64_t, uint64_t> publish_cycle_;   // seq -> edge of its Actual store
    uint64_t newest_pub_ = 0, newest_started_ = 0;
    std::vector<uint64_t> buffer_writes_[5];      // edges of producer writes per buffer
    // Consumer side.
    bool importing_ = false;
    uint64_t imp_start_ = 0, imp_acc_ = 0, imp_iter_ = 0, imp_last_actual_ = 0;
    uint64_t imp_first_read_ = 0, imp_last_read_ = 0, pub_at_start_ = 0;
    int imp_buffer_ = 0, imp_bucket_ = 0, imp_limit_ = -1, iteration_limit_ = -1;
    bool imp_two_buffers_ = false, imp_contended_ = false, exp_contended_ = false;
    bool has_last_ = true, skip_new_check_ = false;  // the initial value counts as read
    uint64_t last_seq_ = 0;
    void note_overhead(int kind, uint64_t accesses);
    std::vector<uint8_t> expect_;
    static const uint64_t kOlderSearched = 64;   // see import_end
    static const int kHistory = 48;
    Access history_[kHistory];
    uint64_t history_n_ = 0;
};
