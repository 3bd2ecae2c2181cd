# tools/mk/system.mk -- the multi-board system (tb/system/tb_system.v: the shared
# soc/albatross_system.v with every board's port A driven from C++, and the
# bus fault injector; harness in tb/system/):
# simulated CPUs run the C driver on every board, the RTL controller executes
# a schedule compiled from sim/mobot3*.toml, faults are injected on its bus.

SYS_DIR     := $(BUILD)/system
SYS_BIN     := $(SYS_DIR)/real/tb_system
SYS_HDR     := $(wildcard tb/system/*.h) $(wildcard tb/common/*.h) tb/common/port/alb_port_impl.h $(wildcard c-driver/*.h)
SYS_CYCLES  ?= 400000

# The harness is compiled once; only system_sim.cpp sees the Verilated model.
SYS_COMMON  := tb/system/tb_system.cpp tb/system/board_program.cpp tb/system/system_checker.cpp tb/system/system_modes.cpp \
               tb/system/system_freshness.cpp tb/system/fresh_scenario.cpp tb/system/rom_scenario.cpp \
               tb/system/tb_system_verdict.cpp tb/system/fragment_checker.cpp tb/system/multirate_scenario.cpp \
               tb/common/plan.cpp \
               tb/common/sim_cpu.cpp tb/common/ref_ram.cpp tb/common/protocol_checker.cpp
SYS_OBJS    := $(patsubst %.cpp,$(SYS_DIR)/obj/%.o,$(notdir $(SYS_COMMON))) $(SYS_DIR)/obj/driver.o
$(SYS_DIR)/obj/%.o: tb/system/%.cpp $(SYS_HDR)
	@mkdir -p $(@D)
	$(CXX) $(TB_CXXFLAGS) -Itb/system -c $< -o $@
$(SYS_DIR)/obj/%.o: tb/common/%.cpp $(SYS_HDR)
	@mkdir -p $(@D)
	$(CXX) $(TB_CXXFLAGS) -Itb/system -c $< -o $@
$(SYS_DIR)/obj/driver.o: c-driver/albatross.c $(SYS_HDR)
	@mkdir -p $(@D)
	$(CC) $(TB_CFLAGS) -c $< -o $@

# A model and its tb_system binary: $(1) = name, $(2) = extra -y library first.
# The real model's C++ is compiled with -O3 (the fault-rate runs are long); a
# mutant's with -O1 (its negative test runs well under a second: the build is
# most of its cost).
define sys_model
$(SYS_DIR)/$(1)/model/Vsys__ALL.a: $(RTL) $(RTL_INC) $(TB_RTL) soc/albatross_system.v $(2)
	@mkdir -p $$(@D)
	verilator --cc -O3 --prefix Vsys --top-module tb_system $(if $(2),-y $(dir $(2))) $(VLIB) \
	    -Mdir $$(@D) tb/system/tb_system.v
	$$(MAKE) -s -C $$(@D) -f Vsys.mk OPT_FAST=$(if $(filter real,$(1)),-O3,-O1) CXX="$$(CXX)" >/dev/null
$(SYS_DIR)/$(1)/tb_system: $(SYS_DIR)/$(1)/system_sim.o $(SYS_OBJS) $(SYS_DIR)/$(1)/model/Vsys__ALL.a \
        $(TB_DIR)/verilated.o
	$$(CXX) $$^ -pthread -o $$@
endef
# system_sim.cpp sees only the model's top class, Vsys.h: a mutant whose Vsys.h
# equals the real model's (the same ports: every mutant so far) links the real
# model's system_sim.o instead of compiling its own.
$(SYS_DIR)/real/system_sim.o: tb/system/system_sim.cpp $(SYS_HDR) $(SYS_DIR)/real/model/Vsys__ALL.a
	$(CXX) $(TB_CXXFLAGS) -Itb/system -I$(SYS_DIR)/real/model -c $< -o $@
$(SYS_DIR)/mutant-%/system_sim.o: tb/system/system_sim.cpp $(SYS_HDR) $(SYS_DIR)/mutant-%/model/Vsys__ALL.a \
        $(SYS_DIR)/real/system_sim.o
	if cmp -s $(SYS_DIR)/mutant-$*/model/Vsys.h $(SYS_DIR)/real/model/Vsys.h; then cp $(SYS_DIR)/real/system_sim.o $@; \
	else $(CXX) $(TB_CXXFLAGS) -Itb/system -I$(SYS_DIR)/mutant-$*/model -c $< -o $@; fi
$(eval $(call sys_model,real,))

# Controller mutants (tb/mutants/controller/*.sed applied to the real RTL):
# each system checker has a negative test that must catch one.
# Each .sed names the controller file it edits on its '# target:' line, and
# each of its substitutions must change that file (else the build fails); the
# mutated copy keeps the file name, so the model's -y finds it first.  Its
# folder is emptied first: a copy left from a target the mutant had before
# would shadow the real file.
CTRL_MUTANTS := $(patsubst tb/mutants/controller/%.sed,%,$(wildcard tb/mutants/controller/*.sed))
sys_mutant_target = $(shell sed -n 's/^# target: *//p' tb/mutants/controller/$(1).sed)
define sys_mutant
$(SYS_DIR)/mutant-src/$(1)/$(notdir $(call sys_mutant_target,$(1))): tb/mutants/controller/$(1).sed $(call sys_mutant_target,$(1))
	@rm -rf $$(@D) && mkdir -p $$(@D)
	sed -f $$< $(call sys_mutant_target,$(1)) > $$@
	@if cmp -s $$@ $(call sys_mutant_target,$(1)); then \
	    echo "controller mutant $(1) did not apply: $(call sys_mutant_target,$(1)) no longer has the line tb/mutants/controller/$(1).sed edits"; \
	    rm -f $$@; exit 1; fi
	@grep '^s' $$< | while IFS= read -r l; do \
	    if sed -e "$$$$l" $(call sys_mutant_target,$(1)) | cmp -s - $(call sys_mutant_target,$(1)); then \
	    echo "controller mutant $(1): its substitution $$$$l matches nothing in $(call sys_mutant_target,$(1))"; \
	    rm -f $$@; exit 1; fi; done
$(call sys_model,mutant-$(1),$(SYS_DIR)/mutant-src/$(1)/$(notdir $(call sys_mutant_target,$(1))))
endef
$(foreach m,$(CTRL_MUTANTS),$(eval $(call sys_mutant,$(m))))

# The testbench's view of a compiled schedule; a plan without redundancy.  The
# compiler outputs and the robot's firmware images are kept (make would delete
# them as intermediate files); named by their rules' patterns, so that make
# never takes a missing prerequisite for a deleted intermediate file.
.PRECIOUS: $(BUILD)/schedule/%-noredundancy/rom.hex \
           $(foreach b,$(PB_BOARDS),$(foreach d,fw fw-clock fw-clock-norate,$(PB_DIR)/%/$(d)/$(b).elf))
$(BUILD)/schedule/%/tb_plan.txt: $(BUILD)/schedule/%/rom.hex tb/common/plan_for_tb.py
	$(PYTHON) tb/common/plan_for_tb.py $(@D)/report.json $@
$(BUILD)/schedule/%-noredundancy/rom.hex: sim/%.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $< --out $(@D) --no-redundancy -q

SYS_RIGID   := $(BUILD)/schedule/mobot3
SYS_SYNC    := $(BUILD)/schedule/mobot3_possync
SYS_NORED   := $(BUILD)/schedule/mobot3-noredundancy
sys_run      = tools/run_test.sh system-$(1) $(SYS_BIN) --label system-$(1) --seed $(SEED) \
               --cycles $(SYS_CYCLES) --report $(REPORTS)/system_$(1).json

# Faults (tb/common/fault_model.h): --fault-rate R is the probability that
# a controller access (a new request to a live board) fails, drawn once per
# access; --burst L the mean run of faulted accesses (default independent).
# Every run prints and reports the nominal and the measured rate and fails if
# they differ by more than 6 sigma (corrected for the bursts' correlation).
TESTS += system-rigid system-possync system-faults-5 system-faults-5-noredundancy system-faults-15 \
         system-faults-20-burst-60 system-faults-20-burst-60-noredundancy system-faults-30-expect-fail \
         system-faults-50-expect-fail system-faults-negative-per-clock system-landed-stores \
         system-dead-board system-corrupt-rom system-corrupt-control

test-system-rigid: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,rigid) --plan $(SYS_RIGID)
test-system-possync: $(SYS_BIN) $(SYS_SYNC)/tb_plan.txt
	@$(call sys_run,possync) --plan $(SYS_SYNC)
test-system-faults-5: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-5) --plan $(SYS_RIGID) --fault-rate 0.05
test-system-faults-5-noredundancy: $(SYS_BIN) $(SYS_NORED)/tb_plan.txt
	@$(call sys_run,faults-5-noredundancy) --plan $(SYS_NORED) --fault-rate 0.05
test-system-faults-15: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-15) --plan $(SYS_RIGID) --fault-rate 0.15
test-system-faults-20-burst-60: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-20-burst-60) --plan $(SYS_RIGID) --fault-rate 0.2 --burst 60
test-system-faults-20-burst-60-noredundancy: $(SYS_BIN) $(SYS_NORED)/tb_plan.txt
	@$(call sys_run,faults-20-burst-60-noredundancy) --plan $(SYS_NORED) --fault-rate 0.2 --burst 60
