// system_modes.h -- schedule modes in tb_system (a plan with [[mode]]
// tables, docs/compiler.md "Modes"): the mode_request channel's producer asks
// for a random mode at random times (a declared one, or now and then one the
// image does not have), and ModeWatch follows the controller's running mode
// (the probe mode_o of tb/system/tb_system.v) to judge every switch:
//   boundary   each switch falls on a cycle boundary of the mode it leaves:
//              its time minus the previous switch's (the start-up mode: the
//              time its first cycle began, as Mode publishes it) is a whole
//              number of that mode's cycles (time-rigid plans);
//   request    each switch to mode m follows a store of a request for m,
//              within the compiler's switch_latency of the mode it leaves
//              (fault-free runs), or within its switch_latency_at_target
//              (runs with faults on an image planned for a fault hypothesis;
//              without one, measured only);
//   published  every Mode value a board imports is {the start-up mode, its
//              first cycle} or {m, the time of a switch to m};
//   rejected   STATUS counts at most one corrupt value per request for an
//              undeclared mode; on a fault-free bus exactly the rejections
//              made before the slot of the last STATUS value a CPU read
//              (its taken_at): a request the controller took (a New Import
//              of the request source, SystemChecker's take) for a mode the
//              image does not declare, while no switch was pending (a
//              request taken while a switch is loaded is ignored, not
//              rejected; every declared mode may switch to every other, as in
//              sim/mobot3_modes.toml).
// It also gives SystemChecker the bounds of the mode in force.  A value from
// 'from' (a copy's publication, a time/status value's take) measured at 'to'
// with no switch between: the bound of the mode in force.  Across switches,
// the last at S: the value had not arrived by S, and the mode whose first
// cycle starts at S delivers what its source holds within its bound, so
// the bound is S - from + that mode's bound.  A mode without the channel
// at 'to' is not judged (its consumers see the value age: stale).
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <vector>
#include "plan.h"
#include "system_sim.h"

namespace tbsys {

class ModeWatch {
public:
    ModeWatch(const Plan &plan, SystemSim &sim);
    bool active() const { return !plan_.modes.empty() && plan_.mode_request >= 0; }
    // The request producer: the mode to ask for next, and the wait after it.
    uint32_t pick(std::mt19937_64 &rng);
    uint64_t interval(std::mt19937_64 &rng) const;
    void requested(uint32_t mode) { pending_ = mode; }     // just before its Export
    void tick();                                           // after every sim.tick()
    void mode_imported(int board, uint32_t mode, uint32_t since);
    // The controller took a value of channel chan, in buffer b, at time t
    // (SystemChecker's take): a request it acts on, rejects or ignores.
    void taken(int chan, uint8_t b, uint32_t t);
    // A CPU read STATUS New: its taken_at, and the corrupt counts summed.
    void status_read(uint32_t taken_at, uint64_t corrupt);
    bool bound(int chan, uint64_t from, uint64_t to, uint64_t &b, uint64_t &b_retry) const;
    // The checks above; judge_latency: a fault-free run.
    void finish(bool judge_latency, uint64_t status_corrupt, std::vector<std::string> &failures) const;
    std::string json() const;                              // the report's "modes" object
    // Latencies run from the request, or from the start-up mode's first cycle
    // for a request stored during the controller's start-up.
    void settle();                                         // after the run, before finish and json
    uint64_t undeclared = 0;                               // requests stored for undeclared modes

private:
    struct Switch {
        uint64_t cycle = 0;
        uint32_t time = 0;
        int from = 0, to = 0;
        bool requested = false;
        uint32_t request = 0;              // the time of the last request for 'to'
        uint64_t latency = 0, bound = 0;   // request (or the first cycle, if later) -> time; switch_latency of 'from'
        uint64_t bound_at_target = 0;      // ... at the fault hypothesis' target (0: none)
    };
    struct Stored { uint32_t mode, time; };
    const Plan &plan_;
    SystemSim &sim_;
    int req_board_ = 0;
    uint32_t req_actual_ = 0;              // the request source's Actual byte address
    uint8_t last_actual_ = 0;
    uint32_t pending_ = 0;
    int mode_ = 0;
    uint64_t c_max_ = 0;
    std::vector<Stored> stores_;           // request values stored (their Actual store)
    std::vector<Switch> switches_;     // (latency: set by settle)
    bool have_t0_ = false;
    uint32_t t0_ = 0;                      // the start-up mode's first cycle (from Mode)
    uint64_t mode_values_ = 0, bad_values_ = 0;
    bool pending_switch_ = false;          // a declared request taken, its switch not yet made
    std::vector<uint32_t> rejected_;       // times of the takes of undeclared requests (rejections)
    bool status_seen_ = false;             // the last STATUS value read: its taken_at, its count
    uint32_t status_taken_ = 0;
    uint64_t status_corrupt_ = 0;
    mutable uint64_t judged_across_ = 0, unjudged_ = 0;   // bound(): values judged across a switch; not judged
    std::string first_bad_;
};

extern ModeWatch *g_modes;

}  // namespace tbsys
