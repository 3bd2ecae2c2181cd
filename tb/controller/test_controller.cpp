// test_controller -- smoke test of albatross_controller on tb/system/tb_system.v.
//
// A small, self-checking test, not the system harness (tb/system/).  Each
// scenario writes its own schedule ROM (with its CRC) to ctrl_rom.hex, the
// file the model was built to $readmemh, then builds a fresh model.  The
// schedule runs on boards 0 and 1:
//   entry 0  COPY   channel 0: board 0 @0x010 (W = 3) -> board 1 @0x020
//   entry 1  TIME   channel 1: -> board 0 @0x040, board 1 @0x040
//   entry 2  STATUS channel 2: -> board 1 @0x080 (W = 1 + 2*N_CHAN)
// The CPU ports initialise the control bytes to 1.  A C++ producer on CPU port
// 0 writes values with the three-buffer protocol, and a C++ consumer on CPU
// port 1 imports them.  Scenarios:
//   basic    values, taken_at, Actual arrive; exact fault-free timing of COPY,
//            TIME and STATUS slots (every access against the formula in the
//            controller's header, start-up time T0 included); the access
//            sequence of a COPY; TIME value and STATUS counters
//   corrupt  entry 1 invalid (TIME with W = 2, CRC resealed): rom_errors counts
//            it each cycle, the other entries still run on time; a bit flipped
//            in an entry or the header (CRC not resealed): error_o, bus idle
//   faults   fault kinds 1, 2, 3 on single accesses are retried; an Actual store
//            that landed but timed out is not published twice
//   sync     position-synchronised mode: polls every POLL clocks after the last
//            entry; a new position starts the cycle, else H1 ends it
//   dead     a board's link is down for a whole cycle: the slots still start on
//            time, no access starts after its deadline, a dead destination is
//            dropped after two failed accesses and the others are still served
//   droprun  the same with the ROM's drop run H2 = 3: the dead
//            destination is tried 3 times in a row, then dropped
//   four     the COPY and TIME entries with E0 flag FOUR_SLOT, a C++
//            four-slot producer and consumer: exact timing and access sequence
//            (Import 3 + W / 1 access, Export W + 4 per destination), the
//            control bytes after each Export, New / Old, the consumer's fixed
//            access count, TIME on two four-slot destinations, STATUS counts;
//            a landed Actual store that timed out is seen by the next
//            control-word load (the 3-bit tried buffer) and not published twice; a fourth buffer past the
//            RAM and SYNC with FOUR_SLOT are invalid
//   abandon  a COPY whose Import ends without choosing (source dead) counts
//            the channel's stored need as abandoned (group 32: the state-RAM
//            write-back regression; negative controller-negative-stale_need)
//   cold     zeroed board RAMs (docs/protocol.md "Cold start"): a source
//            Actual of 0 ends the Import with nothing new, a destination
//            ReadLocked of 0 is Buffer1 (four-slot: pair 1, also with an Actual
//            copy in pair 1), no corrupt count in STATUS, and every value
//            arrives once the CPUs have run their init (group 2; negative
//            controller-negative-cold)
//   modes    an image with two modes and a REQUEST channel: a request
//            switches at the next cycle boundary, the new mode's first entry
//            starts the new cycle, a channel keeps its state (an unchanged
//            value is not New twice), a request for an unknown mode is
//            ignored and counted in STATUS, and a request switches back
//            (groups 1, 2, 4; ctrl_scenarios_modes.cpp; negatives
//            controller-negative-no_request, -forget_state)
//   deadline a dead source retried to the deadline in slots of 16 lengths
//            (every phase of the tries): no access begins after D-TIMEOUT-2
//            or ends after D, and some begins exactly there (group 16;
//            ctrl_scenarios_race.cpp; negative controller-negative-deadline_late)
//   race4    a four-slot value completed between the Import's two
//            control-word loads is the one taken, with the second load's
//            time (group 2; negative controller-negative-slot_first_load)
//   frag     a value over 3 runs (a slot too short for the whole): each run
//            at its word (0 after an Import, else the first word not yet
//            stored to the destination, from the stores seen), published
//            once, after its last word, whole; the source's lock held (no
//            control access) in the runs that go on; a failed run stores
//            nothing and the next goes on at the same word; a run cut off
//            keeps the words it stored; a first run cut before a word leaves
//            no value going on; a reset in the middle publishes nothing of
//            the cut value (group 2; ctrl_scenarios_frag.cpp; negatives
//            controller-negative-frag_publish_first, -frag_reimport,
//            -frag_wrong_word)
//   fragswitch  a mode switch while a value goes over several runs: the
//            value goes on whole when its channel next runs (in the new
//            mode, or back in the old one), at the first word not stored,
//            with the held source buffer and its first run's taken_at
//            (group 2; ctrl_scenarios_fragswitch.cpp; negative
//            controller-negative-fragswitch)
//   fragedge runs cut off in the value's publication (after its last word,
//            before its Actual store): the value is still published, once
//            and whole (group 2; ctrl_scenarios_frag.cpp; negative
//            controller-negative-frag_pub_cut)
// Each check prints what it expected and what it got.  Exit status 0 if all
// pass, else 64 + a bit mask of the failed groups (1 timing, 2 data, 4 rom,
// 8 faults, 16 dead, 32 abandon).  --inject=timing makes the timing checker expect one
// clock more (its negative test: it must fail with bit 1).
// Options: --dir=DIR (work directory for the ROM file, created)  --inject=timing
//          --scenario=NAME (default: all)
// Files: ctrl_bench.h/.cpp (checks, ROM builder, model wrapper, CPU protocol),
//        ctrl_scenarios_data.cpp (basic, corrupt, four), ctrl_scenarios_faults.cpp (faults, dead,
//        droprun, sync, abandon), ctrl_scenarios_cold.cpp (cold), ctrl_scenarios_modes.cpp (modes),
//        ctrl_scenarios_race.cpp (deadline, race4), ctrl_scenarios_frag.cpp (frag, fragedge),
//        ctrl_scenarios_fragswitch.cpp (fragswitch).
#include "ctrl_bench.h"

