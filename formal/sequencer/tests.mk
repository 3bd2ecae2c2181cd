# formal/sequencer/tests.mk -- the SymbiYosys tests of formal/sequencer/sequencer.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-sequencer:sequencer:prove:pass \
    formal-sequencer-sync:sequencer:prove_sync:pass \
    formal-sequencer-error:sequencer:prove_bad:pass \
    formal-sequencer-rep8:sequencer:prove_rep8:pass \
    formal-sequencer-cover:sequencer:cover:pass \
    formal-sequencer-cover-sync:sequencer:cover_sync:pass \
    formal-sequencer-cover-error:sequencer:cover_bad:pass \
    formal-sequencer-negative-slot_late:sequencer:neg_slot_late:go_time \
    formal-sequencer-negative-deadline_late:sequencer:neg_deadline_late:deadline \
    formal-sequencer-negative-start_bad_crc:sequencer:neg_start_bad_crc:idle_on_error \
    formal-sequencer-negative-wrong_cycle:sequencer:neg_wrong_cycle:go_given \
    formal-sequencer-negative-rep_short:sequencer:neg_rep_short:go_time \
    formal-sequencer-negative-count_early:sequencer:neg_count_early:go_time \
    formal-sequencer-negative-count_stuck:sequencer:neg_count_stuck:go_given
FSBY_MUTANTS += sequencer:slot_late:albatross_slot_timing.v sequencer:deadline_late:albatross_slot_timing.v \
                sequencer:start_bad_crc \
                sequencer:wrong_cycle:albatross_minor_cycles.v sequencer:rep_short:albatross_minor_cycles.v \
                sequencer:count_early:albatross_minor_cycles.v sequencer:count_stuck:albatross_minor_cycles.v
FSBY_RTL_sequencer := rtl/albatross_sequencer.v rtl/albatross_schedule_rom.v rtl/albatross_rom_check.v \
                      rtl/albatross_entry_check.v rtl/albatross_mode_switch.v rtl/albatross_entry_fields.v rtl/albatross_sync_poll.v \
                      rtl/albatross_minor_cycles.v rtl/albatross_header_check.v rtl/albatross_seq_status.v \
                      rtl/albatross_slot_timing.v

# The ROM images of the proofs and their decoded fields, written by gen_rom.py with the
# schedule compiler's encoder and CRC (sequencer.sby reads them from this folder).
FSEQ_ROM       := $(BUILD)/formal/sby/sequencer-rom
FSEQ_ROM_FILES := $(foreach i,time sync badcrc rep8,$(FSEQ_ROM)/$(i).hex $(FSEQ_ROM)/$(i).vh)
$(FSEQ_ROM_FILES) &: formal/sequencer/gen_rom.py rtl/albatross_contract.toml \
                     $(wildcard compiler/albatross_schedule/*.py)
	$(PYTHON) formal/sequencer/gen_rom.py $(FSEQ_ROM)
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-sequencer proves (make formal-slow).
FSBY_SLOW_SPEC += formal-sequencer-pdr:sequencer:prove_pdr:pass
# Every sequencer test, make test-slow's too, needs the images (listed after
# both specs: a target list is expanded where make reads it).
$(foreach t,$(FSBY_TESTS_SPEC) $(FSBY_SLOW_SPEC),$(if $(filter sequencer,$(call neg_field,$(t),2)),test-$(call neg_field,$(t),1))): \
        $(FSEQ_ROM_FILES)
