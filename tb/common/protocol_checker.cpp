// protocol_checker.cpp -- see protocol_checker.h.
#include "protocol_checker.h"
#include <algorithm>
#include <cstdio>
#include <cstring>
extern "C" {
#include "albatross.h"
}

void make_value(uint64_t seq, uint8_t *out, uint32_t size)
{
    uint64_t x = seq * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
    for (uint32_t i = 0; i < size; ++i) {
        if (i < 4) {
            out[i] = static_cast<uint8_t>((seq >> (8 * i)) ^ (0x5A + 17 * i));
        } else {
            x ^= x >> 29; x *= 0xBF58476D1CE4E5B9ull; x ^= x >> 32;
            out[i] = static_cast<uint8_t>(x);
        }
    }
}

const char *ProtocolChecker::kind_name(int k)
{
    static const char *n[KINDS] = {"mutual_exclusion", "definite_results", "actuality",
                                   "termination", "ownership", "driver_error"};
    return n[k];
}

ProtocolChecker::ProtocolChecker(uint32_t base, uint32_t size, int producer_port, int consumer_port, int kind)
    : base_(base), size_(size), words_((size + 3) / 4), prod_(producer_port), cons_(consumer_port),
      kind_(kind), bytes_(kind == ALB_FOUR_SLOT ? ALB_FS_CHANNEL_BYTES(size) : ALB_CHANNEL_BYTES(size)),
      expect_(size)
{
    publish_cycle_[0] = 0;   // the initial value, in Buffer1 from the start
    complete_cycle_[0] = 0;
}

uint64_t ProtocolChecker::total_violations() const
{
    uint64_t t = 0;
    for (int k = 0; k < KINDS; ++k) t += violations[k];
    return t;
}

void ProtocolChecker::violation(Kind k, const std::string &msg)
{
    if (violations[k]++ == 0) first_message[k] = msg;
    if (!first_context.empty()) return;
    uint64_t from = history_n_ > kHistory ? history_n_ - kHistory : 0;
    for (uint64_t i = from; i < history_n_; ++i) {
        const Access &a = history_[i % kHistory];
        int b = buffer_of(a.req.addr);
        char line[160];
        std::snprintf(line, sizeof line, "    cycle %8llu  %s %s %-11s lanes %x  data %08x\n",
                      static_cast<unsigned long long>(a.serve_cycle), a.port == prod_ ? "producer" : "consumer",
                      a.req.we ? "write" : "read ",
                      b == 0 ? (a.req.sel == 0xFu ? "control" : a.req.sel & 1 ? "Actual" : a.req.sel & 2 ? "ReadLocked"
                                : a.req.sel & 4 ? "Slot0" : "Slot1") : b > 0 ? ("Buffer" + std::to_string(b)).c_str() : "outside",
                      a.req.sel, a.req.we ? a.req.wdata : a.rdata);
        first_context += line;
    }
}

int ProtocolChecker::buffer_of(uint32_t addr) const
{
    if (addr < base_ || addr >= base_ + bytes_) return -1;
    uint32_t off = addr - base_;
    if (off < ALB_OFF_BUFFERS) return 0;
    return 1 + static_cast<int>((off - ALB_OFF_BUFFERS) / ALB_STRIDE(size_));
}

