// system_checker.cpp -- see system_checker.h.
#include "system_checker.h"
#include <algorithm>
#include <cstdio>
#include <cstring>
#include "protocol_checker.h"
extern "C" {
#include "albatross.h"
}

void channel_value(int channel_id, uint64_t seq, uint8_t *out, uint32_t size)
{
    for (uint32_t i = 0; i < size; ++i) out[i] = static_cast<uint8_t>(value_word(channel_id, seq, i / 4) >> (8 * (i % 4)));
}

const char *SystemChecker::kind_name(int k)
{
    static const char *n[KINDS] = {"mutual_exclusion", "definite_results", "actuality", "duplicate_new",
                                   "latency_bound", "ownership", "in_channel", "driver_error", "global_time",
                                   "taken_at", "new_twice", "freshness", "due_cycle", "fragment_publish",
                                   "source_lock", "fragment_word"};
    return n[k];
}

SystemChecker::SystemChecker(const Plan &plan, SystemSim &sim, uint64_t time_offset)
    : plan_(plan), sim_(sim), time_offset_(time_offset)
{
    const size_t n = plan.channels.size();
    stats.resize(n);
    src_.resize(n);
    dst_.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const PlanChannel &c = plan.channels[i];
        stats[i].dests.resize(c.dests.size());
        dst_[i].resize(c.dests.size());
        if (c.copy()) {
            Instance in;
            in.chan = static_cast<int>(i);
            in.board = c.src_board;
            in.base = c.src_base;
            in.size = c.size;
            in.producer_port = 0;
            in.four_slot = c.four_slot;
            inst_.push_back(in);
            src_[i].publish_cycle.push_back(0);   // seq 0: the RAM image
            src_[i].complete_cycle.push_back(0);
        }
        for (size_t d = 0; d < c.dests.size(); ++d) {
            Instance in;
            in.chan = static_cast<int>(i);
            in.dest = static_cast<int>(d);
            in.board = c.dests[d].board;
            in.base = c.dests[d].base;
            in.size = c.dest_size();
            in.producer_port = 1;
            in.four_slot = c.four_slot;
            inst_.push_back(in);
            // What the destination holds when checking begins (the RAM image,
            // or what the controller published while the images were being
            // loaded): publication 0, unread if Actual != ReadLocked.
            const RefRam &ram = sim.ref[in.board];
            uint8_t actual = ram.byte(in.base + ALB_OFF_ACTUAL), rl = ram.byte(in.base + ALB_OFF_READLOCKED);
            if (!(c.four_slot ? ALB_FS_VALID_INDEX(actual) : ALB_VALID_INDEX(actual))) actual = ALB_BUFFER1;
            DestPub p{0, 0, 0, actual, 0, std::vector<uint8_t>(c.dest_size(), 0)};
            const uint32_t at = in.base + ALB_OFF_BUFFER(static_cast<uint32_t>(actual), in.size);
            for (uint32_t k = 0; k < in.size; ++k) p.bytes[k] = ram.byte(at + k);
            std::memcpy(&p.taken_at, &p.bytes[c.taken_at_offset()], 4);
            dst_[i][d].pubs.push_back(p);
            dst_[i][d].pending = 1;
            dst_[i][d].last_read = actual == rl ? 0 : -1;
            dst_[i][d].actual = actual;
        }
    }
}

uint64_t SystemChecker::total() const
{
    uint64_t t = 0;
    for (int k = 0; k < KINDS; ++k) t += violations[k];
    return t;
}

void SystemChecker::violation(Kind k, const std::string &msg)
{
    if (violations[k]++ == 0) first_message[k] = msg;
}

SystemChecker::Instance *SystemChecker::find(int board, uint32_t addr)
{
    for (Instance &in : inst_)
        if (in.board == board && addr >= in.base && addr < in.base + instance_bytes(plan_.channels[in.chan], in.size))
            return &in;
    return nullptr;
}

