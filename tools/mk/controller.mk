# tools/mk/controller.mk -- smoke test of albatross_controller on the multi-board test
# top tb/system/tb_system.v: 4 boards (soc/albatross_system.v), albatross_bus, bus_fault_injector
# (tb/controller/test_controller.cpp, ctrl_bench.h/.cpp, ctrl_scenarios_*.cpp).  Outputs in build/ctrl/.
#   make test-controller-smoke            the self-checking run (all scenarios)
#   make test-controller-smoke-negative   the timing checker, given a formula one
#                                         clock off, must fail (exit 65: timing only)
#   make test-controller-abandon          the abandon scenario alone (about 2 s once built)
#   make test-controller-negative-stale_need
#                                         the bench built on the state-RAM write-back
#                                         regression of 59c3c2d (tb/mutants/controller/
#                                         stale_need.sed) must fail an abandoned-count
#                                         check (today the cold scenario's) and name it
#   make test-controller-smoke-negative-droprun
#                                         a controller that ignores the ROM's drop
#                                         run (H2) fails scenario droprun
#                                         (exit 80: dead group only)
#   make test-controller-cold             scenario cold alone: zeroed board RAMs (cold start)
#   make test-controller-negative-cold    the controller with the rule from before the
#                                         cold-start contract (tb/mutants/controller/
#                                         cold_zero_corrupt.sed) fails scenario cold
#                                         (exit 66: data group only)
# The model reads its ROM from "ctrl_rom.hex" in the working directory that
# each run selects with --dir, so the two runs never share a ROM file.

CTRL_DIR := $(BUILD)/ctrl
CTRL_BIN := $(CTRL_DIR)/obj/Vtb_system
CTRL_CPP := tb/controller/test_controller.cpp tb/controller/ctrl_bench.cpp \
            tb/controller/ctrl_scenarios_data.cpp tb/controller/ctrl_scenarios_faults.cpp \
            tb/controller/ctrl_scenarios_cold.cpp tb/controller/ctrl_scenarios_modes.cpp \
            tb/controller/ctrl_scenarios_race.cpp tb/controller/ctrl_scenarios_frag.cpp \
            tb/controller/ctrl_scenarios_fragswitch.cpp
CTRL_SRC := tb/system/tb_system.v tb/common/bus_fault_injector.v $(CORE_soc_system) $(CTRL_CPP) tb/controller/ctrl_bench.h \
            $(RTL_INC) tb/common/albatross_contract.h

$(CTRL_BIN): $(CTRL_SRC) tools/mk/controller.mk
	@mkdir -p $(CTRL_DIR)
	$(VERILATOR_BUILD) -j 2 -O3 -Wall --top-module tb_system \
	    -GROM_FILE='"ctrl_rom.hex"' -CFLAGS "-O2 -std=c++17 -Wall -Wextra $(TB_COMMON_INC)" \
	    --Mdir $(CTRL_DIR)/obj $(VLIB) tb/system/tb_system.v $(abspath $(CTRL_CPP)) \
	    > $(CTRL_DIR)/build.log 2>&1 || { cat $(CTRL_DIR)/build.log; exit 1; }

TESTS += controller-smoke controller-smoke-negative
.PHONY: test-controller-smoke test-controller-smoke-negative

test-controller-smoke: $(CTRL_BIN)
	@tools/run_test.sh controller-smoke $(CTRL_BIN) --dir=$(CTRL_DIR)/smoke

test-controller-smoke-negative: $(CTRL_BIN)
	@tools/run_test.sh controller-smoke-negative bash -c '$(CTRL_BIN) --dir=$(CTRL_DIR)/negative \
	    --inject=timing --scenario=basic > $(CTRL_DIR)/negative.log 2>&1; rc=$$?; \
	    grep -m 3 "^FAIL" $(CTRL_DIR)/negative.log | sed "s/^FAIL/  caught (injected):/"; \
	    if [ $$rc -eq 65 ]; then echo "timing checker failed on the wrong formula, as it must (exit 65)"; \
	    else echo "expected exit 65 (timing checker only), came exit $$rc"; tail -n 5 $(CTRL_DIR)/negative.log; exit 1; fi'