# A known limit, kept visible: at 30 % and 50 % independent faults
# per access the unchanged controller never delivers RadarMap and/or Status to
# board 2 (a destination is dropped for the rest of its slot after two failed
# accesses).  These pass while exactly that happens -- no checker violation,
# the rate within tolerance, no other failure -- and fail once the drop rule
# delivers them: then they become ordinary tests.
SYS_XFAIL := --expect-failure "no value was ever published" --expect-failure "STATUS: "
test-system-faults-30-expect-fail: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-30-expect-fail) --plan $(SYS_RIGID) --fault-rate 0.3 $(SYS_XFAIL)
test-system-faults-50-expect-fail: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-50-expect-fail) --plan $(SYS_RIGID) --fault-rate 0.5 $(SYS_XFAIL)
# The robot planned for the rate it meets (--faults; retry
# budgets and the drop run K in ROM H2 from the hypothesis, docs/compiler.md
# "Fault hypothesis"): 20 and 30 % independent faults planned for probability
# 1 - 1e-9 (K = 16, 21), 50 % for 0.99 (the robot's 50 us channels cannot
# promise more at 50 %; K = 12).  Every channel delivered, nothing torn,
# nothing New twice, every value exact.
TESTS += system-faults-20-planned system-faults-30-planned system-faults-50-planned
test-system-faults-20-planned: $(SYS_BIN) $(BUILD)/schedule/mobot3-f20/tb_plan.txt
	@$(call sys_run,faults-20-planned) --plan $(BUILD)/schedule/mobot3-f20 --fault-rate 0.2
