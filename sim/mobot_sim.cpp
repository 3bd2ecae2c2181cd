// mobot_sim.cpp -- the whole-system simulation (make sim) and its scenario
// tests: sim/pico_boards.v, four PicoRV32 boards of the MOBOT-III example
// (radar, odometry, navigation, motor) running sim/firmware/mobot_<board>.c with
// the compiler-generated channel code and the real C driver, each with its
// own albatross_dpram, joined over the bus by albatross_controller running the
// compiler's schedule ROM, with a bus fault injector in between.
//
//   mobot_sim --plan tb_plan.txt +fw0..3=FILE +ram0..3=FILE +rom=FILE [options]
//   (every option: sim/mobot_sim_options.cpp)
//
// The cores report every Import and Export as board events (EVENT/ARG,
// sim/firmware/mobot_check.h).  The harness watches every core's DPRAM port: it
// ages each imported value as (controller time of the Import's last load of
// the control word, that is of Actual; for a four-slot channel its first load,
// docs/four_slot.md) - taken_at, and times each producer's
// stores of Actual; it takes the cycles per call from the events, and it injects
// faults: each new controller request to a live board (the injector's
// fi_new_o) is faulted with probability R, independently or in bursts of mean
// length L accesses (--burst L, tb/common/fault_model.h), its kind (error,
// timeout, timeout after performing) drawn evenly; the measured share is
// checked against R (check faults).
//
// A crashed producer's half-written buffer is never published: its
// consumers' checks (cpu) would see the torn value or a New without a newer
// sequence number.  The report counts the New values after the crash (those
// completed before it and not yet imported).
// Checks (each named; --expect-caught-by CHECK[,CHECK] inverts the verdict:
// the run passes only if those checks, and no other, fail):
//   cpu        every core's own verdict (TOHOST exit code, mobot_check.h):
//              checksums, sequence order, New exactly once
//   liveness   no trap, no unmapped access, no controller error; every
//              live board kept calling the driver into the last quarter of
//              the run, and with --require-done (no crash) every board
//              reported done (its quotas met, sim/firmware/mobot_check.h)
//              (not judged once a core failed its own check: that board
//              stopped and starves its consumers; cpu reports it)
//   freshness  the same runs as age (the paper's actuality): a consumer's
//              Import of a copy channel that began (its first load of the
//              control word) after its producer's newest value had been the
//              newest for longer than the bound in force (latency with
//              retries, by mode) returns that value or a newer one: taken_at
//              at or after that value's Actual store.  A crashed producer's
//              last value included (its channel's ages are not judged), as is
//              a destination never published (judge_fresh, mobot_sim_ages.cpp)
//   age        runs without faults (and no core failed its check): every age <= bound, where the bound of a copy
//              channel is the compiler's latency (with retries) plus the
//              producer's longest measured gap between two Actual stores,
//              and of a time/status channel the compiler's age bound; with
//              modes, the bound in force (sim/mobot_sim_modes.cpp: after a
//              switch, and after a channel comes back, the bound before it
//              plus the time since)
//   staleness  navigation reports RadarMap stale (MOBOT_EV_STALE) after a
//              radar crash (unless a core failed its own check), and, on a
//              fault-free bus, never before it and never without one
//   faults     with faults injected, the controller's STATUS (read by the
//              navigation core) counts retries; the share of accesses
//              faulted is R within the statistical tolerance of
//              tb/common/fault_model.h
//   clock      runs without faults, boards whose firmware has the local
//              clock (MOBOT_EV_CLOCK): every estimate with the rate known
//              lies within the board's lag and lead bounds of the
//              controller's time at its TIMER read, and the rate is known
//              after four windows (sim/mobot_sim_clock.cpp)
//   mode       a description with schedule modes (sim/mobot_sim_modes.cpp):
//              every switch follows a request, within the compiler's
//              switch_latency of the mode it leaves (runs without faults),
//              and reaches navigation as Mode {mode, the switch's time};
//              every Mode value imported names a switch; at least
//              --min-switches switches.  The other checks judge each age by
//              the bound of the mode in force, and staleness expects
//              RadarMap stale in each long stay of a mode without it
//   termination    every three-buffer Import the compiler bounded (report.txt
//              beside the plan: [board] timing in the description) whose
//              loop kept within the compiler's T and V makes at most its
//              max_passes ReadLocked stores and max_accesses RAM accesses,
//              an Import still running at the end counted with its passes so
//              far; without --stall every Import is judged and one whose
//              loop exceeds T or V fails too (sim/mobot_sim_ages.cpp)
// Exit status 0 = verdict pass, 1 = fail, 2 = bad arguments.
// The command line is parsed in sim/mobot_sim_options.cpp, the --ages CSV
// written by sim/mobot_sim_ages.cpp, local time judged and reported by
// sim/mobot_sim_clock.cpp; sim/mobot_sim.h holds what they share.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include "Vpico_boards.h"
#include "fault_model.h"
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include "report.h"
#include "mobot_sim.h"

