# formal/ctrl/tests.mk -- the SymbiYosys tests of formal/ctrl/ctrl.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT,
# CORE:VARIANT:FILE:SED).  The harness takes the controller's own top; its
# mutants are the old proofs' mutants (formal/copy, formal/export,
# formal/import, formal/rtl, tb/mutants/engines, tb/mutants/controller), each
# applied to the rtl/ file it edits, and each must be caught by the property
# that keeps its meaning (docs/verification.md "The controller on its own RTL").
# The controller's files are the Makefile's CTRL_RTL without the sequencer's
# (fseq_contract.v takes its place), copied with the contract header into
# build/formal/sby/ctrl-rtl/base/, which ctrl.sby reads whole: the proof follows
# the controller's file set.  Each mutant's folder is that one with its file
# edited (a mutant of a file the controller no longer has is reported).
FCTRL_SRC     := $(filter-out rtl/albatross_sequencer.v rtl/albatross_schedule_rom.v rtl/albatross_rom_check.v \
                              rtl/albatross_entry_check.v rtl/albatross_mode_switch.v rtl/albatross_entry_fields.v rtl/albatross_sync_poll.v \
                              rtl/albatross_minor_cycles.v rtl/albatross_header_check.v \
                              rtl/albatross_seq_status.v rtl/albatross_slot_timing.v,$(CTRL_RTL))
