# tools/mk/fusesoc.mk -- the packaged IP: FuseSoC (PyPI fusesoc, CAPI2)
# core files beside their sources (rtl/*.core, c-driver/albatross_driver.core,
# soc/albatross_soc.core, fpga/albatross_duo.core, constraints/albatross_constraints.core,
# tb/endpoint/tb_endpoint_loop.core; docs/integration.md), checked the way a
# user meets them, by tools/fusesoc_check.py:
#   make test-fusesoc   the checkout as a FuseSoC library (fusesoc library add
#                       --sync-type local into build/fusesoc/main/fusesoc.conf,
#                       never fetches; SERV's folder of pythondata-cpu-serv and
#                       a core for pythondata-cpu-picorv32's picorv32.v added
#                       the same way): every core file loads and names existing
#                       files, every lint target passes (Verilator -Wall, the
#                       board tops included), the driver compiles from its core,
#                       and the simulation albatross:tb:endpoint_loop (Icarus)
#                       prints PASS.  About 15 s of CPU (17 Verilator lints,
#                       1 Icarus run of about 105,000 clocks).
#   make test-fusesoc-negative-<kind>   a copy of the library under
#                       build/fusesoc/neg-<kind>/ with one fault the check must
#                       reject, with the message naming it (tools/fusesoc_negative.sh):
#                       file (a core names a missing file), dep (the controller
#                       without its engines), schema (a core FuseSoC skips with a
#                       warning), sim (an Export engine mutant: torn values).
#   make fusesoc-boards the board targets through FuseSoC to their bitstreams (not
#                       in make test: minutes of CPU): icebreaker (Yosys,
#                       nextpnr-ice40, icepack) and ulx3s (Yosys, nextpnr-ecp5,
#                       ecppack: the YoWASP builds, through EDALIZE_LAUNCHER=
#                       tools/fusesoc_launcher.sh), on the images of make synth
#                       (build/fpga/duo/*.hex).  arty (Vivado) is not run.
# Everything FuseSoC writes stays in build/fusesoc/; build/FUSESOC_IGNORE keeps
# FuseSoC from reading the copies under build/ when the checkout is a library.

FUSESOC_DIR   := $(BUILD)/fusesoc
FUSESOC_SIM   := albatross:tb:endpoint_loop:1.0.0
FUSESOC_NEGS  := file dep schema sim
FUSESOC_DEPS  := $(wildcard rtl/*.core rtl/*.v rtl/*.vh c-driver/*.core c-driver/*.[ch] c-driver/port/mmio/*.h \
                   soc/*.core soc/*.vlt soc/*.v fpga/*.core fpga/*.v constraints/*) \
                 tb/endpoint/tb_endpoint_loop.core tb/endpoint/tb_endpoint_loop.v tools/fusesoc_check.py

TESTS += fusesoc $(addprefix fusesoc-negative-,$(FUSESOC_NEGS))
.PHONY: test-fusesoc $(addprefix test-fusesoc-negative-,$(FUSESOC_NEGS)) fusesoc-ignore

fusesoc-ignore:
	@mkdir -p $(BUILD) && touch $(BUILD)/FUSESOC_IGNORE

# The CPUs' libraries (tools/mk/pico.mk, serv.mk): deferred, those files are read after this one.
FUSESOC_LIBS   = --library $(SERV_CPU_DIR) --picorv32 $(PICO_RV32_V)

test-fusesoc: $(FUSESOC_DEPS) | fusesoc-ignore ## [test] the FuseSoC cores as a user meets them: load, lint, driver build, a simulation
	$(PICO_NEED)
	$(SERV_NEED)
	@tools/run_test.sh fusesoc $(PYTHON) tools/fusesoc_check.py --root . --work $(FUSESOC_DIR)/main \
	    $(addprefix --sim ,$(FUSESOC_SIM)) $(FUSESOC_LIBS)

$(addprefix test-fusesoc-negative-,$(FUSESOC_NEGS)): test-fusesoc-negative-%: $(FUSESOC_DEPS) tools/fusesoc_negative.sh | fusesoc-ignore
	@tools/run_test.sh fusesoc-negative-$* tools/fusesoc_negative.sh $*

# The core file a user writes (docs/integration.md, "In your own core"), taken
# from the page: it must load and lint with its dependencies; without its
# targets: section it must be rejected (tools/fusesoc_user_core.sh).
TESTS += fusesoc-user-core fusesoc-user-core-negative
.PHONY: test-fusesoc-user-core test-fusesoc-user-core-negative
test-fusesoc-user-core: $(FUSESOC_DEPS) docs/integration.md tools/fusesoc_user_core.sh | fusesoc-ignore
	@tools/run_test.sh fusesoc-user-core tools/fusesoc_user_core.sh
test-fusesoc-user-core-negative: $(FUSESOC_DEPS) docs/integration.md tools/fusesoc_user_core.sh | fusesoc-ignore
	@tools/run_test.sh fusesoc-user-core-negative tools/fusesoc_user_core.sh --negative

# The board targets through FuseSoC, on the config test-fusesoc wrote (run it
# first: the library and the PicoRV32 core are set up there).
FUSESOC_BOARDS := icebreaker ulx3s
.PHONY: fusesoc-boards
fusesoc-boards: test-fusesoc $(FPGA_IMAGES) ## the board targets through FuseSoC: iCEBreaker and ULX3S bitstreams (slow)
	@mkdir -p $(FUSESOC_DIR)/boards; set -e; for t in $(FUSESOC_BOARDS); do echo "fusesoc-boards: $$t (log $(FUSESOC_DIR)/boards/$$t.log)"; \
	    EDALIZE_LAUNCHER=$(abspath tools/fusesoc_launcher.sh) fusesoc --config $(FUSESOC_DIR)/main/fusesoc.conf run --build-root $(FUSESOC_DIR)/boards --target $$t \
	        albatross:board:duo:1.0.0 --ROM_FILE=$(abspath $(FPGA_IMG))/rom.hex --FW_PREFIX=$(abspath $(FPGA_IMG))/fw \
	        --RAM_PREFIX=$(abspath $(FPGA_IMG))/ram > $(FUSESOC_DIR)/boards/$$t.log 2>&1 || \
	        { tail -n 20 $(FUSESOC_DIR)/boards/$$t.log; exit 1; }; done
	@# nextpnr's fit and its final timing (the last report: one line per clock)
	@echo "icebreaker:"; grep -h "ICESTORM_LC:\|ICESTORM_RAM:" $(FUSESOC_DIR)/boards/icebreaker.log | tail -n 2; \
	    grep -h "Max frequency" $(FUSESOC_DIR)/boards/icebreaker.log | tail -n 1
	@echo "ulx3s:"; grep -h "TRELLIS_COMB:\|DP16KD:" $(FUSESOC_DIR)/boards/ulx3s.log | tail -n 2; \
	    grep -h "Max frequency" $(FUSESOC_DIR)/boards/ulx3s.log | tail -n 2
