# tools/mk/parts.mk -- the controller's parts: albatross_sequencer
# (with its albatross_schedule_rom, albatross_rom_check and albatross_entry_check),
# albatross_bus_master, albatross_counters, each on its own (the engines have
# tools/mk/endpoint.mk; rtl/albatross_controller.v composes them all).
#   make test-parts-lint        each part synthesises on its own in Yosys (the
#                               sequencer's own parts inside it, once); Verilator
#                               -Wall and Icarus check each of them in make lint
#   make test-sequencer         tb/sequencer/tb_sequencer.v on the ROM of
#                               tb/sequencer/make_rom.py (new format: whole-ROM
#                               CRC, no per-entry checksum): slot starts, the
#                               deadline, cycle length, a ROM upset found by the
#                               background check and its entry skipped
#   make test-sequencer-bad-start0
#                               the same bench with entry 0's start above
#                               TIME_BITS: skipped and counted every cycle
#   make test-sequencer-negative-slot_late
#                               the same bench on a sequencer whose slots start
#                               one clock late (formal/rtl/mutants/slot_late.sed):
#                               passes only if the bench fails and names the go
#   make test-sequencer-multirate
#                               tb/sequencer/tb_sequencer_multirate.v on a
#                               multi-rate image (make_rom.py --multirate:
#                               cluster 8, reps 0 to 8, three entries in one
#                               window): every go and every cycle against the
#                               bench's model of the due rule, the count's wrap,
#                               invalid E6 entries (rep above the cluster)
#                               counted in rom_errors, an entry whose base is not
#                               below 2^rep run in the cycles n mod 2^rep =
#                               base mod 2^rep
#   make test-sequencer-multirate-modes
#                               the same with a mode switch to a cluster of 4
#                               and back: the count restarts at each switch
#   make test-sequencer-multirate-negative-no_reset, -e6_unchecked, -base_high
#                               the bench on a sequencer whose count does not
#                               restart at a switch, whose entry check forgets
#                               E6 (rep above the cluster), or whose due test
#                               asks base < 2^rep too (tb/sequencer/mutants/):
#                               must fail
# Outputs in build/parts/.

PARTS_DIR := $(BUILD)/parts
PARTS     := albatross_sequencer albatross_schedule_rom albatross_rom_check albatross_entry_check albatross_mode_switch albatross_entry_fields albatross_sync_poll \
             albatross_minor_cycles albatross_header_check albatross_seq_status albatross_slot_timing \
             albatross_bus_master albatross_counters
# The modules albatross_sequencer instantiates.
SEQ_SUB   := rtl/albatross_schedule_rom.v rtl/albatross_rom_check.v rtl/albatross_entry_check.v rtl/albatross_mode_switch.v rtl/albatross_entry_fields.v rtl/albatross_sync_poll.v \
             rtl/albatross_minor_cycles.v rtl/albatross_header_check.v rtl/albatross_seq_status.v \
             rtl/albatross_slot_timing.v

TESTS += parts-lint sequencer sequencer-bad-start0 sequencer-negative-slot_late \
         sequencer-modes sequencer-modes-bad sequencer-modes-negative sequencer-modes-switch \
         sequencer-modes-switch-negative sequencer-multirate sequencer-multirate-modes \
         sequencer-multirate-negative-no_reset sequencer-multirate-negative-e6_unchecked \
         sequencer-multirate-negative-base_high
.PHONY: test-parts-lint test-sequencer test-sequencer-bad-start0 test-sequencer-negative-slot_late \
        test-sequencer-modes test-sequencer-modes-bad test-sequencer-modes-negative test-sequencer-modes-switch \
        test-sequencer-modes-switch-negative test-sequencer-multirate test-sequencer-multirate-modes \
        test-sequencer-multirate-negative-no_reset test-sequencer-multirate-negative-e6_unchecked \
        test-sequencer-multirate-negative-base_high

test-parts-lint: $(addprefix rtl/,$(addsuffix .v,$(PARTS))) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)
	@tools/run_test.sh parts-lint bash -c 'set -e; for m in $(PARTS); do \
	    case " $(SEQ_SUB) " in *" rtl/$$m.v "*) echo "$$m: synthesised inside albatross_sequencer"; continue;; esac; \
	    sub=; if [ $$m = albatross_sequencer ]; then sub="$(SEQ_SUB)"; fi; \
	    yosys -q -p "read_verilog -Irtl rtl/$$m.v $$sub; synth -top $$m" > $(PARTS_DIR)/$$m.yosys.log; \
	    echo "$$m: Yosys synthesis clean"; done'

test-sequencer: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)/seq
	@tools/run_test.sh sequencer bash -c 'set -e; $(PYTHON) tb/sequencer/make_rom.py $(PARTS_DIR)/seq/seq_rom.hex; \
	    iverilog -g2005 -Irtl -o $(PARTS_DIR)/seq/tb tb/sequencer/tb_sequencer.v rtl/albatross_sequencer.v \
	        $(SEQ_SUB); \
	    cd $(PARTS_DIR)/seq && vvp -n tb | grep -v readmemh | tee tb.log; grep -q "^PASS" tb.log'