test-system-faults-30-planned: $(SYS_BIN) $(BUILD)/schedule/mobot3-f30/tb_plan.txt
	@$(call sys_run,faults-30-planned) --plan $(BUILD)/schedule/mobot3-f30 --fault-rate 0.3
test-system-faults-50-planned: $(SYS_BIN) $(BUILD)/schedule/mobot3-f50p2/tb_plan.txt
	@$(call sys_run,faults-50-planned) --plan $(BUILD)/schedule/mobot3-f50p2 --fault-rate 0.5

# Schedule modes (tb/system/system_modes.h): the robot with its modes cruise
# and dock (sim/mobot3_modes.toml); the ModeRequest producer asks for a random
# mode (1 in 16 an undeclared one) every 2 to 10 cycles.  Every checker
# holds across every switch; each switch falls on a cycle boundary, follows
# its request within the compiler's switch_latency (fault-free) and is
# published as Mode; a latency or age measured across switches is judged by
# the time to the last switch plus the new mode's bound (system_modes.h).
# Fault-free, and at 20 % on the image planned for 20 %.  Negatives: a
# controller whose running mode changes before the boundary
# (tb/mutants/controller/early_switch.sed); the bounds of every mode cut to
# 90 % (latency_bound must fire).
SYS_MODES     := $(BUILD)/schedule/mobot3-modes
SYS_MODES_F20 := $(BUILD)/schedule/mobot3-modes-f20
TESTS += system-modes system-modes-faults-20-planned system-negative-modes-early system-negative-modes-latency
test-system-modes: $(SYS_BIN) $(SYS_MODES)/tb_plan.txt
	@$(call sys_run,modes) --plan $(SYS_MODES)
test-system-modes-faults-20-planned: $(SYS_BIN) $(SYS_MODES_F20)/tb_plan.txt
	@$(call sys_run,modes-faults-20-planned) --plan $(SYS_MODES_F20) --fault-rate 0.2
test-system-negative-modes-early: $(SYS_DIR)/mutant-early_switch/tb_system $(SYS_MODES)/tb_plan.txt
	@tools/run_test.sh system-negative-modes-early $< --plan $(SYS_MODES) --seed $(SEED) --cycles 300000 \
	    --label system-negative-modes-early --expect-failure "on a cycle boundary" --expect-failure "which names no switch"
test-system-negative-modes-latency: $(SYS_BIN) $(SYS_MODES)/tb_plan.txt
	@tools/run_test.sh system-negative-modes-latency $< --plan $(SYS_MODES) --seed $(SEED) --cycles 300000 \
	    --label system-negative-modes-latency --latency-scale 0.9 --expect-caught-by latency_bound

# Negative of the rate check: the old injector's driving (the Gilbert chain
# advanced every clock, not every access) at a nominal 20 % in bursts of 10
# faults about 9 % of the accesses; only the rate check may fail.
test-system-faults-negative-per-clock: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,faults-negative-per-clock) --plan $(SYS_RIGID) --fault-rate 0.2 --burst 10 \
	    --fault-clocking clock --expect-failure "fault rate:"
