// multirate_scenario.h -- what tb_system asks of a run on a multi-rate image
// with fragments (tools/mk/system.mk "Multi-rate"), beyond the checkers:
//   --require-fragments N      at least N values published after two or more
//                              runs, each judged (fragment_checker.h);
//   --require-fragments plan   N from the plan: the values it guarantees in
//                              the run's clocks for the channels whose values
//                              cannot go in one slot (fragment_checker.h
//                              values_over_runs);
//   --require-cut-fragments N  at least N runs of E7.frag != 0 entries cut
//                              short by faults (fewer words than planned and
//                              the value not ended, or a destination dropped
//                              for the rest of a value);
//   --bounds-at-target FILE    every consumer's largest latency (copy) or age
//                              (time, status) within its bound at the fault
//                              hypothesis' target (the compiler's report.json,
//                              channels[].consumers[].faults.age_bound.at_target,
//                              as tb/system/bounds_at_target.py writes it;
//                              scaled by --latency-scale as the plan's bounds).
#pragma once
#include <string>
#include <vector>
#include "board_program.h"
#include "fragment_checker.h"
#include "plan.h"
#include "system_checker.h"

namespace tbsys {

// Prints the fragment figures and adds the failures of the requirements
// above; frag: null when the run is not judged by fragment_checker.h.
void multirate_verdict(const Plan &plan, const Options &o, const SystemChecker &chk, const FragmentChecker *frag,
                       std::vector<std::string> &failures);

}  // namespace tbsys