void SystemChecker::close_window(Instance &in)
{
    if (!in.win_buffer) return;
    std::vector<uint64_t> &w = in.writes[in.win_buffer];
    auto it = std::lower_bound(w.begin(), w.end(), in.win_first);
    if (it != w.end() && *it <= in.win_last) {
        char m[240];
        std::snprintf(m, sizeof m, "board %d, %s %s: the %s wrote Buffer%d at cycle %llu while the %s read it (cycles %llu..%llu)",
                      in.board, plan_.channels[in.chan].name.c_str(), in.dest < 0 ? "source" : "destination",
                      in.producer_port ? "controller" : "CPU", in.win_buffer, static_cast<unsigned long long>(*it),
                      in.producer_port ? "CPU" : "controller", static_cast<unsigned long long>(in.win_first),
                      static_cast<unsigned long long>(in.win_last));
        violation(MUTEX, m);
    }
    in.win_buffer = 0;
    for (int b = 1; b <= 4; ++b)
        if (in.writes[b].size() > 1024) in.writes[b].erase(in.writes[b].begin(), in.writes[b].end() - 64);
}

void SystemChecker::on_access(int board, const Access &a)
{
    char m[240];
    Instance *in = find(board, a.req.addr);
    if (!in) {
        if (a.port == 1) ++controller_accesses_outside;
        std::snprintf(m, sizeof m, "board %d: the %s %s address 0x%x, outside every channel", board,
                      a.port ? "controller" : "CPU", a.req.we ? "wrote" : "read", a.req.addr);
        violation(IN_CHANNEL, m);
        return;
    }
    const uint32_t off = a.req.addr - in->base;
    const bool control = off < ALB_OFF_BUFFERS;
    const int buffer = control ? 0 : 1 + static_cast<int>((off - ALB_OFF_BUFFERS) / ALB_STRIDE(in->size));
    const bool producer = a.port == in->producer_port;
    const char *who = a.port ? "controller" : "CPU";
    if (a.req.we) {
        // Four-slot: the producer also stores the Slot bytes, one at a time.
        const bool slot_store = in->four_slot && (a.req.sel == 1u << ALB_OFF_SLOT0 || a.req.sel == 1u << ALB_OFF_SLOT1);
        bool ok = control ? a.req.sel == (producer ? 1u << ALB_OFF_ACTUAL : 1u << ALB_OFF_READLOCKED) ||
                            (producer && slot_store)
                          : producer;
        if (!ok) {
            std::snprintf(m, sizeof m, "board %d, %s: the %s (%s) wrote offset %u lanes 0x%x at cycle %llu, which it does not own",
                          board, plan_.channels[in->chan].name.c_str(), who, producer ? "producer" : "consumer", off,
                          a.req.sel, static_cast<unsigned long long>(a.serve_cycle));
            violation(OWNERSHIP, m);
        }
    }
    if (producer) {
        if (a.req.we && buffer) in->writes[buffer].push_back(a.serve_cycle);
        // A source's producer begins an Export with its load of the control word.
        if (!a.req.we && control && in->dest < 0) src_[in->chan].exporting = true, src_[in->chan].overtaken = false;
        if (!a.req.we && control && in->four_slot && in->dest >= 0) dst_[in->chan][in->dest].loaded = true;
        if (a.req.we && control && (a.req.sel & 1u)) {
            uint8_t actual = static_cast<uint8_t>(a.req.wdata);
            // A four-slot source's value is complete, and may be taken, from
            // its Slot store (below), before this store publishes it.
            if (in->dest < 0) {
                src_[in->chan].pending_publish = a.serve_cycle;
                src_[in->chan].exporting = false;
                if (!in->four_slot) src_[in->chan].pending_complete = a.serve_cycle;
            }
            else if (in->four_slot) dest_actual_stored(*in, a.serve_cycle, actual);
            else dest_published(*in, a.serve_cycle, actual);
            if (in->dest >= 0) {
                // Performed: until the controller sees its ack (on_bus, in
                // this same clock) the store counts as landed, unanswered.
                DestState &d = dst_[in->chan][in->dest];
                if (d.unanswered) ++stats[in->chan].dests[in->dest].landed_unanswered;
                d.unanswered = true;
                d.unanswered_cycle = a.serve_cycle;
            }
        }
        if (a.req.we && control && in->four_slot && in->dest < 0 && (a.req.sel & 0xCu))
            src_[in->chan].pending_complete = a.serve_cycle;
        // Four-slot: the Slot store completes buf(pair, slot).
        if (a.req.we && control && in->four_slot && in->dest >= 0 && (a.req.sel & 0xCu)) {
            const unsigned pair = (a.req.sel & 0x8u) ? 1u : 0u;
            const uint8_t slot = static_cast<uint8_t>(a.req.wdata >> (8 * (ALB_OFF_SLOT0 + pair)));
            if (!ALB_FS_VALID_SLOT(slot)) {
                std::snprintf(m, sizeof m, "board %d, %s: the controller stored Slot%u = %u", board,
                              plan_.channels[in->chan].name.c_str(), pair, slot);
                violation(DEFINITE, m);
            } else {
                dst_[in->chan][in->dest].loaded = false;
                dest_published(*in, a.serve_cycle, static_cast<uint8_t>(ALB_FS_BUFFER(pair, slot)));
            }
        }
    } else {
        if (!a.req.we && buffer) {
            if (in->win_buffer != buffer) {
                close_window(*in);
                in->win_buffer = buffer;
                in->win_first = a.serve_cycle;
            }
            in->win_last = a.serve_cycle;
        } else {
            close_window(*in);
        }
    }
}

