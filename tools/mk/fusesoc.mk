# tools/mk/fusesoc.mk -- the packaged IP (issue 14): FuseSoC (PyPI fusesoc, CAPI2)
# core files beside their sources (rtl/*.core, c-driver/albatross_driver.core,
# tb/endpoint/tb_endpoint_loop.core; docs/integration.md), checked the way a user
# meets them, by tools/fusesoc_check.py:
#   make test-fusesoc   the checkout as a FuseSoC library (fusesoc library add
#                       --sync-type local into build/fusesoc/main/fusesoc.conf,
#                       never fetches): every core file loads and names existing
#                       files, every lint target passes (Verilator -Wall), the
#                       driver compiles from its core, and the simulation
#                       albatross:tb:endpoint_loop (Icarus) prints PASS.
#                       About 10 s of CPU (9 Verilator lints, 1 Icarus run).
#   make test-fusesoc-negative-<kind>   a copy of the library under
#                       build/fusesoc/neg-<kind>/ with one fault the check must
#                       reject, with the message naming it (tools/fusesoc_negative.sh):
#                       file (a core names a missing file), dep (the controller
#                       without its engines), schema (a core FuseSoC skips with a
#                       warning), sim (an Export engine mutant: torn values).
# Everything FuseSoC writes stays in build/fusesoc/; build/FUSESOC_IGNORE keeps
# FuseSoC from reading the copies under build/ when the checkout is a library.

FUSESOC_DIR   := $(BUILD)/fusesoc
FUSESOC_SIM   := albatross:tb:endpoint_loop:1.0.0
FUSESOC_NEGS  := file dep schema sim
FUSESOC_DEPS  := $(wildcard rtl/*.core rtl/*.v rtl/*.vh c-driver/*.core c-driver/*.[ch] c-driver/port/mmio/*.h) \
                 tb/endpoint/tb_endpoint_loop.core tb/endpoint/tb_endpoint_loop.v tools/fusesoc_check.py

TESTS += fusesoc $(addprefix fusesoc-negative-,$(FUSESOC_NEGS))
.PHONY: test-fusesoc $(addprefix test-fusesoc-negative-,$(FUSESOC_NEGS)) fusesoc-ignore

fusesoc-ignore:
	@mkdir -p $(BUILD) && touch $(BUILD)/FUSESOC_IGNORE

test-fusesoc: $(FUSESOC_DEPS) | fusesoc-ignore
	@tools/run_test.sh fusesoc $(PYTHON) tools/fusesoc_check.py --root . --work $(FUSESOC_DIR)/main --sim $(FUSESOC_SIM)

$(addprefix test-fusesoc-negative-,$(FUSESOC_NEGS)): test-fusesoc-negative-%: $(FUSESOC_DEPS) tools/fusesoc_negative.sh | fusesoc-ignore
	@tools/run_test.sh fusesoc-negative-$* tools/fusesoc_negative.sh $*
