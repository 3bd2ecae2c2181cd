// rom_scenario.h -- tb_system --flip-rom-bit WORD:BIT: the schedule ROM image
// with one bit flipped before start-up.  The start-up CRC pass must refuse
// it: the controller raises error_o and never starts a slot, so it makes no
// bus access and publishes nothing; the CPUs run on (their Imports return
// the RAM image's values, Old).  The run's usual expectations (a value
// published at every destination, STATUS read, error_o low) give way to
// these (a controller that skipped the check runs the image: its accesses
// fail the run).
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "plan.h"
#include "system_checker.h"
#include "system_sim.h"

namespace tbsys {

// A copy of the ROM image file rom with bit BIT of word WORD flipped, in a
// temporary file (removed at exit): its path, or "" with err set.
std::string flip_rom_bit(const std::string &rom, int word, int bit, std::string &err);

// The verdict of a run on a flipped image: the failures the refusal makes
// (no value published, STATUS never read, error_o) are expected and left
// out of failures; the refusal's own expectations are added.
void rom_refused_verdict(const Plan &plan, const SystemChecker &chk, SystemSim &sim, std::vector<std::string> &failures);

}  // namespace tbsys