int64_t SystemChecker::source_seq(int chan, uint8_t b)
{
    const PlanChannel &c = plan_.channels[chan];
    const SourceState &s = src_[chan];
    const uint32_t at = c.src_base + ALB_OFF_BUFFER(static_cast<uint32_t>(b), c.size);
    std::vector<uint8_t> bytes(c.size), v(c.size);
    for (uint32_t i = 0; i < c.size; ++i) bytes[i] = sim_.ref[c.src_board].byte(at + i);
    // Newest first; one past the last exported(): an Export whose Actual
    // store is done but whose call has not returned yet.
    const uint64_t newest = s.publish_cycle.size(), lowest = newest > 4096 ? newest - 4096 : 0;
    for (uint64_t q = newest + 1; q-- > lowest;) {
        channel_value(c.id, q, v.data(), c.size);
        if (v == bytes) return static_cast<int64_t>(q);
    }
    return -1;
}

// The controller's own view: its acked accesses to a source's control word
// find its takes; an ack of a destination's Actual store shows it answered.
void SystemChecker::on_bus(const SystemSim::BusEvent &e)
{
    Instance *in = find(e.board, e.addr);
    if (!in || e.addr != in->base) return;
    const PlanChannel &c = plan_.channels[in->chan];
    if (in->dest >= 0) {
        if (e.ok && e.we && (e.sel & (1u << ALB_OFF_ACTUAL))) dst_[in->chan][in->dest].unanswered = false;
        return;
    }
    if (!c.copy() || !e.ok) return;
    SourceState &s = src_[in->chan];
    if (e.we && (e.sel & (1u << ALB_OFF_READLOCKED))) {
        s.rl_stored = static_cast<int>((e.wdata >> (8 * ALB_OFF_READLOCKED)) & 0xFFu);
        if (s.exporting && !s.overtaken) s.overtaken = true, ++stats[in->chan].exports_overtaken;
        return;
    }
    if (e.we || !(e.sel & (1u << ALB_OFF_ACTUAL))) return;
    const uint8_t a = static_cast<uint8_t>(e.rdata >> (8 * ALB_OFF_ACTUAL));
    // A later slot finds the source holding the value a destination holds
    // from a store that landed with its answer lost: the case in which a
    // controller that forgot the landing would publish it again (counted for
    // the three-buffer kind, whose Actual names the value directly).
    if (!in->four_slot && ALB_VALID_INDEX(a)) {
        int64_t cur = -1;
        for (size_t k = 0; k < dst_[in->chan].size(); ++k) {
            const DestState &d = dst_[in->chan][k];
            if (!d.unanswered || d.pubs.size() < 2 || e.start <= d.unanswered_cycle) continue;
            if (cur < 0) cur = source_seq(in->chan, a);
            if (cur < 0 || d.pubs.back().seq != static_cast<uint64_t>(cur)) continue;
            ++stats[in->chan].dests[k].landed_same_later;
            if (d.new_seq == static_cast<uint64_t>(cur)) ++stats[in->chan].dests[k].landed_same_read;
        }
    }
    uint8_t b = 0;
    if (s.rl_stored >= 0) {
        if (!in->four_slot && a == s.rl_stored && ALB_VALID_INDEX(a)) b = a;
        else if (in->four_slot && ALB_FS_VALID_INDEX(static_cast<unsigned>(s.rl_stored))) {
            // b = 1 + 2p + Slot_p of this load, p the pair of the Actual the
            // Import stored as ReadLocked (not of this load's Actual).
            const unsigned pair = ALB_FS_PAIR(s.rl_stored);
            b = static_cast<uint8_t>(ALB_FS_BUFFER(pair, (e.rdata >> (8 * ALB_OFF_SLOT(pair))) & 1u));
        }
    }
    s.rl_stored = -1;
    if (!b) return;
    const int64_t q = source_seq(in->chan, b);
    s.taken = true;
    s.take_seq = q < 0 ? ~0ull : static_cast<uint64_t>(q);
    s.take_time = e.time;
    s.take_cycle = e.end;
    if (take_fn_) take_fn_(in->chan, b, e.time);
}