int main(int argc, char **argv)
{
    Options o;
    Plan plan;
    std::vector<std::string> expect;  // --expect-caught-by a,b: every one of them fails, no other
    if (const int rc = parse_options(argc, argv, o, plan, expect); rc >= 0) return rc;

    // What the plan says: one series per channel and consumer, one producer per copy channel.
    std::vector<Series> series;
    std::map<int, Producer> producers;  // by channel id
    for (const PlanChannel &c : plan.channels) {
        for (const PlanDest &d : c.dests) {
            Series s;
            s.ch = &c;
            s.board = d.board;
            s.base = d.base;
            series.push_back(s);
        }
        if (c.copy()) producers[c.id].ch = &c;
    }
    // The guaranteed age: a copy channel's latency (with retries) plus its
    // producer's longest gap between Actual stores so far; time/status: the
    // compiler's age bound.
    auto age_bound = [&](const Series &s) -> uint64_t {
        return s.ch->copy() ? s.ch->latency_retry + producers[s.ch->id].max_gap : s.ch->latency_retry;
    };
    // --age-samples: every imported age, with the producer's longest gap
    // between Actual stores so far (copy channels; the age bound's slack).
    std::FILE *samples = nullptr;
    if (!o.age_samples.empty()) {
        samples = std::fopen(o.age_samples.c_str(), "w");
        if (!samples) { std::fprintf(stderr, "mobot_sim: cannot write %s\n", o.age_samples.c_str()); return 2; }
        std::fprintf(samples, "channel,board,cycle,age,producer_gap\n");
    }
    auto find_series = [&](int board, uint32_t id) -> Series * {
        for (Series &s : series)
            if (s.board == board && uint32_t(s.ch->id) == id) return &s;
        return nullptr;
    };
    // Import termination: the compiler's bounds, and each core's instances (word ranges) it imports from.
    const int n_term = load_termination(o.plan, series, plan);
    struct Range { uint32_t first, end; Series *s; };
    std::vector<Range> ranges[NB];
    for (Series &s : series)
        ranges[s.board].push_back({s.base / 4, s.base / 4 + 1 + 3 * s.ch->dest_size() / 4, &s});
    bool seen_event[NB] = {false, false, false, false};
    const uint64_t n_buckets = std::min<uint64_t>(800, o.cycles);
    const uint64_t bucket_len = (o.cycles + n_buckets - 1) / n_buckets;
    for (Series &s : series) s.bucket_max.assign(n_buckets, 0), s.bucket_bound.assign(n_buckets, 0);
    ModeTrack modes;  // schedule modes (sim/mobot_sim_modes.cpp)
    modes.plan = &plan;

    // The boards' clock drift: board_memmap's +drift<c>=PPM plusargs.
    std::vector<std::string> vargs(argv, argv + argc);
    for (int c = 0; c < NB; ++c)
        if (o.drift_ppm[c]) vargs.push_back("+drift" + std::to_string(c) + "=" + std::to_string(o.drift_ppm[c]));
    if (o.mute_board >= 0) {
        vargs.push_back("+mute_board=" + std::to_string(o.mute_board));
        vargs.push_back("+mute_word=" + std::to_string(o.mute_word));
    }
    std::vector<const char *> vargv;
    for (const std::string &a : vargs) vargv.push_back(a.c_str());
    Verilated::commandArgs(int(vargv.size()), vargv.data());
    auto m = std::make_unique<Vpico_boards>();
    // The wave's time base: clock cycles since power-up, reset included (two
    // time steps per cycle, one dump per step), so its times only grow; the
    // window [trace_from, trace_from + trace_cycles) counts cycles after reset,
    // and with trace_from 0 it also holds the reset and the state before the
    // first edge.
    uint64_t ticks = 0, cycle = 0;
    bool in_reset = true;
#if VM_TRACE
    std::unique_ptr<VerilatedVcdC> vcd;
    bool trace_done = false;
    if (!o.trace.empty()) {
        Verilated::traceEverOn(true);
        vcd = std::make_unique<VerilatedVcdC>();
        m->trace(vcd.get(), 99);
    }
    auto dump = [&](uint64_t time) {
        if (!vcd || trace_done) return;
        const bool want = in_reset ? o.trace_from == 0
                                   : cycle >= o.trace_from && cycle < o.trace_from + o.trace_cycles;
        if (!want) {
            if (vcd->isOpen()) { vcd->close(); trace_done = true; }  // the window is over
            return;
        }
        if (!vcd->isOpen()) vcd->open(o.trace.c_str());
        vcd->dump(time);
    };
#endif
    uint64_t rng = o.seed * 0x9E3779B97F4A7C15ull + 1;
    auto next = [&]() { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; return rng; };
    FaultModel fault_model(o.fault_rate, o.burst, o.seed ^ 0xFA17ull);

    uint64_t stall_left[NB] = {0, 0, 0, 0}, busy = 0, faults = 0, requests = 0;
    uint64_t first_access = ~0ull;   // the controller's first bus request (the end of its start-up)
    uint64_t fresh_from = ~0ull;     // check freshness judges values stored from its first cycle's end on
    uint32_t frozen = 0;
    auto tick = [&]() {
        uint32_t st = frozen;
        for (int c = 0; c < NB; ++c) {
            if (o.stall && stall_left[c] == 0 && next() % o.stall == 0) stall_left[c] = 1 + next() % 1024u;
            if (stall_left[c]) { --stall_left[c]; st |= 1u << c; }
        }
        m->stall_i = st;
        // A new request to a live board samples fi_kind at this edge: it
        // uses the drawn kind, and the next access gets the next draw.
        const bool drawn = m->fi_new_o && !m->fi_dead_o && !m->rst_i;
        if (drawn) {
            ++requests;
            if (m->fi_kind_i) ++faults;
        }
        busy += m->m_cyc_o;
        if (m->m_cyc_o && first_access == ~0ull) first_access = cycle, fresh_from = m->time_o + plan.cycle;
        m->clk_i = 1; m->eval();
#if VM_TRACE
        dump(2 * ticks + 1);
#endif
        m->clk_i = 0; m->eval();
#if VM_TRACE
        dump(2 * ticks + 2);
#endif
        ++ticks;
        ++cycle;
        // The next access's kind (per clock: the old, wrong driving, a negative test).
        if (drawn || o.fault_per_clock) m->fi_kind_i = fault_model.next() & 3u;
    };

    m->clk_i = 0;
    m->rst_i = 1;
    m->stall_i = 0;
    m->fi_kind_i = fault_model.next() & 3u;   // the first access's kind
    m->fi_dead_i = 0;
    m->eval();  // every clock low before the first edge
#if VM_TRACE
    dump(0);
#endif
    for (int i = 0; i < 8; ++i) tick();
    m->rst_i = 0;
    in_reset = false;
    cycle = 0; busy = 0; faults = 0; requests = 0; first_access = ~0ull; fresh_from = ~0ull;

    const uint32_t all = (1u << NB) - 1u;
    // The DPRAM's address width (the model's aw_o): the plan's RAM must fit it.
    const unsigned aw = m->aw_o;
    const uint32_t dp_words = 1u << aw, adr_mask = dp_words - 1u;
    if (aw < 2 || dp_words > uint32_t(DP_MAX_WORDS) || plan.ram_bytes > 4u * dp_words) {
        std::fprintf(stderr, "mobot_sim: the plan's ram_bytes %u does not fit the model's DPRAM of %u bytes "
                     "(ADDR_WIDTH %u; the harness tracks at most %d words)\n", plan.ram_bytes, 4u * dp_words, aw,
                     DP_MAX_WORDS);
        return 2;
    }
    static uint64_t last_load[NB][DP_MAX_WORDS];  // per core and DPRAM word: controller time of its last load
    // ... and of its first load since the core's last event (the start of a
    // four-slot Import: its value is at least as new as Actual then, not at its last load)
    static uint64_t first_load[NB][DP_MAX_WORDS];
    static bool first_seen[NB][DP_MAX_WORDS];
    bool clear_first[NB] = {false, false, false, false};  // an event came: a new Import starts
    uint64_t done_at[NB] = {0, 0, 0, 0}, last_event[NB] = {0, 0, 0, 0}, events[NB] = {0, 0, 0, 0};
    // crash state: armed at crash_at, begins with the next Export, fires after half its words
    int crash_phase = o.crash_board >= 0 ? 1 : 0;  // 1 armed, 2 in the Export, 3 crashed
    uint32_t crash_words = 0, crash_need = 0, crash_seq = 0;
    uint64_t crash_cycle = 0;
    const Producer *crash_prod = nullptr;
    // the board's first data channel by id (the radar: RadarMap, before its slow RadarScan);
    // not the mode request: it is not a data channel
    for (auto &p : producers)
        if (!crash_prod && p.second.ch->src_board == o.crash_board && p.second.ch->id != plan.mode_request)
            crash_prod = &p.second;
    if (o.crash_board >= 0 && !crash_prod)
        return usage(("--crash: board " + plan.board_names[o.crash_board] + " produces no copy channel").c_str());
    LocalClock clocks[NB];
    uint64_t stale_events = 0, stale_before_crash = 0, fresh_events = 0, first_stale = 0, status_reads = 0;
    uint64_t stale_after_crash = 0, first_stale_after_crash = 0;  // (a mode without RadarMap may report before)
    uint64_t stale_in_mode = 0;  // stale reports while the mode in force carries no such channel
    uint32_t status_retries = 0, status_abandoned = 0;

    std::printf("%s: %d boards (%s, %s, %s, %s), %llu cycles, seed %llu, fault rate %.2f%s%s%s\n", o.label.c_str(), NB,
                plan.board_names[0].c_str(), plan.board_names[1].c_str(), plan.board_names[2].c_str(),
                plan.board_names[3].c_str(), (unsigned long long)o.cycles, (unsigned long long)o.seed, o.fault_rate,
                o.crash_board >= 0 ? (", crash " + o.crash_arg).c_str() : "",
                o.hang_board >= 0 ? (", hang " + o.hang_arg).c_str() : "",
                o.mute_board >= 0 ? (", stores to " + o.mute_arg + "'s control word lost").c_str() : "");
    std::fflush(stdout);
    auto bad = [&]() { return (m->trap_o & all) || (m->bus_err_o & all) || m->error_o; };
    uint64_t next_progress = o.progress ? o.cycles / o.progress : ~0ull;
    while (cycle < o.cycles && !bad()) {
        if (o.hang_board >= 0 && cycle >= o.hang_at) frozen |= 1u << o.hang_board;
        tick();
        const uint64_t now = m->time_o;
        modes.observe(m->mode_o, now, cycle);
        for (int c = 0; c < NB; ++c) {
            if (clear_first[c]) std::fill(first_seen[c], first_seen[c] + dp_words, false), clear_first[c] = false;
            if (((m->done_o >> c) & 1u) && !done_at[c]) done_at[c] = cycle;
            if ((m->timer_rd_o >> c) & 1u) clocks[c].read(now, m->timer_o[c], cycle);  // a TIMER read completes
            const uint32_t adr = uint32_t(m->dp_adr_o >> (aw * c)) & adr_mask, sel = (m->dp_sel_o >> (4 * c)) & 0xfu;
            // a load: when a consumer read a control word (its Actual) last
            if (((m->dp_ack_o >> c) & 1u) && !((m->dp_we_o >> c) & 1u)) {
                last_load[c][adr] = now;
                if (!first_seen[c][adr]) first_load[c][adr] = now, first_seen[c][adr] = true;
            }
            if ((m->dp_ack_o >> c) & 1u)  // an access inside an Import (termination)
                for (Range &g : ranges[c])
                    if (adr >= g.first && adr < g.end)
                        g.s->term.access((m->dp_we_o >> c) & 1u, adr == g.first, sel, cycle);
            // a producer's store of Actual (byte 0 of its channel): port A write, lane 0
            if (((m->dp_ack_o >> c) & 1u) && ((m->dp_we_o >> c) & 1u)) {
                for (auto &pp : producers) {
                    Producer &p = pp.second;
                    if (p.ch->src_board != c) continue;
                    const uint32_t first = p.ch->src_base / 4, buf_first = first + 1;
                    if (adr == first && (sel & 1u)) {
                        if (p.ch->id == plan.mode_request) modes.request(now);
                        if (p.stores) p.max_gap = std::max(p.max_gap, cycle - p.last_store);
                        else p.first_store = cycle;
                        p.store_times.push_back(now);
                        p.last_store = cycle;
                        ++p.stores;
                    } else if (crash_phase == 2 && &p == crash_prod && adr >= buf_first &&
                               adr < buf_first + 3 * ((p.ch->size + 3) / 4)) {
                        if (++crash_words >= crash_need) {
                            frozen |= 1u << c;
                            crash_phase = 3;
                            crash_cycle = cycle;
                            std::printf("%s: cycle %llu: %s crashes inside Export %u of %s, after %u of %u words\n",
                                        o.label.c_str(), (unsigned long long)cycle, plan.board_names[c].c_str(),
                                        crash_seq, p.ch->name.c_str(), crash_words, p.ch->words);
                        }
                    }
                }
            }
            if (!((m->ev_valid_o >> c) & 1u)) continue;
            const uint32_t ev = m->ev_data_o[c], arg = m->ev_arg_o[c];
            const uint32_t kind = ev & 0xfu, id = (ev >> 4) & 0xfu, cyc = ev >> 8;
            ++events[c];
            last_event[c] = cycle;
            // termination: an Import's window ends at its event; every event starts the next windows
            if (kind == EV_NEW || kind == EV_OLD || kind == EV_ERROR)
                if (Series *s = find_series(c, id); s && seen_event[c]) s->term.import_done(o.term_scale, cycle, o.stall == 0);
            for (Range &g : ranges[c]) g.s->term.reset();
            seen_event[c] = true;
            clear_first[c] = true;
            if (kind == EV_NEW || kind == EV_OLD) {
                Series *s = find_series(c, id);
                if (!s) continue;
                // the age's reference: the Import's last load of Actual (three-buffer: the
                // confirming load) or its first (four-slot: actuality holds from the Import's start)
                const uint32_t w = s->base / 4;
                const uint64_t t_load = s->ch->four_slot && first_seen[c][w] ? first_load[c][w] : last_load[c][w];
                // taken_at 0 is the RAM image's value (or nothing yet): the controller has not
                // published (its values have taken_at >= its cycle 0 start > 0).  Before the
                // controller's first access and one cycle after it (every destination's first
                // slot; the system test starts its measurements there too) its age runs from
                // reset through the controller's start-up, which the compiler's bounds do not
                // include: no age sample.  Later it is judged like any value (age = t_load), so
                // a destination that is never published still fails the bound.
                const bool starting = arg == 0 && (first_access == ~0ull || t_load < first_access + plan.cycle);
                if (!starting) {
                    const uint64_t age = t_load > arg ? t_load - arg : 0;
                    s->age.add(age);
                    if (samples)
                        std::fprintf(samples, "%s,%d,%llu,%llu,%llu\n", s->ch->name.c_str(), c, (unsigned long long)cycle,
                                     (unsigned long long)age,
                                     (unsigned long long)(s->ch->copy() ? producers[s->ch->id].max_gap : 0));
                    const uint64_t k = std::min<uint64_t>(cycle / bucket_len, n_buckets - 1);
                    s->bucket_max[k] = std::max(s->bucket_max[k], age);
                    // the bound in force at the load: the mode's, the producer's longest gap so far
                    uint64_t bound = 0;
                    const uint64_t gap = s->ch->copy() ? producers[s->ch->id].gap_so_far(cycle) : 0;
                    int how = 0;
                    if (modes.bound_at(*s->ch, gap, t_load, bound, &how)) {
                        // (every channel of a crashing producer's board counts toward no verdict: its ages grow)
                        s->judge(age, bound, k, o.age_scale, crash_prod && s->ch->src_board == crash_prod->ch->src_board,
                                 how == 2);
                        s->settling += how == 1;
                        s->comeback += how == 2;
                    } else
                        ++s->unjudged;
                }
                // freshness: from the Import's start (its first load of Actual since the last event)
                if (s->ch->copy() && first_access != ~0ull)
                    judge_fresh(*s, producers[s->ch->id], modes, plan.board_names[c], first_seen[c][w] ? first_load[c][w] : t_load,
                                arg, fresh_from);
                s->import_cycles.add(cyc);
                if (s->last_import) s->max_import_gap = std::max(s->max_import_gap, cycle - s->last_import);
                s->last_import = cycle;
                if (kind == EV_NEW && s->ch->kind == "time") clocks[c].new_time(cycle);  // the board's clock syncs
                if (kind == EV_NEW) {
                    ++s->news;
                    if (crash_phase == 3 && crash_prod && s->ch == crash_prod->ch) ++s->news_after_crash;
                } else {
                    ++s->olds;
                }
            } else if (kind == EV_BEGIN && crash_phase == 1 && c == o.crash_board && cycle >= o.crash_at &&
                       id == uint32_t(crash_prod->ch->id)) {
                crash_phase = 2;
                crash_words = 0;
                crash_need = std::max<uint32_t>(1, crash_prod->ch->words / 2);
                crash_seq = arg;
            } else if (kind == EV_EXPORT) {
                auto it = producers.find(int(id));
                if (it != producers.end() && it->second.ch->src_board == c) {
                    ++it->second.exports;
                    it->second.export_cycles.add(cyc);
                }
            } else if (kind == EV_MODE) {
                modes.published(int(id), arg);
            } else if (kind == EV_STALE) {
                if (!stale_events++) first_stale = cycle;
                if (crash_phase == 3 && !stale_after_crash++) first_stale_after_crash = cycle;
                // stale as planned: a mode without the channel was in force within the
                // consumer's view of it (two of its Import gaps and a cycle before now)
                const Series *ss = find_series(c, id);
                const uint64_t look = ss ? 2 * ss->max_import_gap + 2 * plan.cycle : 0;
                if (ss && modes.absent_during(int(id), now > look ? now - look : 0, now)) ++stale_in_mode;
                else if (crash_phase != 3) ++stale_before_crash;
            } else if (kind == EV_FRESH) {
                ++fresh_events;
            } else if (kind == EV_CLOCK) {  // id: alb_clock_state, ARG: the estimate at the last TIMER read
                clocks[c].estimate(id, cyc, arg, cycle);
            } else if (kind == EV_STATUS) {
                ++status_reads;
                status_retries = arg;
                status_abandoned = cyc;
            }
        }
        if (cycle >= next_progress) {
            uint64_t worst_pm = 0;  // worst age / bound in force so far, per mille (not the crashed producer's channel)
            for (const Series &s : series) worst_pm = std::max(worst_pm, s.worst_pm);
            std::printf("  [%3llu%%] cycle %9llu  exports", (unsigned long long)(100 * cycle / o.cycles),
                        (unsigned long long)cycle);
            for (auto &p : producers) std::printf(" %s %llu", p.second.ch->name.c_str(), (unsigned long long)p.second.exports);
            std::printf("  faults %llu  worst age/bound %.3f\n", (unsigned long long)faults, worst_pm / 1000.0);
            std::fflush(stdout);
            next_progress += o.cycles / o.progress;
        }
    }
#if VM_TRACE
    if (vcd && vcd->isOpen()) vcd->close();
#endif

    if (samples) std::fclose(samples);
    // ---- bounds and checks ----
    for (Series &s : series) {
        const PlanChannel &c = *s.ch;
        s.bound = age_bound(s);  // the start-up mode's (each sample was judged by the one in force)
        (void)c;
    }
    std::map<std::string, std::string> failed;  // check -> first failure
    auto fail = [&](const char *check, const std::string &msg) { if (!failed.count(check)) failed[check] = msg; };
    char b[512];
    const uint32_t done = m->done_o & all;
    uint32_t code[NB];
    for (int c = 0; c < NB; ++c) code[c] = m->code_o[c];
    const bool crash_run = o.crash_board >= 0;
    bool cpu_failed = false;  // a board stopped by its own check starves its consumers: left to cpu
    const BoardsAtEnd ends{done, m->trap_o & all, m->bus_err_o & all, {code[0], code[1], code[2], code[3]},
                           m->error_o != 0, m->rom_errors_o, {last_event[0], last_event[1], last_event[2], last_event[3]}};
    for (const auto &f : board_failures(ends, plan, o, cycle, cpu_failed)) fail(f.first.c_str(), f.second);
    // A crashed producer's channel is skipped; a stopped core's channels age too (left to cpu).
    const bool check_ages = o.fault_rate == 0 && o.hang_board < 0 && !cpu_failed;
    if (check_ages)
        for (const std::string &f : age_failures(series, plan, o)) fail("age", f);
    // Freshness (judge_fresh), on the same runs as the ages.
    uint64_t fresh_judged = 0, fresh_late = 0;
    for (const Series &s : series) {
        fresh_judged += s.fresh_judged;
        fresh_late += s.fresh_late;
        if (check_ages && s.fresh_late) fail("freshness", s.fresh_first);
    }
    std::printf("  freshness: %llu Imports began after a value had been its producer's newest for longer than the "
                "bound, %llu of them returned an older one%s\n", (unsigned long long)fresh_judged,
                (unsigned long long)fresh_late, check_ages ? "" : " (not judged: faults, a hang or a failed core)");
    if (crash_run && crash_phase != 3) {
        std::snprintf(b, sizeof b, "expected %s to crash inside an Export after cycle %llu, it never did "
                      "(no Export began)", plan.board_names[o.crash_board].c_str(), (unsigned long long)o.crash_at);
        fail("liveness", b);
    }
    // Local time: every estimate with the rate within its bounds (sim/mobot_sim_clock.cpp).
    clock_bounds(clocks, series, plan);
    for (int c = 0; c < NB; ++c) {
        std::string msg;
        if (check_ages && !(crash_run && c == o.crash_board) && !clock_verdict(clocks[c], c, o, plan, cycle, msg))
            fail("clock", msg);
    }
    // Import termination (sim/mobot_sim_ages.cpp).
    for (const std::string &f : termination_failures(series, plan, o, cycle, seen_event)) fail("termination", f);
    const bool radar_crash = crash_run && crash_phase == 3 && crash_prod->ch->name == "RadarMap";
    if (radar_crash && stale_after_crash == 0 && !cpu_failed)
        fail("staleness", "expected navigation to report RadarMap stale after the radar crashed, it never did");
    if (stale_before_crash && faults == 0) {
        std::snprintf(b, sizeof b, "expected no stale RadarMap %s, navigation reported it %llu times",
                      crash_run ? "before the crash" : "without a crash", (unsigned long long)stale_before_crash);
        fail("staleness", b);
    }
    // Schedule modes: check mode and the modes' part of staleness (sim/mobot_sim_modes.cpp).
    // Navigation reports RadarMap stale at its first Import after the map's age
    // passes MOBOT_RADAR_SCAN_CLOCKS + the latency (sim/firmware/mobot_check.h:
    // 20,000 clocks, 100,000 in a build with the slow channels): a stay without
    // it longer than that and two of navigation's longest gaps between those
    // Imports must see a report (at least 50,000 clocks).
    uint64_t long_run = 50000;
    if (const PlanChannel *rm = plan.by_name("RadarMap"))
        for (const Series &s : series)
            if (s.ch == rm)
                long_run = std::max<uint64_t>(long_run, (plan.by_name("RadarScan") ? 100000 : 20000) +
                                                            rm->latency_retry + 2 * s.max_import_gap);
    for (const auto &f : modes.verdict(o, cycle, m->time_o, check_ages, cpu_failed, stale_in_mode,
                                       crash_phase == 3 ? crash_cycle : 0, long_run))
        fail(f.first.c_str(), f.second);
    // The injected rate per access against the nominal one (tb/common/fault_model.h).
    const double rate_measured = requests ? double(faults) / double(requests) : 0;
    const double rate_tol = fault_model.tolerance(requests);
    const bool rate_ok = std::fabs(rate_measured - o.fault_rate) <= rate_tol;
    if (!rate_ok) {
        std::snprintf(b, sizeof b, "expected a fault rate of %.4f +- %.4f per access, got %.4f (%llu of %llu accesses "
                      "faulted)", o.fault_rate, rate_tol, rate_measured, (unsigned long long)faults,
                      (unsigned long long)requests);
        fail("faults", b);
    }
    if (faults && status_retries == 0) {
        std::snprintf(b, sizeof b, "expected STATUS to count retries after %llu injected faults, navigation read "
                      "%llu STATUS values with 0 retries", (unsigned long long)faults, (unsigned long long)status_reads);
        fail("faults", b);
    }

    // ---- report ----
    std::printf("\n%s: %llu cycles (%.2f ms at %.0f MHz), controller time %u, bus busy %.1f %%, "
                "%llu requests, %llu faults injected, STATUS: %u retries, %u abandoned\n",
                o.label.c_str(), (unsigned long long)cycle, 1e3 * double(cycle) / plan.clock_hz, plan.clock_hz / 1e6, m->time_o,
                cycle ? 100.0 * double(busy) / double(cycle) : 0.0, (unsigned long long)requests,
                (unsigned long long)faults, status_retries, status_abandoned);
    std::printf("  fault rate per access: nominal %.4f, measured %.4f (mean burst %.3g accesses; tolerance +-%.4f, "
                "%.0f sigma)%s\n", o.fault_rate, rate_measured, fault_model.mean_burst(), rate_tol,
                FaultModel::kSigmas, rate_ok ? "" : ": OUT OF TOLERANCE");
    JsonReport r;
    r.str("label", o.label).num("seed", double(o.seed)).num("cycles", double(cycle)).num("clock_hz", plan.clock_hz)
     .num("fault_rate", o.fault_rate).num("faults_injected", double(faults)).num("requests", double(requests))
     .num("burst", o.burst).num("fault_mean_burst", fault_model.mean_burst())
     .num("fault_rate_measured", rate_measured).num("fault_rate_tolerance", rate_tol).num("fault_rate_ok", rate_ok ? 1 : 0)
     .num("status_retries", status_retries).num("status_abandoned", status_abandoned)
     .num("bus_busy_fraction", cycle ? double(busy) / double(cycle) : 0.0)
     .str("muted", o.mute_arg).str("crash_board", crash_run ? plan.board_names[o.crash_board] : "").num("crash_cycle", double(crash_cycle))
     .num("stale_events", double(stale_events))
     .num("first_stale_cycle", double(crash_run ? first_stale_after_crash : first_stale))
     .num("fresh_events", double(fresh_events)).num("stale_in_mode", double(stale_in_mode))
     .num("freshness_judged", double(fresh_judged)).num("freshness_late", double(fresh_late));
    if (!plan.modes.empty()) {  // the switches, printed and in the report
        uint64_t worst = 0, worst_bound = 0;
        modes.summary(stale_in_mode, worst, worst_bound);
        r.raw("mode_switches", modes.report("    "))
         .num("switch_latency_worst", double(worst)).num("switch_latency_bound", double(worst_bound));
    }
    r.raw("series", series_report(series, plan)).num("termination_bounded_series", n_term);
    if (n_term) print_termination(series, plan, o);
    else std::printf("  Import termination: no bounds (the description has no [board] timing): not checked\n");
    r.raw("producers", producers_report(producers, plan));
    for (int c = 0; c < NB; ++c) {
        std::printf("  board %d %-10s %s%s, exit code 0x%x (%s), %llu events\n", c, plan.board_names[c].c_str(),
                    (done >> c & 1u) ? "done at cycle " : "not done", (done >> c & 1u) ? std::to_string(done_at[c]).c_str() : "",
                    code[c], code_text(code[c], plan).c_str(), (unsigned long long)events[c]);
        r.num((plan.board_names[c] + "_done_cycle").c_str(), double(done_at[c]))
         .num((plan.board_names[c] + "_code").c_str(), code[c]);
    }
    r.raw("local_time", clock_report(clocks, o, plan));
    if (crash_run) {
        uint64_t after = 0;
        for (const Series &s : series) after += s.news_after_crash;
        std::printf("  crash: %s at cycle %llu; its consumers imported %llu New values after it (completed before "
                    "it); navigation reported RadarMap stale %llu times after it, first at cycle %llu (%lld clocks after the "
                    "crash)\n", plan.board_names[o.crash_board].c_str(), (unsigned long long)crash_cycle,
                    (unsigned long long)after, (unsigned long long)stale_after_crash,
                    (unsigned long long)first_stale_after_crash,
                    stale_after_crash ? (long long)first_stale_after_crash - (long long)crash_cycle : 0ll);
    }

    if (!o.ages.empty() &&  // the picture's data: worst age per bucket and series
        !write_ages(o.ages, series, plan, n_buckets, bucket_len, cycle, crash_cycle,
                    crash_run ? first_stale_after_crash : first_stale))
        return 1;

    std::string last;
    std::vector<std::string> lines;
    const std::string verdict = judge(failed, expect, o.expect.empty(), last, lines);
    r.raw("checks", checks_report(failed)).str("expect_caught_by", o.expect).str("verdict", verdict);
    if (!o.report.empty() && !r.write(o.report)) return 1;
    for (const std::string &l : lines) std::printf("  %s\n", l.c_str());
    std::printf("%s: %s\n", o.label.c_str(), last.c_str());
    return verdict == "pass" ? 0 : 1;
}