# The abandon scenario alone, and its negative: the controller mutant that
# reproduces the state-RAM write-back regression (the abandoned count of a COPY
# whose Import ended without choosing taken from a stale Export's need).
# The bench built on a controller mutant: $(1) = the mutant's name,
# tb/mutants/controller/$(1).sed, which names the file it edits on its
# '# target:' line; the model in $(CTRL_DIR)/mutant-$(1)/obj.
ctrl_mut_target = $(shell sed -n 's/^# target: *//p' tb/mutants/controller/$(1).sed)
define ctrl_mutant_model
$(CTRL_DIR)/mutant-$(1)/src/$(notdir $(call ctrl_mut_target,$(1))): $(call ctrl_mut_target,$(1)) tb/mutants/controller/$(1).sed
	@rm -rf $$(@D) && mkdir -p $$(@D)
	sed -f tb/mutants/controller/$(1).sed $$< > $$@
	@if cmp -s $$@ $$<; then echo "mutant $(1) did not apply: $$< no longer has the line it edits"; \
	    rm -f $$@; exit 1; fi
$(CTRL_DIR)/mutant-$(1)/obj/Vtb_system: $(CTRL_SRC) $(CTRL_DIR)/mutant-$(1)/src/$(notdir $(call ctrl_mut_target,$(1))) tools/mk/controller.mk
	@mkdir -p $(CTRL_DIR)/mutant-$(1)
	$(VERILATOR_BUILD) -j 2 -O3 -Wall --top-module tb_system \
	    -GROM_FILE='"ctrl_rom.hex"' -CFLAGS "-O2 -std=c++17 -Wall -Wextra $(TB_COMMON_INC)" \
	    --Mdir $(CTRL_DIR)/mutant-$(1)/obj -y $(CTRL_DIR)/mutant-$(1)/src $(VLIB) tb/system/tb_system.v $(abspath $(CTRL_CPP)) \
	    > $(CTRL_DIR)/mutant-$(1)/build.log 2>&1 || { cat $(CTRL_DIR)/mutant-$(1)/build.log; exit 1; }
endef
$(foreach m,stale_need cold_zero_corrupt no_request forget_state forget_switch deadline_late slot_first_load \
    frag_publish_first frag_reimport frag_wrong_word frag_pub_cut,$(eval $(call ctrl_mutant_model,$(m))))
CTRL_MUT_DIR := $(CTRL_DIR)/mutant-stale_need

TESTS += controller-abandon controller-negative-stale_need
.PHONY: test-controller-abandon test-controller-negative-stale_need
test-controller-abandon: $(CTRL_BIN)
	@tools/run_test.sh controller-abandon $(CTRL_BIN) --dir=$(CTRL_DIR)/abandon --scenario=abandon

test-controller-negative-stale_need: $(CTRL_MUT_DIR)/obj/Vtb_system
	@tools/run_test.sh controller-negative-stale_need bash -c '$< --dir=$(CTRL_MUT_DIR)/run \
	    > $(CTRL_MUT_DIR)/run.log 2>&1; rc=$$?; \
	    grep -m 3 "^FAIL" $(CTRL_MUT_DIR)/run.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$rc -ge 64 ] && grep -qE "^FAIL .*STATUS channel 0 (abandoned|\{abandoned, corrupt\})" $(CTRL_MUT_DIR)/run.log; then \
	        echo "an abandoned-count check failed on the stale-need mutant, as it must (exit $$rc)"; \
	    else echo "expected an abandoned-count check to fail (exit >= 64), came exit $$rc"; tail -n 5 $(CTRL_MUT_DIR)/run.log; exit 1; fi'
# The ROM's drop run must reach the Export engine: the controller with H2 not
# connected (K read as 2) is caught by scenario droprun (the dead destination
# is tried twice, not 3 times).  One more model build (about a minute).
CTRL_NEG_DR := $(CTRL_DIR)/mutant-droprun
$(CTRL_NEG_DR)/src/albatross_controller.v: rtl/albatross_controller.v tools/mk/controller.mk
	@mkdir -p $(@D)
	sed 's/\.drop_run_i(drop_run)/.drop_run_i(8'"'"'d0)/' $< > $@
	@if cmp -s $@ $<; then echo "mutant droprun did not apply: $< no longer connects .drop_run_i(drop_run)"; \
	    rm -f $@; exit 1; fi