void ProtocolChecker::on_access(const Access &a)
{
    history_[history_n_++ % kHistory] = a;
    int b = buffer_of(a.req.addr);
    bool ctrl_actual = b == 0 && (a.req.sel & (1u << ALB_OFF_ACTUAL));
    bool ctrl_rl = b == 0 && (a.req.sel & (1u << ALB_OFF_READLOCKED));
    char msg[200];
    if (a.port == prod_) {
        ++export_acc_;
        if (importing_) imp_contended_ = true;
        if (a.req.we) {
            const bool fs = kind_ == ALB_FOUR_SLOT;
            if (ctrl_rl || (b == 0 && !fs && (a.req.sel & 0xCu))) {
                std::snprintf(msg, sizeof msg, "producer wrote control lanes 0x%x at cycle %llu: it owns only Actual%s",
                              a.req.sel, static_cast<unsigned long long>(a.serve_cycle), fs ? ", Slot0 and Slot1" : "");
                violation(OWNERSHIP, msg);
            }
            if (fs && b == 0 && (a.req.sel & 0xCu) && exporting_) {
                ++exp_slot_stores_;
                complete_cycle_.emplace(cur_seq_, a.serve_cycle);
                newest_complete_ = std::max(newest_complete_, cur_seq_);
            }
            if (b >= 1) buffer_writes_[b].push_back(a.serve_cycle);
            if (ctrl_actual && exporting_) {
                publish_cycle_[cur_seq_] = a.serve_cycle;
                if (kind_ == ALB_FOUR_SLOT) complete_cycle_.emplace(cur_seq_, a.serve_cycle);  // kind mismatch
                else complete_cycle_[cur_seq_] = a.serve_cycle;   // three-buffer: complete = published
                newest_complete_ = std::max(newest_complete_, cur_seq_);
                newest_pub_ = std::max(newest_pub_, cur_seq_);
                ++published;
            }
        }
    } else if (a.port == cons_) {
        ++imp_acc_;
        if (exporting_) exp_contended_ = true;
        if (a.req.we) {
            if (!ctrl_rl || (a.req.sel & ~(1u << ALB_OFF_READLOCKED) & 0xFu)) {
                std::snprintf(msg, sizeof msg, "consumer wrote address 0x%x lanes 0x%x at cycle %llu: it owns only ReadLocked",
                              a.req.addr, a.req.sel, static_cast<unsigned long long>(a.serve_cycle));
                violation(OWNERSHIP, msg);
            } else {
                ++imp_iter_;
            }
        } else if (ctrl_actual || (b == 0 && kind_ == ALB_FOUR_SLOT)) {
            imp_last_actual_ = a.serve_cycle;   // four-slot: the last control-word load
        } else if (b >= 1) {
            if (imp_buffer_ == 0) {
                imp_buffer_ = b;
                imp_first_read_ = a.serve_cycle;
            } else if (b != imp_buffer_) {
                imp_two_buffers_ = true;
            }
            imp_last_read_ = a.serve_cycle;
        }
    }
}

void ProtocolChecker::note_overhead(int kind, uint64_t accesses)
{
    overhead_min[kind] = std::min(overhead_min[kind], accesses);
    overhead_max[kind] = std::max(overhead_max[kind], accesses);
}

void ProtocolChecker::export_begin(uint64_t seq)
{
    cur_seq_ = seq;
    newest_started_ = std::max(newest_started_, seq);
    exporting_ = true;
    exp_contended_ = false;
    export_acc_ = 0;
    exp_slot_stores_ = 0;
}

void ProtocolChecker::export_end(int rc)
{
    char msg[160];
    exporting_ = false;
    ++exports;
    if (rc != ALB_OK) {
        std::snprintf(msg, sizeof msg, "Export of seq %llu returned %d, expected ALB_OK (control bytes valid)",
                      static_cast<unsigned long long>(cur_seq_), rc);
        violation(DRIVER_ERROR, msg);
    }
    const bool fs = kind_ == ALB_FOUR_SLOT;
    if (fs && exp_slot_stores_ != 1) {
        std::snprintf(msg, sizeof msg, "kind mismatch: Export of seq %llu on a four-slot channel made %llu Slot stores, "
                      "expected exactly 1%s", static_cast<unsigned long long>(cur_seq_),
                      static_cast<unsigned long long>(exp_slot_stores_),
                      exp_slot_stores_ ? "" : " (a three-buffer producer?)");
        violation(TERMINATION, msg);
    }
    uint64_t fixed = (fs ? 3 : 2) + words_;
    if (export_acc_ != fixed) {
        std::snprintf(msg, sizeof msg, "Export of seq %llu took %llu accesses, expected exactly %llu",
                      static_cast<unsigned long long>(cur_seq_),
                      static_cast<unsigned long long>(export_acc_), static_cast<unsigned long long>(fixed));
        violation(TERMINATION, msg);
    }
    export_accesses = export_acc_;
    if (!exp_contended_) note_overhead(EXPORT, export_acc_ - words_);
}

void ProtocolChecker::producer_restarted()
{
    exporting_ = false;
}

void ProtocolChecker::consumer_restarted()
{
    importing_ = false;
    skip_new_check_ = true;
}