# Every store of a destination's Actual is performed and its answer lost
# (kind 3; the retry too): the controller must read Actual back, count the
# value delivered and never publish it again (negative: forget_landed below).
test-system-landed-stores: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,landed-stores) --plan $(SYS_RIGID) --land-actual 1
test-system-dead-board: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,dead-board) --plan $(SYS_RIGID) --dead-board 0 --dead-at 100000
test-system-corrupt-rom: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,corrupt-rom) --plan $(SYS_RIGID) --corrupt-entry 3
# A faulty producer leaves Actual = 7 in MotorCmd's source for two cycles.
test-system-corrupt-control: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,corrupt-control) --plan $(SYS_RIGID) --corrupt-actual 2:100000

# RadarMap and Position of the four-slot kind (sim/mobot3.toml with
# four_slot = true added to both): the checkers' four-slot source paths (a
# value complete from its producer's Slot store; a take's buffer from the Slot
# byte of the pair the controller stored as ReadLocked), under 5 % faults.
SYS_FS      := $(BUILD)/schedule/mobot3_fscopy
$(SYS_FS)/rom.hex: sim/mobot3.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	sed -e '/^name *= *"Position"/a four_slot     = true' -e '/^name *= *"RadarMap"/a four_slot     = true' \
	    $< > $(@D)/mobot3_fscopy.toml
	$(SCHEDULE) $(@D)/mobot3_fscopy.toml --out $(@D) -q
TESTS += system-four-slot-copy
test-system-four-slot-copy: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@$(call sys_run,four-slot-copy) --plan $(SYS_FS) --fault-rate 0.05

# Figures: bus cycles per transfer against the protocol's minimum (4, 16, 64,
# 256-byte channels), and latency against the compiler's bound.
BENCHES += bench-system
bench-system: $(SYS_BIN) $(BUILD)/schedule/bus_bench/tb_plan.txt
	$(SYS_BIN) --plan $(BUILD)/schedule/bus_bench --label bus-bench --seed $(SEED) --cycles 200000 \
	    --report $(REPORTS)/system_bus_bench.json

# Negative tests of the system checkers: NAME:MUTANT:CHECKER[:extra options].
# bad_index: the pick can yield buffer 0, the channel's control word: the
# value's stores land on it (ownership; the controller also counts corrupt
# control bytes).  Since a destination's picked buffer is its buffer tried,
# no driver reads an invalid index back (driver_error stays 0).
# actual_corrupt: every Actual store writes 7, no buffer: the consumers' Imports
# find the control bytes corrupt and return an error (driver_error).
SYS_NEGATIVE := \
  latency:real:latency_bound:--latency-scale,0.9 \
  ignore_readlocked:mutant-ignore_readlocked:actuality \
  never_delivered:mutant-never_delivered:duplicate_new \
  bad_index:mutant-bad_index:ownership \
  actual_corrupt:mutant-actual_corrupt:driver_error \
  wrong_lane:mutant-wrong_lane:ownership \
  time_wraps:mutant-time_wraps:global_time \
  taken_at_end:mutant-taken_at_end:taken_at:--fault-rate,0.15 \
  forget_landed:mutant-forget_landed:duplicate_new:--land-actual,1
define sys_negative
TESTS += system-negative-$(call neg_field,$(1),1)
test-system-negative-$(call neg_field,$(1),1): $(SYS_DIR)/$(call neg_field,$(1),2)/tb_system $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-$(call neg_field,$(1),1) $$< --plan $(SYS_RIGID) --seed $(SEED) \
	    --cycles 300000 --label system-negative-$(call neg_field,$(1),1) \
	    --expect-caught-by $(call neg_field,$(1),3) $(subst $(comma), ,$(call neg_field,$(1),4))
endef
$(foreach n,$(SYS_NEGATIVE),$(eval $(call sys_negative,$(n))))

# The exactness check on four-slot sources too: a controller that writes the
# taken_at word with the time of that store (mutant taken_at_store) on the
# plan with RadarMap and Position four-slot, fault-free.  TIME's taken_at goes
# wrong as well, so global_time fires beside taken_at.
TESTS += system-negative-taken_at_store
test-system-negative-taken_at_store: $(SYS_DIR)/mutant-taken_at_store/tb_system $(SYS_FS)/tb_plan.txt
	@tools/run_test.sh system-negative-taken_at_store $< --plan $(SYS_FS) --seed $(SEED) --cycles 300000 \
	    --label system-negative-taken_at_store --expect-caught-by taken_at