# The negative: the mutant must make the bench print the slot-start failure.
test-sequencer-negative-slot_late: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v \
        formal/rtl/mutants/slot_late.sed $(SEQ_SUB) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)/seq-neg
	@tools/run_test.sh sequencer-negative-slot_late bash -c 'set -e; $(PYTHON) tb/sequencer/make_rom.py $(PARTS_DIR)/seq-neg/seq_rom.hex; \
	    sed -f formal/rtl/mutants/slot_late.sed rtl/albatross_sequencer.v > $(PARTS_DIR)/seq-neg/albatross_sequencer.v; \
	    if cmp -s $(PARTS_DIR)/seq-neg/albatross_sequencer.v rtl/albatross_sequencer.v; then echo "mutant slot_late did not apply"; exit 1; fi; \
	    iverilog -g2005 -Irtl -o $(PARTS_DIR)/seq-neg/tb tb/sequencer/tb_sequencer.v $(PARTS_DIR)/seq-neg/albatross_sequencer.v \
	        $(SEQ_SUB); \
	    cd $(PARTS_DIR)/seq-neg && vvp -n tb | grep -v readmemh > tb.log || true; \
	    if grep -q "^PASS" tb.log; then echo "the bench passed a sequencer whose slots start late"; exit 1; fi; \
	    if ! grep -q "^FAIL entry .* go at" tb.log; then echo "expected a FAIL naming the go clock, got: $$(head -n 3 tb.log)"; exit 1; fi; \
	    echo "caught: $$(grep -m1 "^FAIL entry" tb.log)"'

test-sequencer-bad-start0: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)/seq-bad0
	@tools/run_test.sh sequencer-bad-start0 bash -c 'set -e; $(PYTHON) tb/sequencer/make_rom.py $(PARTS_DIR)/seq-bad0/seq_rom.hex --bad-start0; \
	    iverilog -g2005 -Irtl -o $(PARTS_DIR)/seq-bad0/tb tb/sequencer/tb_sequencer.v rtl/albatross_sequencer.v \
	        $(SEQ_SUB); \
	    cd $(PARTS_DIR)/seq-bad0 && vvp -n tb +bad_start0 | grep -v readmemh | tee tb.log; grep -q "^PASS" tb.log'

# An image with two modes (make_rom.py --modes): the sequencer runs the
# start-up mode's entries only, and the background check covers the mode
# descriptors; --modes-bad: H2.start_end beyond NE is an invalid header.  The negative: a sequencer that ends the cycle at NE (all entries)
# runs the other mode's entries, which the bench must catch.
SEQ_MODES = set -e; mkdir -p $(PARTS_DIR)/$(1); $(PYTHON) tb/sequencer/make_rom.py $(PARTS_DIR)/$(1)/seq_rom.hex $(2); \
	    iverilog -g2005 -Irtl -o $(PARTS_DIR)/$(1)/tb tb/sequencer/tb_sequencer.v $(3); \
	    cd $(PARTS_DIR)/$(1) && vvp -n tb $(4) | grep -v readmemh > tb.log || true; cat tb.log
test-sequencer-modes: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@tools/run_test.sh sequencer-modes bash -c '$(call SEQ_MODES,seq-modes,--modes,rtl/albatross_sequencer.v $(SEQ_SUB),+modes); \
	    grep -q "^PASS" tb.log'
test-sequencer-modes-switch: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@tools/run_test.sh sequencer-modes-switch bash -c '$(call SEQ_MODES,seq-modes-switch,--modes,rtl/albatross_sequencer.v $(SEQ_SUB),+modes_switch); \
	    grep -q "^PASS" tb.log'
test-sequencer-modes-bad: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@tools/run_test.sh sequencer-modes-bad bash -c '$(call SEQ_MODES,seq-modes-bad,--modes-bad,rtl/albatross_sequencer.v $(SEQ_SUB),+modes_bad); \
	    grep -q "^PASS" tb.log'
test-sequencer-modes-negative: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)/seq-modes-neg
	@sed 's/last_ent  = ent_inc == m_end;/last_ent  = ent_inc == ne_q;/' rtl/albatross_sequencer.v > $(PARTS_DIR)/seq-modes-neg/albatross_sequencer.v
	@tools/run_test.sh sequencer-modes-negative bash -c 'if cmp -s $(PARTS_DIR)/seq-modes-neg/albatross_sequencer.v rtl/albatross_sequencer.v; then \
	        echo "the edit (cycle end at NE) did not apply to rtl/albatross_sequencer.v"; exit 1; fi; \
	    $(call SEQ_MODES,seq-modes-neg,--modes,$(PARTS_DIR)/seq-modes-neg/albatross_sequencer.v $(SEQ_SUB),+modes); \
	    if grep -q "^PASS" tb.log; then echo "the bench passed a sequencer that runs every mode'"'"'s entries"; exit 1; fi; \
	    grep -q "^FAIL" tb.log && echo "caught: $$(grep -m1 "^FAIL" tb.log)"'