void SystemChecker::exported(int chan, uint64_t seq)
{
    SourceState &s = src_[chan];
    if (seq != s.publish_cycle.size()) return;   // the harness numbers exports 1, 2, ...
    s.publish_cycle.push_back(s.pending_publish);
    s.complete_cycle.push_back(s.pending_complete);
    ++stats[chan].exports;
}

void SystemChecker::dest_published(Instance &in, uint64_t cycle, uint8_t buffer)
{
    const PlanChannel &c = plan_.channels[in.chan];
    DestState &d = dst_[in.chan][in.dest];
    DestStats &st = stats[in.chan].dests[in.dest];
    char m[260];
    if (!(in.four_slot ? ALB_FS_VALID_INDEX(buffer) : ALB_VALID_INDEX(buffer))) {
        std::snprintf(m, sizeof m, "board %d, %s: the controller stored Actual = %u", in.board, c.name.c_str(), buffer);
        violation(DEFINITE, m);
        return;
    }
    // Storing the index Actual already holds (a retry after a store that
    // landed but whose answer was lost) publishes nothing new.
    if (buffer == d.actual) return;
    d.actual = buffer;
    DestPub p;
    p.cycle = cycle;
    p.pub_cycle = in.four_slot ? ~0ull : cycle;
    p.buffer = buffer;
    p.bytes.resize(in.size);
    const uint32_t at = in.base + ALB_OFF_BUFFER(static_cast<uint32_t>(buffer), in.size);
    for (uint32_t i = 0; i < in.size; ++i) p.bytes[i] = sim_.ref[in.board].byte(at + i);
    std::memcpy(&p.taken_at, &p.bytes[c.taken_at_offset()], 4);
    const DestPub &last = d.pubs.back();
    const uint64_t taken_cycle = p.taken_at + time_offset_;
    ++st.publications;
    if (c.copy()) {
        const SourceState &s = src_[in.chan];
        scratch_.resize(c.size);
        bool found = false;
        uint64_t newest = s.publish_cycle.size() - 1;
        uint64_t lowest = newest > 4096 ? newest - 4096 : 0;
        for (uint64_t q = newest + 1; q-- > lowest;) {
            channel_value(c.id, q, scratch_.data(), c.size);
            if (std::memcmp(scratch_.data(), p.bytes.data(), c.size) == 0) { found = true; p.seq = q; break; }
        }
        if (!found) {
            std::snprintf(m, sizeof m, "board %d, %s: the controller published at cycle %llu a value its producer never exported (torn or invented)",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(cycle));
            violation(DEFINITE, m);
            return;
        }
        if (p.seq == last.seq && d.pubs.size() > 1 && d.unanswered) {
            std::snprintf(m, sizeof m, "board %d, %s: value %llu had landed (its Actual store at cycle %llu was performed, "
                          "answered with err or not at all) and the controller published it again at cycle %llu: "
                          "a landed store must count as delivered, its consumer would see it New twice",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(p.seq),
                          static_cast<unsigned long long>(d.unanswered_cycle), static_cast<unsigned long long>(cycle));
            violation(DUPLICATE, m);
        } else if (p.seq == last.seq && d.pubs.size() > 1) {
            std::snprintf(m, sizeof m, "board %d, %s: the controller published value %llu again at cycle %llu: its consumer would see it New twice",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(p.seq), static_cast<unsigned long long>(cycle));
            violation(DUPLICATE, m);
        } else if (p.seq < last.seq) {
            std::snprintf(m, sizeof m, "board %d, %s: the controller published value %llu after value %llu: back in time",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(p.seq), static_cast<unsigned long long>(last.seq));
            violation(ACTUALITY, m);
        }
        if (taken_cycle < s.complete_cycle[p.seq] || taken_cycle > cycle) {
            std::snprintf(m, sizeof m, "board %d, %s: value %llu completed by its producer at cycle %llu carries taken_at = cycle %llu, "
                          "published at the destination at cycle %llu: expected producer <= taken_at <= destination",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(p.seq),
                          static_cast<unsigned long long>(s.complete_cycle[p.seq]), static_cast<unsigned long long>(taken_cycle),
                          static_cast<unsigned long long>(cycle));
            violation(DEFINITE, m);
        }
        // Exactness: the value of the source's last take, stamped with the
        // time of that take's final Actual load.
        if (!s.taken || p.seq != s.take_seq || p.taken_at != s.take_time) {
            if (!s.taken)
                std::snprintf(m, sizeof m, "board %d, %s: value %llu published at cycle %llu, but the controller never "
                              "took a value from its source", in.board, c.name.c_str(),
                              static_cast<unsigned long long>(p.seq), static_cast<unsigned long long>(cycle));
            else
                std::snprintf(m, sizeof m, "board %d, %s: value %llu published at cycle %llu with taken_at %u: expected "
                              "value %llu with taken_at %u, the time of the final source Actual load (acked at cycle %llu)",
                              in.board, c.name.c_str(), static_cast<unsigned long long>(p.seq),
                              static_cast<unsigned long long>(cycle), p.taken_at, static_cast<unsigned long long>(s.take_seq),
                              s.take_time, static_cast<unsigned long long>(s.take_cycle));
            violation(TAKEN_AT, m);
        }
        if (taken_cycle >= s.complete_cycle[p.seq])
            st.max_taken_minus_publish = std::max(st.max_taken_minus_publish, taken_cycle - s.complete_cycle[p.seq]);
    } else {
        // TIME and STATUS: the controller's own values, taken at the slot.
        p.seq = last.seq + 1;
        uint32_t value0 = 0;
        std::memcpy(&value0, p.bytes.data(), 4);
        bool bad_time = c.kind == "time" && value0 != p.taken_at;
        if (bad_time || taken_cycle > cycle || (d.pubs.size() > 1 && p.taken_at <= last.taken_at)) {
            std::snprintf(m, sizeof m, "board %d, %s: published at cycle %llu with value %u, taken_at %u (cycle %llu) after taken_at %u: "
                          "expected value = taken_at, increasing, not in the future",
                          in.board, c.name.c_str(), static_cast<unsigned long long>(cycle), value0, p.taken_at,
                          static_cast<unsigned long long>(taken_cycle), last.taken_at);
            violation(TIME, m);
        }
    }
    // Latency / age: three-buffer at the Actual store, here; four-slot at its
    // Actual store too (dest_actual_stored), not at the Slot store.
    if (!in.four_slot) measure(in, p, last, d.pubs.size() == 1, cycle);
    d.pubs.push_back(std::move(p));
}