# The wall-clock hand-off watchdog: a controller that zeroes ReadLocked makes a
# consumer's driver loop without a RAM access; the run must end with the
# watchdog's message (exit 3), not hang.  That needs a board whose every
# consumer attach fails (the controller published to its destinations before
# its simulated CPU attached) and whose Exports are not yet due: simulated
# time then stands still.  The CPUs start at cycle 2,500 (--cpu-start, one
# cycle of the plan), after the controller's start-up and first cycle, so
# the controller has published first whatever its start-up length (the ROM
# check's CRC step sets it: with CPUs starting at reset the race was lost
# once the start-up grew by 7 clocks a ROM word).
# The time-rigid plan no longer does it since its [board] timing spaced
# GlobalTime to 2 slots per cycle: the attaches that matter succeed and the
# run ends at its cycle count with exit 1.  Since GlobalTime, which every
# board imports, is four-slot in sim/mobot3.toml, its Import is wait-free and
# always reaches the RAM, so no board can stand still: the test runs on the
# same description with GlobalTime three-buffer (four_slot lines removed),
# without redundancy.
SYS_WD      := $(BUILD)/schedule/mobot3_threebuffer-noredundancy
$(SYS_WD)/rom.hex: sim/mobot3.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	sed '/^four_slot *= *true/d' $< > $(@D)/mobot3_threebuffer.toml
	$(SCHEDULE) $(@D)/mobot3_threebuffer.toml --out $(@D) --no-redundancy -q
TESTS += system-negative-watchdog
test-system-negative-watchdog: $(SYS_DIR)/mutant-zero_readlocked/tb_system $(SYS_WD)/tb_plan.txt
	@tools/run_test.sh system-negative-watchdog bash -c '$< --plan $(SYS_WD) --seed $(SEED) --cycles 300000 \
	    --cpu-start 2500 --handoff-watchdog 2 --label system-negative-watchdog > $(SYS_DIR)/watchdog.log 2>&1; rc=$$?; tail -1 $(SYS_DIR)/watchdog.log; \
	    if [ $$rc = 3 ] && grep -q "tb: watchdog: simulated CPU" $(SYS_DIR)/watchdog.log; then \
	    echo "the hand-off watchdog ended the run, as expected"; \
	    else echo "expected the hand-off watchdog to end the run (exit 3), got exit $$rc"; exit 1; fi'

# A destination's Actual store lands but its answer is lost, and a later slot
# carries the same source value: the consumer must not see it New twice.  The
# fault plan is deterministic: every store of a destination's Actual is
# performed with its answer lost, alternately without any answer (kind 3) and
# with err (kind 1); MotorCmd's producer exports only every 7500 clocks (three
# cycles), so the slots between carry the value already delivered.  The run
# counts those slots (landed_same_later, and the ones after the consumer read
# the value New) and fails on none; the consumer-side checker new_twice guards
# the outcome.  Negative: the controller that forgets a landed store
# (mutant forget_landed) republishes it and its consumer reads it New twice.
SYS_LANDED_SAME := --land-actual 1 --land-kind 13 --producer-interval MotorCmd:7500 --require-landed-same 1
TESTS += system-landed-same-value system-negative-landed-same-value
test-system-landed-same-value: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,landed-same-value) --plan $(SYS_RIGID) $(SYS_LANDED_SAME)
test-system-negative-landed-same-value: $(SYS_DIR)/mutant-forget_landed/tb_system $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-landed-same-value $< --plan $(SYS_RIGID) --seed $(SEED) --cycles $(SYS_CYCLES) \
	    --label system-negative-landed-same-value $(SYS_LANDED_SAME) --expect-caught-by new_twice

# A four-slot consumer overtaken by four or more Exports while it reads one
# value: the motor board's CPU idles 3000 clocks before every GlobalTime
# buffer load but a value's first (a slow consumer), while the controller
# publishes GlobalTime about every 300 clocks.  The run counts the Imports
# overtaken by four or more publications and fails on fewer than three; the
# consumer-side checkers require the value read to be whole (definite_results)
# and current during the Import (actuality).  Negative: a four-slot Export
# that ignores ReadLocked (mutant fs_ignore_readlocked) writes the buffer the
# consumer reads by the fourth overtake: a torn value.
SYS_OVERTAKE := --stretch-import GlobalTime:3:3000
TESTS += system-four-slot-overtaken system-negative-four-slot-overtaken
test-system-four-slot-overtaken: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,four-slot-overtaken) --plan $(SYS_RIGID) $(SYS_OVERTAKE)
test-system-negative-four-slot-overtaken: $(SYS_DIR)/mutant-fs_ignore_readlocked/tb_system $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-four-slot-overtaken $< --plan $(SYS_RIGID) --seed $(SEED) --cycles $(SYS_CYCLES) \
	    --label system-negative-four-slot-overtaken $(SYS_OVERTAKE) --expect-caught-by definite_results