// ------------------------------------------------------------------ main
int main(int argc, char **argv) {
    g_argc = argc;
    g_argv = argv;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!std::strcmp(a, "--inject=timing")) g_inject_timing = true;
        else if (!std::strncmp(a, "--scenario=", 11)) only = a + 11;
        else if (!std::strncmp(a, "--dir=", 6)) {
            mkdir(a + 6, 0777);
            if (chdir(a + 6) != 0) {
                std::perror(a + 6);
                return 2;
            }
        }
        else {
            std::fprintf(stderr, "usage: %s [--dir=DIR] [--inject=timing] [--scenario=basic|corrupt|faults|dead|droprun|sync|four|abandon|cold|modes|deadline|race4|frag|fragswitch|fragedge]\n",
                         argv[0]);
            return 2;
        }
    }
    if (g_inject_timing) std::printf("injected: the timing checker expects every completion one clock late\n");
    struct { const char *name; void (*fn)(); bool by_name = false; } sc[] = {
        {"basic", scenario_basic}, {"corrupt", scenario_corrupt}, {"faults", scenario_faults}, {"dead", scenario_dead},
        {"droprun", scenario_droprun},
        {"sync", scenario_sync}, {"four", scenario_four}, {"abandon", scenario_abandon}, {"cold", scenario_cold},
        {"modes", scenario_modes}, {"deadline", scenario_deadline}, {"race4", scenario_race4},
        {"frag", scenario_frag}, {"fragswitch", scenario_fragswitch}, {"fragedge", scenario_fragedge}};
    for (auto &x : sc)
        if (only.empty() ? !x.by_name : only == x.name) x.fn();
    std::printf("test_controller: %u checks, %u failed%s\n", g_checks, g_fails,
                g_fails ? "" : " -- PASS");
    return g_fails ? 64 + (int)g_failed_groups : 0;
}
