# tools/mk/axil.mk -- albatross_dpram_axil, the DPRAM with an AXI4-Lite port A
# (docs/rtl.md "albatross_dpram_axil", docs/verification.md).
#
# Formal (registered by formal/axil/tests.mk through tools/mk/formal_sby.mk, the
# project's pattern for SymbiYosys proofs; listed here for the overview):
#   axil-formal                            k-induction of formal/axil/axil.sby: the
#                                          AXI4-Lite property set formal/axil/faxil_slave.v
#                                          on port A (response bounds 5 / 4 clocks),
#                                          fwb_slave on port B, shadow of one word
#                                          (about 8 s)
#   axil-formal-cover                      non-vacuity; both bounds reached (about 4 s)
#   axil-formal-negative-<mutant>          formal/axil/mutants/<mutant>.sed of
#                                          rtl/albatross_axil2native.v must fail on its
#                                          property (drop_wstrb_lane, late_start,
#                                          ready_ignores_full, rdata_unheld; 2-8 s each)
# Simulation (cocotb 2.x + cocotbext-axi under Icarus 11, tb/axil/):
#   axil-cocotb                            cocotbext-axi's AxiLiteMaster on port A, a
#                                          Wishbone driver on port B, reference model of
#                                          every byte, the bounds (about 6 s; figures in
#                                          build/reports/axil_cocotb.json)
#   axil-cocotb-negative-drop_wstrb_lane   the same test on the adapter without WSTRB
#                                          lane 0: must fail with "byte mismatch"
#   axil-cocotb-negative-late_start        the adapter that starts a request a clock
#                                          late: must fail with "write response bound"
# Synthesis: axil-bram (block RAM inferred through the wrapper, about 25 s).
# Longer random run: make soak-axil-cocotb (AXIL_SOAK_OPS accesses per phase, seed SEED).

AXIL_RUN       := $(PYTHON) tb/axil/run_axil.py
AXIL_SRC       := tb/axil/tb_axil.v tb/axil/test_axil.py tb/axil/run_axil.py \
                  $(CORE_dpram_axil)
AXIL_OPS       ?= 1500
AXIL_SOAK_OPS  ?= 40000
AXIL_SEED      ?= $(SEED)
AXIL_MUT       := $(BUILD)/axil/mutant-src
AXIL_COCOTB_NEG := drop_wstrb_lane late_start
# the message each negative must fail with
AXIL_NEG_MSG_drop_wstrb_lane := byte mismatch
AXIL_NEG_MSG_late_start      := write response bound

TESTS += axil-cocotb $(addprefix axil-cocotb-negative-,$(AXIL_COCOTB_NEG))
.PHONY: test-axil-cocotb soak-axil-cocotb $(addprefix test-axil-cocotb-negative-,$(AXIL_COCOTB_NEG))

test-axil-cocotb: $(AXIL_SRC)
	@tools/run_test.sh axil-cocotb $(AXIL_RUN) axil-cocotb --ops $(AXIL_OPS) --seed $(AXIL_SEED) \
	    --report $(REPORTS)/axil_cocotb.json

soak-axil-cocotb: $(AXIL_SRC) ## AXI4-Lite DPRAM cocotb test, AXIL_SOAK_OPS accesses per phase (a few minutes)
	$(AXIL_RUN) axil-cocotb-soak --ops $(AXIL_SOAK_OPS) --seed $(SEED)

# The adapter mutants are the formal ones (formal/axil/mutants/*.sed), built here
# on their own so the simulation does not depend on the formal build.
$(AXIL_MUT)/%/albatross_axil2native.v: formal/axil/mutants/%.sed rtl/albatross_axil2native.v
	@mkdir -p $(@D)
	sed -f $< rtl/albatross_axil2native.v > $@
	@if cmp -s $@ rtl/albatross_axil2native.v; then echo "mutant $* did not apply: rtl/albatross_axil2native.v no longer has the line $< edits"; \
	    rm -f $@; exit 1; fi

define axil_cocotb_neg
test-axil-cocotb-negative-$(1): $(AXIL_SRC) $(AXIL_MUT)/$(1)/albatross_axil2native.v
	@tools/run_test.sh axil-cocotb-negative-$(1) $(AXIL_RUN) axil-cocotb-negative-$(1) \
	    --adapter $(AXIL_MUT)/$(1)/albatross_axil2native.v --ops $(AXIL_OPS) --seed $(AXIL_SEED) \
	    --expect-fail '$(AXIL_NEG_MSG_$(1))'
endef
$(foreach n,$(AXIL_COCOTB_NEG),$(eval $(call axil_cocotb_neg,$(n))))

# The AXI4-Lite wrapper still infers block RAM on iCE40, ECP5 and xc7 (Yosys,
# ADDR_WIDTH 10; about 25 s; figures in build/reports/synth_albatross_dpram_axil.json).
# Its negative is dpram-bram-negative (tools/mk/synth_check.mk): the same check
# rejects a RAM that does not map.
TESTS += axil-bram
.PHONY: test-axil-bram
test-axil-bram: $(CORE_dpram_axil)
	@tools/run_test.sh axil-bram $(SYNTH_REPORT) albatross_dpram_axil \
	    --file $(subst $(space),$(comma),$(strip $(CORE_dpram_axil))) --require-bram \
	    --report $(REPORTS)/synth_albatross_dpram_axil.json