# A four-slot value is never completed twice: RadarMap four-slot (the plan of
# system-four-slot-copy) with a slow producer (every 3000 clocks, longer than
# a cycle: later slots carry the same value) at 5 % faults.  A slot cut off or
# dropped after its Slot store landed and before its Actual store leaves the
# value complete and unpublished; the next slot must store only Actual (a
# late publication), never write the value again into another buffer.  The
# run fails on no late publication of RadarMap; the duplicate-publication
# check (duplicate_new) and the consumers' new_twice guard the outcome.
# Negative: the controller that never recognises the landed Slot store
# (mutant forget_slot4) completes and publishes the value a second time.
SYS_LATE := --fault-rate 0.05 --producer-interval RadarMap:3000
TESTS += system-four-slot-late-publish system-negative-four-slot-late-publish
test-system-four-slot-late-publish: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@$(call sys_run,four-slot-late-publish) --plan $(SYS_FS) $(SYS_LATE) --require-late-publication RadarMap
test-system-negative-four-slot-late-publish: $(SYS_DIR)/mutant-forget_slot4/tb_system $(SYS_FS)/tb_plan.txt
	@tools/run_test.sh system-negative-four-slot-late-publish $< --plan $(SYS_FS) --seed $(SEED) --cycles $(SYS_CYCLES) \
	    --label system-negative-four-slot-late-publish $(SYS_LATE) --expect-caught-by duplicate_new

# The four-slot copy plan without faults, so that every latency is judged
# against the compiler's bound (under faults only the counts are kept): a
# four-slot destination's latency is taken at its Actual store, and source
# values superseded before a slot carried them (skipped) are measured at the
# next publication.  Fails unless both four-slot channels had such a value.
# Negatives: the bounds cut to 90 % (latency_bound must fire); a RadarMap
# producer slower than its slots has no skipped value (the requirement fails).
TESTS += system-four-slot-copy-nofault system-negative-four-slot-copy-latency system-negative-four-slot-copy-skipped
test-system-four-slot-copy-nofault: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@$(call sys_run,four-slot-copy-nofault) --plan $(SYS_FS) --require-skipped RadarMap --require-skipped Position
test-system-negative-four-slot-copy-latency: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@tools/run_test.sh system-negative-four-slot-copy-latency $< --plan $(SYS_FS) --seed $(SEED) --cycles 300000 \
	    --label system-negative-four-slot-copy-latency --latency-scale 0.9 --expect-caught-by latency_bound
test-system-negative-four-slot-copy-skipped: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@tools/run_test.sh system-negative-four-slot-copy-skipped $< --plan $(SYS_FS) --seed $(SEED) --cycles 300000 \
	    --label system-negative-four-slot-copy-skipped --producer-interval RadarMap:3000 --require-skipped RadarMap \
	    --expect-failure "RadarMap: expected at least one skipped value"

# Freshness (tb/system/system_checker.h "freshness", system_freshness.cpp): a
# source value that stays its source's newest for longer than the channel's
# bound must have reached every destination within it, judged when the bound
# runs out, published there or not (tb/system/fresh_scenario.h).  Every
# producer stops at cycle 300,000 (its last value must still arrive), and
# Position's producer exports two values back to back every 20,000 clocks
# (the second stays the newest for 20,000 clocks); on the four-slot plan its
# Exports are stretched by a cycle (2,500 clocks) before the Slot store that
# completes each value, so that the controller takes the first value of a
# burst while the second is written into the pair it then locks.  Fault-free
# on the rigid plan (three-buffer), the four-slot plan and the modes plan
# (each value judged by the bound of the mode in force).  Negatives: a source
# Import that answers Old whenever Actual lies in the pair of its copy,
# whatever the slot (tb/mutants/controller/old_same_pair4.sed) or the buffer
# of that pair (old_same_pair3.sed), skips the burst's second value and
# withholds it until the next burst, the last one for good.
SYS_FRESH  := --cycles 400000 --producer-interval Position:20000:2 --producer-stop all:300000
SYS_FRESH4 := $(SYS_FRESH) --stretch-export Position:2500
TESTS += system-freshness system-freshness-four-slot system-freshness-modes \
         system-negative-freshness-pair3 system-negative-freshness-pair4
test-system-freshness: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,freshness) --plan $(SYS_RIGID) $(SYS_FRESH)
test-system-freshness-four-slot: $(SYS_BIN) $(SYS_FS)/tb_plan.txt
	@$(call sys_run,freshness-four-slot) --plan $(SYS_FS) $(SYS_FRESH4)
test-system-freshness-modes: $(SYS_BIN) $(SYS_MODES)/tb_plan.txt
	@$(call sys_run,freshness-modes) --plan $(SYS_MODES) $(SYS_FRESH)
test-system-negative-freshness-pair3: $(SYS_DIR)/mutant-old_same_pair3/tb_system $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-freshness-pair3 $< --plan $(SYS_RIGID) --seed $(SEED) \
	    --label system-negative-freshness-pair3 $(SYS_FRESH) --expect-caught-by freshness
