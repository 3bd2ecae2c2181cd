# tools/mk/formal_rtl.mk -- bounded proofs of the RTL properties (formal/rtl/,
# docs/verification.md "Formal proofs (RTL)").  The unbounded proofs of the RAM,
# the clock-crossing bridge and the bus are in tools/mk/formal_sby.mk.  formal/rtl/run_check.py runs one check,
# names the failed assertions and writes build/reports/formal_rtl.json.
#   formal-controller             albatross_controller, black box: complete
#                                 publication, no write of a locked buffer, slot
#                                 times (yosys-abc bmc3: z3 cannot unroll it)
#   formal-*-negative-<variant>   a broken variant; passes only if the proof
#                                 fails on the named property
# Build outputs in build/formal/rtl/.

FRTL_DIR   := $(BUILD)/formal/rtl
FRTL_RUN   := $(PYTHON) formal/rtl/run_check.py
FRTL_DEPS  := formal/rtl/run_check.py tools/mk/formal_rtl.mk $(RTL_INC)

CTRL_PROPS := complete_publish,no_locked_write,slot_idle,slot_start,time_step,rom_valid
CTRL_REACH := reach_publish0,reach_publish1
# Two slots: cycle 0 starts at time 20, the second slot's first access is at 51.
CTRL_DEPTH := 56
# The controller's files; a mutant replaces the one its .sed names ('# target:').
CTRL_PARTS := $(CTRL_RTL)
ctrl_mutant_sed    = $(firstword $(wildcard formal/rtl/mutants/$(1).sed tb/mutants/controller/$(1).sed))
ctrl_mutant_target = $(shell sed -n 's/^# target: *//p' $(call ctrl_mutant_sed,$(1)))
ctrl_mutant_file   = $(FRTL_DIR)/mutant-src/$(1)/$(notdir $(call ctrl_mutant_target,$(1)))
ctrl_mutant_srcs   = $(call ctrl_mutant_file,$(1)) $(filter-out $(call ctrl_mutant_target,$(1)),$(CTRL_PARTS))
frtl_ctrl    = $(FRTL_RUN) $(1) --engine abc --top formal_controller --depth $(CTRL_DEPTH) \
               --src $(2) formal/rtl/formal_controller.v --props $(3) --expect $(4)

FORMAL_RTL_TESTS := formal-controller formal-controller-negative-ignore_readlocked \
                    formal-controller-negative-publish_early formal-controller-negative-slot_late
# A bounded cross-check of the whole composition (the real sequencer with the
# datapath, one fixed image), beside the assume-guarantee proofs that make test
# runs: formal/ctrl proves the controller's top against the sequencer's
# contract, formal/sequencer proves the sequencer's side of it.  So these run
# with make formal-slow, not in make test.
SLOW_TESTS += $(FORMAL_RTL_TESTS)
.PHONY: formal-slow
formal-slow: $(addprefix test-,$(FORMAL_RTL_TESTS))
.PHONY: $(addprefix test-,$(FORMAL_RTL_TESTS))

test-formal-controller: $(FRTL_DEPS) formal/rtl/ctrl_time.hex $(CTRL_PARTS)
	@tools/run_test.sh formal-controller $(call frtl_ctrl,formal-controller,$(CTRL_PARTS),$(CTRL_PROPS),pass) --reach $(CTRL_REACH)

# Controller mutants: tb/mutants/controller/ignore_readlocked.sed (shared with
# the system tests) and formal/rtl/mutants/*.sed (formal only); each names the
# file it edits on its '# target:' line.
FRTL_CTRL_NEG := ignore_readlocked:no_locked_write publish_early:complete_publish slot_late:slot_start
# The mutated copies are kept between runs (named: a bare .SECONDARY: would make
# every file secondary, and make would then skip missing prerequisites).
.SECONDARY: $(foreach n,$(FRTL_CTRL_NEG),$(call ctrl_mutant_file,$(call neg_field,$(n),1)))
define frtl_ctrl_negative
$(call ctrl_mutant_file,$(call neg_field,$(1),1)): $(call ctrl_mutant_sed,$(call neg_field,$(1),1)) $(call ctrl_mutant_target,$(call neg_field,$(1),1))
	@mkdir -p $$(@D)
	sed -f $$< $(call ctrl_mutant_target,$(call neg_field,$(1),1)) > $$@
	@if cmp -s $$@ $(call ctrl_mutant_target,$(call neg_field,$(1),1)); then echo "controller mutant $(call neg_field,$(1),1) did not apply: its target no longer has the line its .sed edits"; \
	    rm -f $$@; exit 1; fi
test-formal-controller-negative-$(call neg_field,$(1),1): $(FRTL_DEPS) formal/rtl/ctrl_time.hex $(CTRL_PARTS) $(call ctrl_mutant_file,$(call neg_field,$(1),1))
	@tools/run_test.sh formal-controller-negative-$(call neg_field,$(1),1) $$(call frtl_ctrl,formal-controller-negative-$(call neg_field,$(1),1),$(call ctrl_mutant_srcs,$(call neg_field,$(1),1)),$(call neg_field,$(1),2),$(call neg_field,$(1),2))
endef
$(foreach n,$(FRTL_CTRL_NEG),$(eval $(call frtl_ctrl_negative,$(n))))
