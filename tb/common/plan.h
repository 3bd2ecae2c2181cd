// plan.h -- what the testbench knows of a compiled schedule: boards,
// channels, where each instance lives, and the compiler's bounds.  Read from
// tb_plan.txt, which tb/common/plan_for_tb.py writes from the compiler's
// report.json (one line per fact, so the C++ side needs no JSON parser):
//
//   system <boards> <cycle_clocks> <rigid|sync> <n_chan> <ram_bytes>
//   clock <hz>                                the controller's clock
//   board <index> <name>                      (in index order)
//   channel <id> <name> <copy|time|status> <size> <words> <src_board> <src_base>
//           <period> <latency> <latency_with_retries> <sync> <slots> [<four_slot>]
//   dest <id> <index> <board> <base>
//   mode <index> <name> <cycle_clocks> <switch_latency> [<at_target>]   (a description with
//                                             modes; at_target: the switch latency that holds with
//                                             the fault hypothesis' probability, 0: none)
//   mode_request <id>                         the channel whose values ask for a mode
//   mode_info <id>                            the channel the controller publishes {mode, since} on
//   mode_channel <mode> <id> <period> <bound> <bound_with_retries>   a channel the mode
//                                             carries: its guaranteed period and latency (copy)
//                                             or age bound, fault-free and with retries
//
// Sizes and bases in bytes, times in controller clocks; src_board is -1 for
// channels the controller produces.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "albatross_contract.h"   // the channel layout (generated, make contract)

struct PlanDest {
    int board = 0;
    uint32_t base = 0;
};

struct PlanChannel {
    int id = 0;
    std::string name, kind;
    uint32_t size = 0, words = 0;
    int src_board = -1;
    uint32_t src_base = 0;
    uint64_t period = 0, latency = 0, latency_retry = 0;
    bool sync = false;
    bool four_slot = false;  // the four-slot kind (docs/four_slot.md)
    int slots = 0;
    std::vector<PlanDest> dests;

    bool copy() const { return kind == "copy"; }
    // Bytes of the destination payload: the value's words and taken_at.
    uint32_t dest_size() const { return alb_contract::dest_bytes(words); }
    // Byte offset of taken_at in a destination payload.
    uint32_t taken_at_offset() const { return alb_contract::taken_at_offset(words); }
};

// One schedule mode (docs/compiler.md "Modes"); index 0 is the start-up mode.
struct PlanMode {
    std::string name;
    uint64_t cycle = 0, switch_latency = 0;  // its cycle; worst request -> first cycle of the next
    uint64_t switch_latency_at_target = 0;   // ... under the plan's fault hypothesis (0: none)
    std::vector<uint64_t> bound;             // by channel id: latency/age bound with retries, 0 = absent
    std::vector<uint64_t> bound_ff;          // ... fault-free
    bool carries(int id) const { return id >= 0 && id < int(bound.size()) && bound[id] != 0; }
};

struct Plan {
    int boards = 0, n_chan = 0;
    uint64_t cycle = 0;
    bool sync_mode = false;
    uint32_t ram_bytes = 0;
    double clock_hz = 50e6;                // controller clock (from the description)
    std::vector<std::string> board_names;  // by index
    std::vector<PlanChannel> channels;
    std::vector<PlanMode> modes;           // empty: one schedule, no modes
    int mode_request = -1;                 // the mode_request channel's id (-1: none)
    int mode_info = -1;                    // the mode channel's id: {mode, since} (-1: none)

    // Reads tb_plan.txt; on error returns false with a message naming the line.
    bool load(const std::string &path, std::string &error);
    const PlanChannel *by_name(const std::string &name) const;
};
