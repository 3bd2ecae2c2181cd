// channel_watch.h -- feeds the protocol checker (tb/common/protocol_checker.h)
// of one channel from the accesses seen at the two ports of an
// albatross_dpram, when neither side is a simulated CPU that could announce
// its calls: a soft core running the real driver, or a hardware endpoint.
// The call boundaries are read from the accesses themselves:
//   Export  begins at the producer's load of ReadLocked (a read of the
//           control word selecting the ReadLocked lane; an engine's
//           read-back of Actual before it is not part of the Export), ends at
//           its store of Actual.  The producer exports seq 1, 2, 3, ... in
//           order; the first value word it stores must be that seq.
//   Import  begins at the consumer's load of Actual when no Import is open,
//           ends with its W-th load of a buffer word.  Its result is New if
//           the consumer stored ReadLocked in it (the driver's rule), unless
//           the bench reports the result itself (external_result: an
//           endpoint's new_o, with import_done()).
// Accesses before arm_producer() / arm_consumer() are not watched (a
// program's start-up: the RAM image, attach).  Test-only, header-only.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>
#include "protocol_checker.h"
extern "C" {
#include "albatross.h"
}

class ChannelWatch {
public:
    ChannelWatch(uint32_t base, uint32_t size, int producer_port, int consumer_port)
        : chk(base, size, producer_port, consumer_port), base_(base), size_(size),
          words_((size + 3) / 4), prod_(producer_port), cons_(consumer_port), value_(words_ * 4, 0) {}

    ProtocolChecker chk;
    bool external_result = false;   // the bench calls import_done() with the result
    int skip_consumer_ctrl_reads = 0;  // control-word reads to ignore first (attach)
    uint64_t next_seq = 1;
    uint64_t export_order_errors = 0;
    std::string first_order_error;
    uint64_t imports_ended = 0;

    void arm_producer() { prod_armed_ = true; }
    void arm_consumer() { cons_armed_ = true; }

    // One completed access (ack seen) at the given edge.
    void on_access(int port, bool we, uint32_t word_adr, uint8_t sel, uint32_t wdata, uint32_t rdata,
                   uint64_t cycle) {
        Access a{};
        a.port = port;
        a.req.addr = word_adr * 4u;
        a.req.we = we;
        a.req.sel = sel;
        a.req.wdata = wdata;
        a.rdata = rdata;
        a.issue_cycle = a.serve_cycle = cycle;
        const bool ctrl = a.req.addr == base_;
        const uint32_t buf0 = base_ + ALB_OFF_BUFFERS, end = base_ + ALB_CHANNEL_BYTES(size_);
        const bool payload = a.req.addr >= buf0 && a.req.addr < end;
        if (port == prod_ && prod_armed_) {
            if (!exporting_ && !we && ctrl && (sel & (1u << ALB_OFF_READLOCKED))) {
                chk.export_begin(next_seq);
                exporting_ = true;
                first_word_ = true;
            }
            chk.on_access(a);
            if (exporting_ && we && payload && first_word_) {
                first_word_ = false;
                if (wdata != static_cast<uint32_t>(next_seq) && export_order_errors++ == 0) {
                    char m[160];
                    std::snprintf(m, sizeof m, "export %llu stored 0x%08x as its first word, expected its seq",
                                  static_cast<unsigned long long>(next_seq), wdata);
                    first_order_error = m;
                }
            }
            if (exporting_ && we && ctrl && (sel & (1u << ALB_OFF_ACTUAL))) {
                chk.export_end(ALB_OK);
                exporting_ = false;
                ++next_seq;
            }
        } else if (port == cons_ && cons_armed_) {
            if (!importing_ && !we && ctrl && (sel & (1u << ALB_OFF_ACTUAL))) {
                if (skip_consumer_ctrl_reads > 0) {
                    --skip_consumer_ctrl_reads;
                } else {
                    chk.import_begin(cycle, 0);
                    importing_ = true;
                    stored_rl_ = false;
                    read_ = 0;
                    payload_done_ = false;
                }
            }
            chk.on_access(a);
            if (importing_ && we && ctrl) stored_rl_ = true;
            if (importing_ && !we && payload && read_ < words_) {
                std::memcpy(&value_[4 * read_], &rdata, 4);
                if (++read_ == words_) {
                    payload_done_ = true;
                    if (!external_result) finish(stored_rl_ ? ALB_NEW : ALB_OLD, cycle);
                }
            }
        }
    }

    // external_result: the consumer's Import ended with result rc (ALB_NEW,
    // ALB_OLD or an error) in this cycle.
    void import_done(int rc, uint64_t cycle) {
        if (importing_) finish(rc, cycle);
    }
    bool stored_rl_in_import() const { return stored_rl_; }
    bool importing() const { return importing_; }

private:
    void finish(int rc, uint64_t cycle) {
        chk.import_end(rc, value_.data(), cycle);
        importing_ = false;
        ++imports_ended;
    }
    uint32_t base_, size_, words_;
    int prod_, cons_;
    bool prod_armed_ = false, cons_armed_ = false;
    bool exporting_ = false, first_word_ = false;
    bool importing_ = false, stored_rl_ = false, payload_done_ = false;
    uint32_t read_ = 0;
    std::vector<uint8_t> value_;
};

// The pair test's value (soc/firmware/board.h): seq, mix(seq), mix(mix(seq)),
// and their checksum, as 16 little-endian bytes (seq taken modulo 2^32).
static inline uint32_t cw_pair_mix(uint32_t x)
{
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return x + 0x9E3779B9u;
}

static inline void cw_pair_value(uint64_t seq, uint8_t *out, uint32_t size)
{
    uint32_t w[4];
    w[0] = static_cast<uint32_t>(seq);
    w[1] = cw_pair_mix(w[0]);
    w[2] = cw_pair_mix(w[1]);
    w[3] = w[0] ^ w[1] ^ w[2] ^ 0x5A5A5A5Au;
    std::memset(out, 0, size);
    std::memcpy(out, w, size < 16 ? size : 16);
}