# The negative of the switch: a mode switch that takes effect as soon as
# the mode is loaded, before the cycle boundary, must fail the bench.
test-sequencer-modes-switch-negative: tb/sequencer/tb_sequencer.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
	@mkdir -p $(PARTS_DIR)/seq-switch-neg
	@sed 's/default: if (switch_i) begin               \/\/ L_READY: the boundary/default: if (1'"'"'b1) begin/' \
	    rtl/albatross_mode_switch.v > $(PARTS_DIR)/seq-switch-neg/albatross_mode_switch.v
	@tools/run_test.sh sequencer-modes-switch-negative bash -c 'if cmp -s $(PARTS_DIR)/seq-switch-neg/albatross_mode_switch.v \
	        rtl/albatross_mode_switch.v; then echo "the edit (switch before the boundary) did not apply to rtl/albatross_mode_switch.v"; exit 1; fi; \
	    $(call SEQ_MODES,seq-switch-neg,--modes,rtl/albatross_sequencer.v $(filter-out rtl/albatross_mode_switch.v,$(SEQ_SUB)) \
	        $(PARTS_DIR)/seq-switch-neg/albatross_mode_switch.v,+modes_switch); \
	    if grep -q "^PASS" tb.log; then echo "the bench passed a mode switch before the cycle boundary"; exit 1; fi; \
	    grep -q "^FAIL" tb.log && echo "caught: $$(grep -m1 "^FAIL" tb.log)"'

# The multi-rate bench: $(1) = folder, $(2) = make_rom.py option, $(3) = the
# sequencer and its parts (a mutant in the place of one), $(4) = plusargs.
SEQ_MR = set -e; mkdir -p $(PARTS_DIR)/$(1); $(PYTHON) tb/sequencer/make_rom.py $(PARTS_DIR)/$(1)/seq_rom.hex $(2); \
	    iverilog -g2005 -Irtl -o $(PARTS_DIR)/$(1)/tb tb/sequencer/tb_sequencer_multirate.v $(3); \
	    cd $(PARTS_DIR)/$(1) && vvp -n tb $(4) | grep -v readmemh > tb.log || true; cat tb.log
SEQ_MR_DEPS := tb/sequencer/tb_sequencer_multirate.v tb/sequencer/make_rom.py rtl/albatross_sequencer.v $(SEQ_SUB) $(RTL_INC)
test-sequencer-multirate: $(SEQ_MR_DEPS)
	@tools/run_test.sh sequencer-multirate bash -c '$(call SEQ_MR,seq-mr,--multirate,rtl/albatross_sequencer.v $(SEQ_SUB),); \
	    grep -q "^PASS" tb.log'
test-sequencer-multirate-modes: $(SEQ_MR_DEPS)
	@tools/run_test.sh sequencer-multirate-modes bash -c '$(call SEQ_MR,seq-mr-modes,--multirate-modes,rtl/albatross_sequencer.v $(SEQ_SUB),+modes); \
	    grep -q "^PASS" tb.log'
# $(1) = mutant (tb/sequencer/mutants/$(1).sed), $(2) = the file it breaks, $(3) = make_rom.py option, $(4) = plusargs.
define seq_mr_negative
test-sequencer-multirate-negative-$(1): $(SEQ_MR_DEPS) tb/sequencer/mutants/$(1).sed
	@mkdir -p $(PARTS_DIR)/seq-mr-neg-$(1)
	@sed -f tb/sequencer/mutants/$(1).sed rtl/$(2) > $(PARTS_DIR)/seq-mr-neg-$(1)/$(2)
	@tools/run_test.sh sequencer-multirate-negative-$(1) bash -c 'if cmp -s $(PARTS_DIR)/seq-mr-neg-$(1)/$(2) rtl/$(2); then \
	        echo "mutant $(1) did not apply: rtl/$(2) no longer has the line its .sed edits"; exit 1; fi; \
	    $$(call SEQ_MR,seq-mr-neg-$(1),$(3),$(filter-out rtl/$(2),rtl/albatross_sequencer.v $(SEQ_SUB)) $(PARTS_DIR)/seq-mr-neg-$(1)/$(2),$(4)); \
	    if grep -q "^PASS" tb.log; then echo "the bench passed the broken sequencer $(1)"; exit 1; fi; \
	    grep -q "^FAIL" tb.log && echo "caught: $$$$(grep -m1 "^FAIL" tb.log)"'
endef
$(eval $(call seq_mr_negative,no_reset,albatross_minor_cycles.v,--multirate-modes,+modes))
$(eval $(call seq_mr_negative,e6_unchecked,albatross_entry_check.v,--multirate,))
$(eval $(call seq_mr_negative,base_high,albatross_minor_cycles.v,--multirate,))