FCTRL_DIR     := $(BUILD)/formal/sby/ctrl-rtl
FSBY_RTL_ctrl := $(FCTRL_SRC) formal/ctrl/fseq_contract.v $(wildcard formal/alb/*.v)
# The negatives: VARIANT:PROPERTY (the property that keeps the old mutant's
# meaning; docs/verification.md has each one's intent).  A four-slot Import
# that reads a buffer other than buf(pair(Actual), Slot) (idx_actual,
# wrong_slot) reads either the buffer being written (src_no_torn) or an older
# value than the one announced (src_fresh): the solver may show either.
# old_same_pair4 and old_same_pair3 (an Import answering Old on Actual's pair
# alone) are src_fresh's: the four-slot one in make test (about 30 s), as
# the fault the check was written for.
FCTRL_NEG := \
    early_publish:dst_publish_complete \
    publish_early:dst_publish_complete \
    writes_locked:dst_no_held_write \
    ignore_actual:dst_no_actual_write \
    extra_access:dst_one_load \
    drop_total:retry_same|drop_k \
    ignore_rl4:dst_no_held_write \
    same_slot4:dst_no_held_write \
    actual_first4:dst_slot_first \
    early_slot4:dst_slot_complete \
    extra_load4:dst_one_load \
    idx_actual:src_no_torn|src_fresh \
    loop4:src_wait_free \
    new_unstored:dst_new_once \
    old_by_actual:dst_new_once \
    skip_confirm:src_no_torn \
    store_actual:src_store_rl \
    wrong_slot:src_no_torn|src_fresh \
    import_no_readlocked:src_no_torn \
    never_delivered:dst_new_once \
    forget_landed:dst_new_once \
    forget_slot4:dst_new_once \
    bad_index:dst_ctrl_store|dst_in_channel \
    wrong_lane:dst_ctrl_store \
    old_same_pair4:src_fresh \
    old_same_pair3:src_fresh \
    frag_publish_first:frag_words_dst|dst_publish_complete \
    frag_reimport:frag_held \
    frag_wrong_word:frag_words_src \
    frag_progress_early:frag_prog|dst_publish_complete
# Each mutant is formal/ctrl/mutants/VARIANT.sed, an edit of the controller
# file its '# target:' line names (CORE:VARIANT:FILE).
fctrl_target  = $(notdir $(shell sed -n 's/^# target: *//p' formal/ctrl/mutants/$(1).sed))
FCTRL_MUTANTS := $(foreach n,$(FCTRL_NEG),ctrl:$(call neg_field,$(n),1):$(call fctrl_target,$(call neg_field,$(n),1)))
# The negatives whose counterexample needs two slots or more (a value published
# twice, a reader overtaken by three Exports) take longer than make test allows:
# make formal-slow runs them.
FCTRL_DEEP := new_unstored old_by_actual never_delivered forget_landed forget_slot4 ignore_rl4
# make test keeps one negative per property (the quickest); the other mutants
# caught by a property make test already breaks also run with make test-slow.
# (skip_confirm stays in make test: src_no_torn's own, idx_actual showing
# either property.)
FCTRL_SECOND := publish_early same_slot4 wrong_slot import_no_readlocked wrong_lane
FCTRL_SLOW := $(FCTRL_DEEP) $(FCTRL_SECOND)
fctrl_neg_spec = formal-ctrl-negative-$(call neg_field,$(1),1):ctrl:neg_$(call neg_field,$(1),1):$(call neg_field,$(1),2)
# The covers vouch for the unbounded three/four proofs (formal-ctrl-pdr),
# which run outside make test: they run with make test-slow.  In make test
# the k3 and k4 harnesses show their reach through their negatives, each of
# which must reach a failing state of its property.
FSBY_TESTS_SPEC += \
    formal-ctrl-shape-fixed:ctrl:shape_fixed:pass \
    formal-ctrl-shape-negative-drop_total:ctrl:neg_shape_drop_total:retry_same|drop_k \
    $(foreach n,$(FCTRL_NEG),$(if $(filter $(call neg_field,$(n),1),$(FCTRL_SLOW)),,$(call fctrl_neg_spec,$(n))))
FSBY_SLOW_SPEC += formal-ctrl-cover3:ctrl:cover3:pass formal-ctrl-cover4:ctrl:cover4:pass
# A value over several runs (F_FRAG, fctrl.v's frag_* properties): the
# proofs (abc pdr: three-buffer about 2 CPU minutes; four-slot not within
# 15 minutes so far, bounded by the long timeout) run with make
# test-slow; their negatives (frag_*) in make test.
FSBY_SLOW_SPEC += formal-ctrl-frag-three:ctrl:frag3:pass formal-ctrl-frag-four:ctrl:frag4:pass
# The protocol proofs that converge within the slow suite's bound (abc pdr:
# three and three_fixed in minutes, four_fixed in 15 to 25 minutes)
# run with make test-slow too; make formal-ctrl-pdr runs every unbounded task.
FSBY_SLOW_SPEC += formal-ctrl-pdr-three:ctrl:three:pass formal-ctrl-pdr-three_fixed:ctrl:three_fixed:pass \
                  formal-ctrl-pdr-four_fixed:ctrl:four_fixed:pass
FSBY_SLOW_SPEC += $(foreach n,$(FCTRL_NEG),$(if $(filter $(call neg_field,$(n),1),$(FCTRL_SLOW)),$(call fctrl_neg_spec,$(n))))
FSBY_MUTANTS += $(FCTRL_MUTANTS)

# The unbounded proofs (abc pdr: tasks shape, three, four on the free image, three_fixed,
# four_fixed on the fixed one) take longer than make test allows: they run behind
# their own target, each bounded by the task's timeout (3600 s), and write their
# verdict to build/reports/formal_sby.json as the others.
FCTRL_PDR := shape three_fixed three four_fixed four
.PHONY: formal-ctrl-pdr
formal-ctrl-pdr: $(FSBY_DEPS) formal/ctrl/ctrl.sby formal/ctrl/fctrl.v $(FSBY_RTL_ctrl) $(FCTRL_DIR)/base/.stamp ## [formal] the unbounded PDR tasks of the controller-top harness (up to an hour each)
	@for t in $(FCTRL_PDR); do $(FSBY_RUN) formal-ctrl-pdr-$$t --sby formal/ctrl/ctrl.sby --task $$t \
	    --expect pass --timeout 3700 || fail=1; done; exit $${fail:-0}

$(FCTRL_DIR)/base/.stamp: $(FCTRL_SRC) $(RTL_INC) formal/ctrl/tests.mk
	@rm -rf $(@D) && mkdir -p $(@D) && cp $(FCTRL_SRC) $(RTL_INC) $(@D)/ && touch $@
define fctrl_mutant_dir
$(FCTRL_DIR)/$(call neg_field,$(1),2)/.stamp: $(FCTRL_DIR)/base/.stamp $(FSBY_MUT)/ctrl/$(call neg_field,$(1),2)/$(call neg_field,$(1),3)
	@if [ ! -f $(FCTRL_DIR)/base/$(call neg_field,$(1),3) ]; then echo "mutant $(call neg_field,$(1),2) edits $(call neg_field,$(1),3), which the controller (CTRL_RTL) no longer has: retarget it"; exit 1; fi
	@rm -rf $$(@D) && cp -r $(FCTRL_DIR)/base $$(@D) && cp $(FSBY_MUT)/ctrl/$(call neg_field,$(1),2)/$(call neg_field,$(1),3) $$(@D)/ && touch $$@
test-formal-ctrl-negative-$(call neg_field,$(1),2): $(FCTRL_DIR)/$(call neg_field,$(1),2)/.stamp
endef
$(foreach m,$(FCTRL_MUTANTS),$(eval $(call fctrl_mutant_dir,$(m))))
$(foreach t,$(FSBY_TESTS_SPEC) $(FSBY_SLOW_SPEC),$(if $(filter ctrl,$(call neg_field,$(t),2)),test-$(call neg_field,$(t),1))): \
        $(FCTRL_DIR)/base/.stamp
test-formal-ctrl-shape-negative-drop_total: $(FCTRL_DIR)/drop_total/.stamp
