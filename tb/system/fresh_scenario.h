// fresh_scenario.h -- the producers' side of tb_system's freshness scenarios
// (the check itself: SystemChecker::tick, system_freshness.cpp):
//   --producer-stop CH:CYCLE      channel CH's producer (CH "all": every copy
//                                 channel's but the mode request's) exports
//                                 nothing from CYCLE on: its last value must
//                                 reach every destination within the bound;
//                                 the run fails unless each such destination
//                                 had a value judged (fault-free runs);
//   --producer-interval CH:CLOCKS:BURST  (board_program) BURST Exports back
//                                 to back every CLOCKS clocks;
//   --stretch-export CH:CLOCKS    CH's producer idles CLOCKS before the store
//                                 that completes each value (four-slot: its
//                                 Slot store; three-buffer: its Actual store),
//                                 so that the controller's takes overtake its
//                                 Exports (a take between the Export's
//                                 ReadLocked load and that store): the run
//                                 fails on fewer than 3 Exports overtaken.
// With bursts of two, stretched, the second value is completed in the pair
// the controller locks while the Export runs: a four-slot Import that
// answers Old on Actual's pair alone skips it, and the pause withholds it.
#pragma once
#include <string>
#include <vector>
#include "board_program.h"
#include "plan.h"
#include "system_checker.h"
#include "system_sim.h"

namespace tbsys {

// Checks the options against the plan and installs the Export stretch on
// the producer's CPU: false with a message on bad input.
bool fresh_setup(const Plan &plan, const Options &o, SystemSim &sim, std::string &err);

// Channel c's producer has stopped at cycle now (--producer-stop).
bool producer_stopped(const Plan &plan, const Options &o, const PlanChannel &c, uint64_t now);

// After the run: the scenario's own failures, the console lines and the
// report's "freshness" array (per destination: values judged, late; per
// channel: Exports overtaken).
void fresh_report(const Plan &plan, const Options &o, const SystemChecker &chk, bool judged,
                  std::vector<std::string> &failures, std::string &json);

}  // namespace tbsys