test-system-negative-freshness-pair4: $(SYS_DIR)/mutant-old_same_pair4/tb_system $(SYS_FS)/tb_plan.txt
	@tools/run_test.sh system-negative-freshness-pair4 $< --plan $(SYS_FS) --seed $(SEED) \
	    --label system-negative-freshness-pair4 $(SYS_FRESH4) --expect-caught-by freshness

# Weak spots, each a controller mutant the system test must catch:
#   reject_uncounted  a rejected mode request not counted: system-modes'
#                     exact count (STATUS counts exactly the requests for
#                     undeclared modes the controller took before the slot
#                     of the last STATUS value read) fails;
#   forget_switch     every channel's state forgotten in a mode's first 100
#                     clocks: with Position unchanged for 20,000 clocks at a
#                     time (the freshness scenario), a switch republishes it
#                     (duplicate_new, and new_twice at its consumers);
#   skip_crc          the start-up CRC check skipped: the ROM image with one
#                     bit of a reserved word flipped (entry 3's E6) must be
#                     refused at start-up (error_o, no bus access, nothing
#                     published; tb/system/rom_scenario.h), system-rom-start-crc.
TESTS += system-negative-modes-reject-count system-negative-modes-forget-switch \
         system-rom-start-crc system-negative-rom-start-crc
test-system-negative-modes-reject-count: $(SYS_DIR)/mutant-reject_uncounted/tb_system $(SYS_MODES)/tb_plan.txt
	@tools/run_test.sh system-negative-modes-reject-count $< --plan $(SYS_MODES) --seed $(SEED) --cycles $(SYS_CYCLES) \
	    --label system-negative-modes-reject-count --expect-failure "modes: STATUS taken at time"
test-system-negative-modes-forget-switch: $(SYS_DIR)/mutant-forget_switch/tb_system $(SYS_MODES)/tb_plan.txt
	@tools/run_test.sh system-negative-modes-forget-switch $< --plan $(SYS_MODES) --seed $(SEED) \
	    --label system-negative-modes-forget-switch $(SYS_FRESH) --expect-caught-by duplicate_new --expect-caught-by new_twice
test-system-rom-start-crc: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@$(call sys_run,rom-start-crc) --plan $(SYS_RIGID) --cycles 100000 --flip-rom-bit 35:31
test-system-negative-rom-start-crc: $(SYS_DIR)/mutant-skip_crc/tb_system $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-rom-start-crc $< --plan $(SYS_RIGID) --seed $(SEED) --cycles 100000 \
	    --label system-negative-rom-start-crc --flip-rom-bit 35:31 --expect-failure "flipped ROM bit"

# Multi-rate images with fragments (tb/system/sys_multirate.toml; the checks
# of tb/system/fragment_checker.h): a 50 us and two 100 us channels beside
# slow ones at a minor cycle of 8 us, Scan (three-buffer, two destinations)
# and Map (four-slot) carried in fragments.  sys_multirate-plain is the
# description without its [faults] table (fault-free: Scan in 4 fragments,
# Map in 2, each channel with two entries); sys_multirate as written, planned
# for 5 % independent faults (Scan in 30 fragments, Map in 8), run at that
# rate (at 10 % or 20 % the planner finds no plan for it: each fragment's slot
# keeps the retry budget of the whole value).  bounds_at_target.txt: each
# consumer's bound at the hypothesis' target, from report.json.
SYS_MR       := $(BUILD)/schedule/sys_multirate
SYS_MR_PLAIN := $(BUILD)/schedule/sys_multirate-plain
$(SYS_MR)/rom.hex: tb/system/sys_multirate.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	$(SCHEDULE) $< -o $(@D) -q
$(SYS_MR_PLAIN)/rom.hex: tb/system/sys_multirate.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	sed '/^\[faults\]/,/^probability/d' $< > $(@D)/sys_multirate-plain.toml
	$(SCHEDULE) $(@D)/sys_multirate-plain.toml -o $(@D) -q
$(BUILD)/schedule/%/bounds_at_target.txt: $(BUILD)/schedule/%/rom.hex tb/system/bounds_at_target.py
	$(PYTHON) tb/system/bounds_at_target.py $(@D)/report.json $@
# Fault-free on the plain image (every latency and age judged against the
# compiler's bounds), and at 5 % on the image planned for it (every latency
# and age against the report's bound at the target); each fails unless as
# many values were published after two or more runs as the plan guarantees
# in the run's clocks for the channels whose values cannot go in one slot
# (--require-fragments plan, tb/system/fragment_checker.h values_over_runs).
# Beyond the hypothesis, 20 % in bursts of mean 60 on the same image: runs
# are cut short of their planned words (the next goes on from the first word
# not stored to all, destinations dropped for the rest of a value) and the
# run fails unless 50 were; the named checks hold, values still arrive
# (their ages are not judged).
SYS_MR_RUN := --cycles 1600000 --require-fragments plan
TESTS += system-multirate system-multirate-faults-5-planned system-multirate-faults-20-burst-60
test-system-multirate: $(SYS_BIN) $(SYS_MR_PLAIN)/tb_plan.txt
	@$(call sys_run,multirate) --plan $(SYS_MR_PLAIN) $(SYS_MR_RUN)