$(CTRL_NEG_DR)/obj/Vtb_system: $(CTRL_SRC) $(CTRL_NEG_DR)/src/albatross_controller.v
	@mkdir -p $(CTRL_NEG_DR)
	$(VERILATOR_BUILD) -j 2 -O3 -Wall -Wno-UNUSEDSIGNAL --top-module tb_system \
	    -GROM_FILE='"ctrl_rom.hex"' -CFLAGS "-O2 -std=c++17 -Wall -Wextra $(TB_COMMON_INC)" \
	    --Mdir $(CTRL_NEG_DR)/obj -y $(CTRL_NEG_DR)/src $(VLIB) tb/system/tb_system.v $(abspath $(CTRL_CPP)) \
	    > $(CTRL_NEG_DR)/build.log 2>&1 || { cat $(CTRL_NEG_DR)/build.log; exit 1; }

TESTS += controller-smoke-negative-droprun
.PHONY: test-controller-smoke-negative-droprun
test-controller-smoke-negative-droprun: $(CTRL_NEG_DR)/obj/Vtb_system
	@tools/run_test.sh controller-smoke-negative-droprun bash -c '$< --dir=$(CTRL_NEG_DR)/run --scenario=droprun \
	    > $(CTRL_NEG_DR)/run.log 2>&1; rc=$$?; \
	    grep -m 3 "^FAIL" $(CTRL_NEG_DR)/run.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$rc -eq 80 ]; then echo "the controller that ignores H2 fails scenario droprun, as it must (exit 80)"; \
	    else echo "expected exit 80 (dead group only), came exit $$rc"; tail -n 5 $(CTRL_NEG_DR)/run.log; exit 1; fi'

# Cold start (docs/controller.md "Cold start"): scenario cold alone, and its
# negative: the controller that takes a control byte of 0 as out of range
# (corrupt; the four-slot pair from the Actual copy) fails it.
CTRL_NEG_COLD := $(CTRL_DIR)/mutant-cold_zero_corrupt

TESTS += controller-cold controller-negative-cold
.PHONY: test-controller-cold test-controller-negative-cold
test-controller-cold: $(CTRL_BIN)
	@tools/run_test.sh controller-cold $(CTRL_BIN) --dir=$(CTRL_DIR)/cold --scenario=cold

test-controller-negative-cold: $(CTRL_NEG_COLD)/obj/Vtb_system
	@tools/run_test.sh controller-negative-cold bash -c '$< --dir=$(CTRL_NEG_COLD)/run --scenario=cold \
	    > $(CTRL_NEG_COLD)/run.log 2>&1; rc=$$?; \
	    grep -m 3 "^FAIL" $(CTRL_NEG_COLD)/run.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$rc -eq 66 ] && grep -q "^FAIL cold.*corrupt" $(CTRL_NEG_COLD)/run.log && \
	       grep -q "^FAIL cold four cycle 1: destination control word" $(CTRL_NEG_COLD)/run.log; then \
	        echo "the controller with the old zero rule fails scenario cold, as it must (exit 66)"; \
	    else echo "expected exit 66 with a corrupt count and the four-slot pair caught, came exit $$rc"; \
	        tail -n 5 $(CTRL_NEG_COLD)/run.log; exit 1; fi'

# Schedule modes (docs/controller.md "Modes"): scenario modes alone, and its
# negatives, each a controller mutant (tb/mutants/controller/NAME.sed) that
# must fail it with a named check:
#   no_request     a transfer that never offers a REQUEST entry's value as a
#                  mode request: mode 1 never runs
#   forget_state   a channel's state forgotten outside mode 0: channel 4's
#                  value, unchanged, is New twice within mode 1
#   forget_switch  every channel's state forgotten in a mode's first 100
#                  clocks: channel 0's value, unchanged over the switches to
#                  mode 1 and back, is New twice
TESTS += controller-modes
.PHONY: test-controller-modes
test-controller-modes: $(CTRL_BIN)
	@tools/run_test.sh controller-modes $(CTRL_BIN) --dir=$(CTRL_DIR)/modes --scenario=modes