// The latency (copy: from each source value's publication) or age (time,
// status: of the value replaced) of publication p at the destination, which
// replaces prev (the RAM image if prev_is_image), published at cycle.
void SystemChecker::measure(Instance &in, const DestPub &p, const DestPub &prev, bool prev_is_image, uint64_t cycle)
{
    const PlanChannel &c = plan_.channels[in.chan];
    DestState &d = dst_[in.chan][in.dest];
    DestStats &st = stats[in.chan].dests[in.dest];
    char m[260];
    if (c.copy()) {
        const SourceState &s = src_[in.chan];
        d.reached = std::max(d.reached, p.seq);
        // Latency of every source value this publication reaches.
        for (; d.pending <= p.seq && d.pending < s.publish_cycle.size(); ++d.pending) {
            if (s.publish_cycle[d.pending] < latency_from_) continue;
            uint64_t lat = cycle - s.publish_cycle[d.pending], bound = c.latency, bound_retry = c.latency_retry;
            if (bound_fn_ && !bound_fn_(in.chan, s.publish_cycle[d.pending], cycle, bound, bound_retry))
                continue;   // no bound (ModeWatch counts it)
            if (ages_)
                std::fprintf(ages_, "%s,%d,%llu,%llu\n", c.name.c_str(), in.board, static_cast<unsigned long long>(cycle),
                             static_cast<unsigned long long>(lat));
            st.latency_max = std::max(st.latency_max, lat);
            st.latency_sum += lat;
            ++st.latency_n;
            if (d.pending < p.seq) ++st.latency_skipped;
            if (lat > bound_retry) ++st.over_retry_bound;
            if (lat > bound) {
                ++st.latency_over;
                if (latency_checked_) {
                    std::snprintf(m, sizeof m, "%s to board %d: value %llu published at cycle %llu arrived at cycle %llu: "
                                  "latency %llu, expected at most the compiler's bound %llu",
                                  c.name.c_str(), in.board, static_cast<unsigned long long>(d.pending),
                                  static_cast<unsigned long long>(s.publish_cycle[d.pending]),
                                  static_cast<unsigned long long>(cycle), static_cast<unsigned long long>(lat),
                                  static_cast<unsigned long long>(bound));
                    violation(LATENCY, m);
                }
            }
        }
    } else {
        // Age bound: how old the value the destination held had grown when
        // this one replaced it.
        const uint64_t last_taken = prev.taken_at + time_offset_;
        uint64_t age = !prev_is_image && last_taken >= latency_from_ ? cycle - last_taken : 0;
        uint64_t bound = c.latency, bound_retry = c.latency_retry;
        if (age && bound_fn_ && !bound_fn_(in.chan, last_taken, cycle, bound, bound_retry))
            return;   // no bound (ModeWatch counts it)
        if (ages_ && !prev_is_image && last_taken >= latency_from_)
            std::fprintf(ages_, "%s,%d,%llu,%llu\n", c.name.c_str(), in.board, static_cast<unsigned long long>(cycle),
                         static_cast<unsigned long long>(age));
        st.latency_max = std::max(st.latency_max, age);
        st.latency_sum += age;
        ++st.latency_n;
        if (age > bound_retry) ++st.over_retry_bound;
        if (age > bound) {
            ++st.latency_over;
            if (latency_checked_) {
                std::snprintf(m, sizeof m, "%s to board %d: published at cycle %llu aged %llu, expected at most %llu",
                              c.name.c_str(), in.board, static_cast<unsigned long long>(cycle),
                              static_cast<unsigned long long>(age), static_cast<unsigned long long>(bound));
                violation(LATENCY, m);
            }
        }
    }
}