test-system-multirate-faults-5-planned: $(SYS_BIN) $(SYS_MR)/tb_plan.txt $(SYS_MR)/bounds_at_target.txt
	@$(call sys_run,multirate-faults-5-planned) --plan $(SYS_MR) $(SYS_MR_RUN) --fault-rate 0.05 \
	    --bounds-at-target $(SYS_MR)/bounds_at_target.txt
test-system-multirate-faults-20-burst-60: $(SYS_BIN) $(SYS_MR)/tb_plan.txt
	@$(call sys_run,multirate-faults-20-burst-60) --plan $(SYS_MR) $(SYS_MR_RUN) --fault-rate 0.2 --burst 60 \
	    --require-cut-fragments 50

# Negatives, each a controller mutant on the plain image, fault-free, and the
# named check that must catch it: NAME:MUTANT:CHECKER (the frag_* mutants are
# the controller bench's, tools/mk/controller.mk).
#   wrong-cycle          the minor-cycle count starts at 1 (sys_wrong_cycle.sed)
#   rep-short            the repetition read one bit short (sys_rep_short.sed)
#   frag-publish-first   a publish after the first fragment (frag_publish_first.sed)
#   frag-lock            the source's lock released between fragments: a fresh
#                        Import at every run (frag_reimport.sed)
#   frag-wrong-word      a fragment resumed one word early (frag_wrong_word.sed)
SYS_MR_NEGATIVE := \
  wrong-cycle:sys_wrong_cycle:due_cycle \
  rep-short:sys_rep_short:due_cycle \
  frag-publish-first:frag_publish_first:fragment_publish \
  frag-lock:frag_reimport:source_lock \
  frag-wrong-word:frag_wrong_word:fragment_word
define sys_mr_negative
TESTS += system-negative-$(call neg_field,$(1),1)
test-system-negative-$(call neg_field,$(1),1): $(SYS_DIR)/mutant-$(call neg_field,$(1),2)/tb_system $(SYS_MR_PLAIN)/tb_plan.txt
	@tools/run_test.sh system-negative-$(call neg_field,$(1),1) $$< --plan $(SYS_MR_PLAIN) --seed $(SEED) \
	    --cycles 200000 --label system-negative-$(call neg_field,$(1),1) --expect-caught-by $(call neg_field,$(1),3)
endef
$(foreach n,$(SYS_MR_NEGATIVE),$(eval $(call sys_mr_negative,$(n))))

# The rule's safety (frag_unsafe.sed: a value goes on after a run that put a
# Slot or Actual store on the bus for a destination still in it): seen only
# when a fault hits such a store and the deadline cuts its retry off, so on
# the image planned for 5 % faults, at that rate (2 to 12 runs caught on
# seeds 1-5); fragment_word must catch it.
TESTS += system-negative-frag-unsafe
test-system-negative-frag-unsafe: $(SYS_DIR)/mutant-frag_unsafe/tb_system $(SYS_MR)/tb_plan.txt
	@tools/run_test.sh system-negative-frag-unsafe $< --plan $(SYS_MR) --seed $(SEED) --cycles 1600000 \
	    --fault-rate 0.05 --label system-negative-frag-unsafe --expect-caught-by fragment_word

# Negatives of the multi-rate runs' own requirements: the bounds at the target
# cut to 90 % on the run at 5 % (Position's worst latency is 93 % of its
# bound: "at the target" must fail), and a plan without fragments (the robot's)
# fails both --require-fragments and --require-cut-fragments.
TESTS += system-negative-multirate-at-target system-negative-multirate-requirements
test-system-negative-multirate-at-target: $(SYS_BIN) $(SYS_MR)/tb_plan.txt $(SYS_MR)/bounds_at_target.txt
	@tools/run_test.sh system-negative-multirate-at-target $< --plan $(SYS_MR) --seed $(SEED) $(SYS_MR_RUN) \
	    --fault-rate 0.05 --bounds-at-target $(SYS_MR)/bounds_at_target.txt --latency-scale 0.9 \
	    --label system-negative-multirate-at-target --expect-failure "at the target:"
test-system-negative-multirate-requirements: $(SYS_BIN) $(SYS_RIGID)/tb_plan.txt
	@tools/run_test.sh system-negative-multirate-requirements $< --plan $(SYS_RIGID) --seed $(SEED) --cycles 200000 \
	    --fault-rate 0.05 --require-fragments 1 --require-cut-fragments 1 \
	    --label system-negative-multirate-requirements --expect-failure "fragments: expected at least"