# $(1) the mutant, $(2) the start of the FAIL line it must produce (a grep
# pattern, no comma), $(3) what the mutant is (no quote).
define ctrl_modes_negative
TESTS += controller-negative-$(1)
.PHONY: test-controller-negative-$(1)
test-controller-negative-$(1): $(CTRL_DIR)/mutant-$(1)/obj/Vtb_system
	@tools/run_test.sh controller-negative-$(1) bash -c '$$< --dir=$(CTRL_DIR)/mutant-$(1)/run --scenario=modes \
	    > $(CTRL_DIR)/mutant-$(1)/run.log 2>&1; rc=$$$$?; \
	    grep -m 3 "^FAIL" $(CTRL_DIR)/mutant-$(1)/run.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$$$rc -ge 64 ] && grep -q "^FAIL modes: $(2)" $(CTRL_DIR)/mutant-$(1)/run.log; then \
	        echo "$(3) fails scenario modes, as it must (exit $$$$rc)"; \
	    else echo "expected scenario modes to fail with: $(2), came exit $$$$rc"; \
	        tail -n 5 $(CTRL_DIR)/mutant-$(1)/run.log; exit 1; fi'
endef
$(eval $(call ctrl_modes_negative,no_request,cycle 2 (mode 1) carries channel 4,the controller that drops mode requests))
$(eval $(call ctrl_modes_negative,forget_state,channel 4.s value. unchanged over two more cycles,the controller that forgets the state of a channel outside mode 0))
$(eval $(call ctrl_modes_negative,forget_switch,channel 0.s value. unchanged over the switches,the controller that forgets the state of every channel at a switch))

# Events at an exact clock of a slot (ctrl_scenarios_race.cpp): scenario
# deadline (a dead source retried to the deadline, in slots of 16 lengths so
# that a retry falls on every phase of the rule: none begins after
# D - TIMEOUT - 2, some begins exactly there) and race4 (a four-slot value
# completed between the Import's two control-word loads is the one taken).
# Negatives, each a controller mutant that must fail its scenario:
#   deadline_late    the deadline check allows one clock more (an access may
#                    end at D): exit 80, scenario deadline
#   slot_first_load  the four-slot Import takes the Slot byte from its first
#                    control-word load: the older value is taken, exit 66
TESTS += controller-deadline controller-race4
.PHONY: test-controller-deadline test-controller-race4
test-controller-deadline: $(CTRL_BIN)
	@tools/run_test.sh controller-deadline $(CTRL_BIN) --dir=$(CTRL_DIR)/deadline --scenario=deadline
test-controller-race4: $(CTRL_BIN)
	@tools/run_test.sh controller-race4 $(CTRL_BIN) --dir=$(CTRL_DIR)/race4 --scenario=race4
# $(1) the mutant, $(2) the scenario, $(3) the exit status, $(4) the start of
# the FAIL line it must produce (a grep pattern, no comma), $(5) what it is.
define ctrl_race_negative
TESTS += controller-negative-$(1)
.PHONY: test-controller-negative-$(1)
test-controller-negative-$(1): $(CTRL_DIR)/mutant-$(1)/obj/Vtb_system
	@tools/run_test.sh controller-negative-$(1) bash -c '$$< --dir=$(CTRL_DIR)/mutant-$(1)/run --scenario=$(2) \
	    > $(CTRL_DIR)/mutant-$(1)/run.log 2>&1; rc=$$$$?; \
	    grep -m 3 "^FAIL" $(CTRL_DIR)/mutant-$(1)/run.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$$$rc -eq $(3) ] && grep -q "^FAIL $(4)" $(CTRL_DIR)/mutant-$(1)/run.log; then \
	        echo "$(5) fails scenario $(2), as it must (exit $$$$rc)"; \
	    else echo "expected scenario $(2) to fail with exit $(3) and: $(4), came exit $$$$rc"; \
	        tail -n 5 $(CTRL_DIR)/mutant-$(1)/run.log; exit 1; fi'
endef
$(eval $(call ctrl_race_negative,deadline_late,deadline,80,deadline: length .* no access begins after D-TIMEOUT-2,the controller whose deadline check allows one clock more))
$(eval $(call ctrl_race_negative,slot_first_load,race4,66,race4: the controller took the value completed before its second load,the four-slot Import that takes the Slot byte from its first load))