// Four-slot: the Actual store publishes the value the producer completed in
// that buffer (the newest one, not yet published).  Storing an index that
// holds no completed, unpublished value (a retried store) publishes nothing.
void SystemChecker::dest_actual_stored(Instance &in, uint64_t cycle, uint8_t buffer)
{
    DestState &d = dst_[in.chan][in.dest];
    if (!ALB_FS_VALID_INDEX(buffer)) {
        char m[200];
        std::snprintf(m, sizeof m, "board %d, %s: the controller stored Actual = %u", in.board,
                      plan_.channels[in.chan].name.c_str(), buffer);
        violation(DEFINITE, m);
        return;
    }
    for (size_t i = d.pubs.size(); i-- > 0;) {
        if (d.pubs[i].buffer != buffer) continue;
        if (d.pubs[i].pub_cycle != ~0ull) return;
        d.pubs[i].pub_cycle = cycle;
        if (d.loaded) ++stats[in.chan].dests[in.dest].late_publications;
        size_t j = i;                       // the publication it replaces
        while (j > 0 && d.pubs[--j].pub_cycle == ~0ull) {}
        measure(in, d.pubs[i], d.pubs[j], j == 0, cycle);
        return;
    }
}

void SystemChecker::imported(int chan, int dest, int rc, const uint8_t *payload, uint64_t begin, uint64_t end,
                             uint32_t consumer_time)
{
    const PlanChannel &c = plan_.channels[chan];
    DestState &d = dst_[chan][dest];
    DestStats &st = stats[chan].dests[dest];
    char m[260];
    ++st.imports;
    if (rc < 0) {
        std::snprintf(m, sizeof m, "%s on board %d: Import returned %d, expected ALB_NEW or ALB_OLD",
                      c.name.c_str(), c.dests[dest].board, rc);
        violation(DRIVER_ERROR, m);
        return;
    }
    if (rc == ALB_NEW) ++st.imports_new;
    // Overtakes: publications here while this Import ran
    // (counted first: a torn value returns below).
    uint64_t over = 0;
    for (size_t i = d.pubs.size(), k = 0; i-- > 1 && k < 64; ++k)
        if (d.pubs[i].pub_cycle != ~0ull && d.pubs[i].pub_cycle > begin && d.pubs[i].pub_cycle <= end) ++over;
    st.max_overtakes = std::max(st.max_overtakes, over);
    if (over >= 4) ++st.imports_overtaken4;
    const uint32_t n = c.dest_size();
    int64_t found = -1, at_begin = 0;
    // Two publications can hold equal bytes (a time value published before
    // and after a reset): an Old result is first matched with the last read.
    if (rc == ALB_OLD && d.last_read >= 0 && std::memcmp(d.pubs[d.last_read].bytes.data(), payload, n) == 0)
        found = d.last_read;
    for (int64_t i = static_cast<int64_t>(d.pubs.size()) - 1; i >= 0; --i) {
        if (d.pubs[i].pub_cycle <= begin && !at_begin) at_begin = i;
        if (found < 0 && std::memcmp(d.pubs[i].bytes.data(), payload, n) == 0 && d.pubs[i].cycle <= end) found = i;
        if (found >= 0 && (at_begin || i == 0)) break;
    }
    if (found < 0) {
        std::snprintf(m, sizeof m, "%s on board %d: Import ending at cycle %llu returned a value never published there (torn or invented)",
                      c.name.c_str(), c.dests[dest].board, static_cast<unsigned long long>(end));
        violation(DEFINITE, m);
        return;
    }
    if (found < at_begin || found < d.last_read) {
        std::snprintf(m, sizeof m, "%s on board %d: Import begun at cycle %llu returned publication %lld, expected at least %lld",
                      c.name.c_str(), c.dests[dest].board, static_cast<unsigned long long>(begin),
                      static_cast<long long>(found), static_cast<long long>(std::max(at_begin, d.last_read)));
        violation(ACTUALITY, m);
    }
    // Consumer side: a source value is New at most once.
    if (c.copy() && rc == ALB_NEW && found > 0) {
        const uint64_t sq = d.pubs[found].seq;
        if (d.new_seq != ~0ull && sq <= d.new_seq) {
            std::snprintf(m, sizeof m, "%s on board %d: Import ending at cycle %llu returned value %llu as New, "
                          "after this consumer had already read value %llu as New: expected Old (a value New twice)",
                          c.name.c_str(), c.dests[dest].board, static_cast<unsigned long long>(end),
                          static_cast<unsigned long long>(sq), static_cast<unsigned long long>(d.new_seq));
            violation(NEW_TWICE, m);
        }
        d.new_seq = sq;
    }
    bool newer = found > d.last_read;
    if (newer != (rc == ALB_NEW)) {
        std::snprintf(m, sizeof m, "%s on board %d: Import returned %s for publication %lld after %lld, expected %s",
                      c.name.c_str(), c.dests[dest].board, rc == ALB_NEW ? "New" : "Old", static_cast<long long>(found),
                      static_cast<long long>(d.last_read), newer ? "New" : "Old");
        violation(ACTUALITY, m);
    }
    d.last_read = std::max<int64_t>(d.last_read, found);
    uint32_t taken_at = d.pubs[found].taken_at;
    if (found > 0) {
        uint64_t age = consumer_time >= taken_at ? consumer_time - taken_at : 0;
        st.last_age_seen = age;
        st.max_age_seen = std::max(st.max_age_seen, age);
    }
}

void SystemChecker::end_of_run()
{
    for (Instance &in : inst_) close_window(in);
}