void ProtocolChecker::import_begin(uint64_t now, int bucket)
{
    importing_ = true;
    imp_start_ = now;
    imp_acc_ = imp_iter_ = 0;
    imp_buffer_ = 0;
    imp_two_buffers_ = false;
    imp_contended_ = false;
    imp_bucket_ = bucket;
    imp_limit_ = iteration_limit_;
    pub_at_start_ = newest_pub_;
    // Prune producer writes that can no longer overlap an Import.
    for (int b = 1; b <= 4; ++b) {
        std::vector<uint64_t> &w = buffer_writes_[b];
        if (w.size() > 4096 || (!w.empty() && w.back() < now)) {
            w.erase(w.begin(), std::lower_bound(w.begin(), w.end(), now));
        }
    }
}

void ProtocolChecker::import_end(int rc, const uint8_t *value, uint64_t now)
{
    char msg[240];
    importing_ = false;
    ++imports;
    if (rc == ALB_NEW) ++imports_new;
    worst_import_accesses = std::max(worst_import_accesses, imp_acc_);
    worst_import_iterations = std::max(worst_import_iterations, imp_iter_);
    bucket_imports[imp_bucket_]++;
    bucket_iter_sum[imp_bucket_] += imp_iter_;
    bucket_worst_iter[imp_bucket_] = std::max(bucket_worst_iter[imp_bucket_], imp_iter_);
    bucket_worst_accesses[imp_bucket_] = std::max(bucket_worst_accesses[imp_bucket_], imp_acc_);
    if (!imp_contended_ && rc >= 0) note_overhead(rc == ALB_NEW ? IMPORT_NEW : IMPORT_OLD, imp_acc_ - words_);
    if (rc < 0) {
        std::snprintf(msg, sizeof msg, "Import returned %d, expected ALB_NEW or ALB_OLD (control bytes valid)", rc);
        violation(DRIVER_ERROR, msg);
        return;
    }
    ++imports_counted;
    import_ctl_sum += imp_acc_ - std::min<uint64_t>(imp_acc_, words_);
    import_ctl_worst = std::max(import_ctl_worst, imp_acc_ - std::min<uint64_t>(imp_acc_, words_));
    if (kind_ == ALB_FOUR_SLOT && imp_acc_ != 1 + words_ && imp_acc_ != 3 + words_) {
        std::snprintf(msg, sizeof msg, "wait-free: four-slot Import begun at cycle %llu took %llu accesses, expected "
                      "exactly 1 + %u = %u (nothing new) or 3 + %u = %u",
                      static_cast<unsigned long long>(imp_start_), static_cast<unsigned long long>(imp_acc_),
                      words_, 1 + words_, words_, 3 + words_);
        violation(TERMINATION, msg);
    }
    if (imp_limit_ >= 0 && imp_iter_ > static_cast<uint64_t>(imp_limit_)) {
        std::snprintf(msg, sizeof msg, "Import begun at cycle %llu looped %llu times, expected at most %d",
                      static_cast<unsigned long long>(imp_start_), static_cast<unsigned long long>(imp_iter_), imp_limit_);
        violation(TERMINATION, msg);
    }
    if (imp_two_buffers_) {
        std::snprintf(msg, sizeof msg, "Import begun at cycle %llu read from more than one buffer",
                      static_cast<unsigned long long>(imp_start_));
        violation(MUTEX, msg);
    }
    if (imp_buffer_ >= 1) {
        const std::vector<uint64_t> &w = buffer_writes_[imp_buffer_];
        auto it = std::lower_bound(w.begin(), w.end(), imp_first_read_);
        if (it != w.end() && *it <= imp_last_read_) {
            std::snprintf(msg, sizeof msg,
                          "producer wrote Buffer%d at cycle %llu while the consumer read it (cycles %llu..%llu)",
                          imp_buffer_, static_cast<unsigned long long>(*it),
                          static_cast<unsigned long long>(imp_first_read_),
                          static_cast<unsigned long long>(imp_last_read_));
            violation(MUTEX, msg);
        }
    }
    // Which exported value is it?  A payload of fewer than 4 bytes names its
    // export only modulo 2^(8*size), so first look among the exports a correct
    // Import may return (published by its last load of Actual, not older than
    // what was published when it began or than the last value read), newest
    // first; only if none matches, search every recent export to tell an old,
    // an unpublished and a torn value apart.
    // The search reaches at most kOlderSearched exports below what was
    // published when the Import began: with a driver that never returns a
    // whole value, last_seq_ stays put and an unbounded search would cost
    // every Import a pass over all exports so far (a run that seems to hang).
    uint64_t lo_seq = std::min(pub_at_start_, has_last_ ? last_seq_ : pub_at_start_);
    lo_seq = lo_seq > 8 ? lo_seq - 8 : 0;
    lo_seq = std::max(lo_seq, pub_at_start_ > kOlderSearched ? pub_at_start_ - kOlderSearched : 0);
    uint64_t floor_seq = std::max(pub_at_start_, has_last_ ? last_seq_ : 0);
    bool found = false;
    uint64_t seq = 0;
    // An Old Import that returns the bytes of the last value read is taken
    // to have returned that value: a payload under 4 bytes repeats every
    // 2^(8*size) exports, and a four-slot Old Import may read its buffer
    // again while a newer export with the same bytes is complete elsewhere.
    if (rc == ALB_OLD && has_last_) {
        value_fn(last_seq_, expect_.data(), size_);
        if (std::memcmp(expect_.data(), value, size_) == 0) { found = true; seq = last_seq_; }
    }
    for (int pass = 0; pass < 2 && !found; ++pass) {
        for (uint64_t s = newest_started_ + 1; s-- > lo_seq;) {
            if (pass == 0) {
                auto p = complete_cycle_.find(s);
                if (s < floor_seq || p == complete_cycle_.end() || p->second > imp_last_actual_) continue;
            }
            value_fn(s, expect_.data(), size_);
            if (std::memcmp(expect_.data(), value, size_) == 0) { found = true; seq = s; break; }
        }
    }
    if (!found) {
        std::snprintf(msg, sizeof msg,
                      "Import ending at cycle %llu returned a value that no Export wrote (torn or invented); "
                      "expected a value of seq %llu..%llu, first bytes %02x %02x %02x %02x",
                      static_cast<unsigned long long>(now), static_cast<unsigned long long>(pub_at_start_),
                      static_cast<unsigned long long>(newest_pub_), value[0], size_ > 1 ? value[1] : 0,
                      size_ > 2 ? value[2] : 0, size_ > 3 ? value[3] : 0);
        violation(DEFINITE, msg);
        return;
    }
    auto pub = complete_cycle_.find(seq);
    if (pub == complete_cycle_.end() || pub->second > imp_last_actual_) {
        std::snprintf(msg, sizeof msg,
                      "Import returned seq %llu, which was not %s before its last load of %s (cycle %llu)",
                      static_cast<unsigned long long>(seq),
                      kind_ == ALB_FOUR_SLOT ? "complete (Slot stored)" : "published",
                      kind_ == ALB_FOUR_SLOT ? "the control word" : "Actual",
                      static_cast<unsigned long long>(imp_last_actual_));
        violation(DEFINITE, msg);
    }
    if (seq < pub_at_start_) {
        std::snprintf(msg, sizeof msg, "Import begun at cycle %llu returned seq %llu, expected seq >= %llu (published before it began)",
                      static_cast<unsigned long long>(imp_start_), static_cast<unsigned long long>(seq),
                      static_cast<unsigned long long>(pub_at_start_));
        violation(ACTUALITY, msg);
    }
    if (has_last_ && seq < last_seq_) {
        std::snprintf(msg, sizeof msg, "Import returned seq %llu after seq %llu: went back in time",
                      static_cast<unsigned long long>(seq), static_cast<unsigned long long>(last_seq_));
        violation(ACTUALITY, msg);
    }
    if (has_last_ && !skip_new_check_) {
        bool newer = seq > last_seq_;
        if (newer != (rc == ALB_NEW)) {
            std::snprintf(msg, sizeof msg, "Import returned %s for seq %llu after seq %llu, expected %s",
                          rc == ALB_NEW ? "New" : "Old", static_cast<unsigned long long>(seq),
                          static_cast<unsigned long long>(last_seq_), newer ? "New" : "Old");
            violation(ACTUALITY, msg);
        }
    }
    skip_new_check_ = false;
    has_last_ = true;
    last_seq_ = seq;
}