# A value over several runs (ctrl_scenarios_frag.cpp): scenario frag (W 5 in
# a slot too short for it, 3 runs: published once after its last word,
# whole; the source's lock held and each run at the first word not yet
# stored; a failed run, a run cut off after 2 words, a first run cut before
# a word; a reset in the middle).  Negatives, each a controller mutant
# (tb/mutants/controller/NAME.sed) that must fail it (exit 66, data):
#   frag_publish_first  a publish after the first word of a first run
#   frag_reimport       the source's lock released between runs (a fresh Import)
#   frag_wrong_word     a run that goes on resumes one word early
# Scenario fragedge: runs cut off in the value's publication (after its last
# word, before its Actual store): the value must still be published, once and
# whole.  Its negative, frag_pub_cut, ends the value at such a cut-off (the
# next run Imports afresh): with a slot too short for the value and its
# publication together the runs then repeat without end.
TESTS += controller-frag controller-fragedge
.PHONY: test-controller-frag
test-controller-frag: $(CTRL_BIN)
	@tools/run_test.sh controller-frag $(CTRL_BIN) --dir=$(CTRL_DIR)/frag --scenario=frag
$(eval $(call ctrl_race_negative,frag_publish_first,frag,66,frag whole: run 0 publishes nothing,the controller that publishes after the first word of a first run))
$(eval $(call ctrl_race_negative,frag_reimport,frag,66,frag whole: run 1 makes no access to the source.s control word,the controller that Imports afresh at every run))
$(eval $(call ctrl_race_negative,frag_wrong_word,frag,66,frag whole: run 1 goes on at the first word not yet stored,the controller that resumes a value one word early))
$(eval $(call ctrl_race_negative,frag_pub_cut,fragedge,66,frag edge .*expected the value published once,the controller that ends a value cut off in its publication))
.PHONY: test-controller-fragedge
test-controller-fragedge: $(CTRL_BIN)
	@tools/run_test.sh controller-fragedge $(CTRL_BIN) --dir=$(CTRL_DIR)/fragedge --scenario=fragedge

# A mode switch while a value goes over several runs (ctrl_scenarios_fragswitch.cpp):
# scenario fragswitch (the value goes on whole when its channel next runs, in
# the new mode or back in the old one, at the first word not yet stored, with
# the held source buffer and its first run's taken_at).  Its negative runs it on the
# forget_switch mutant (every channel's state forgotten in a mode's first 100
# clocks: the held buffer lost at the switch), which must fail it (exit 66).
TESTS += controller-fragswitch controller-negative-fragswitch
.PHONY: test-controller-fragswitch test-controller-negative-fragswitch
test-controller-fragswitch: $(CTRL_BIN)
	@tools/run_test.sh controller-fragswitch $(CTRL_BIN) --dir=$(CTRL_DIR)/fragswitch --scenario=fragswitch
test-controller-negative-fragswitch: $(CTRL_DIR)/mutant-forget_switch/obj/Vtb_system
	@tools/run_test.sh controller-negative-fragswitch bash -c '$< --dir=$(CTRL_DIR)/mutant-forget_switch/fragswitch \
	    --scenario=fragswitch > $(CTRL_DIR)/mutant-forget_switch/fragswitch.log 2>&1; rc=$$?; \
	    grep -m 3 "^FAIL" $(CTRL_DIR)/mutant-forget_switch/fragswitch.log | sed "s/^FAIL/  caught:/"; \
	    if [ $$rc -eq 66 ] && grep -q "^FAIL fragswitch on: the run after the switch (mode 1) goes on at the first word not yet stored" \
	        $(CTRL_DIR)/mutant-forget_switch/fragswitch.log; then \
	        echo "the controller that forgets the held buffer at a switch fails scenario fragswitch, as it must (exit 66)"; \
	    else echo "expected scenario fragswitch to fail with exit 66 and: the run after the switch goes on at the first word not yet stored, came exit $$rc"; \
	        tail -n 5 $(CTRL_DIR)/mutant-forget_switch/fragswitch.log; exit 1; fi'
