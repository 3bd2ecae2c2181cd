# tools/mk/controller.mk -- smoke test of albatross_controller on the multi-board test
# top tb/system/tb_system.v: 4 boards (soc/albatross_system.v), albatross_bus, bus_fault_injector
# (tb/controller/test_controller.cpp, ctrl_bench.h/.cpp, ctrl_scenarios_*.cpp).  Outputs in build/ctrl/.
#   make test-controller-smoke            the self-checking run (all scenarios)
#   make test-controller-smoke-negative   the timing checker, given a formula one
#                                         clock off, must fail (exit 65: timing only)
# The model reads its ROM from "ctrl_rom.hex" in the working directory that
# each run selects with --dir, so the two runs never share a ROM file.

CTRL_DIR := $(BUILD)/ctrl
CTRL_BIN := $(CTRL_DIR)/obj/Vtb_system
CTRL_CPP := tb/controller/test_controller.cpp tb/controller/ctrl_bench.cpp \
            tb/controller/ctrl_scenarios_data.cpp tb/controller/ctrl_scenarios_faults.cpp
CTRL_SRC := tb/system/tb_system.v soc/albatross_system.v tb/common/bus_fault_injector.v $(CTRL_RTL) \
            rtl/albatross_bus.v rtl/albatross_dpram.v rtl/albatross_dpram_core.v $(CTRL_CPP) tb/controller/ctrl_bench.h \
            $(RTL_INC) tb/common/albatross_contract.h

$(CTRL_BIN): $(CTRL_SRC) tools/mk/controller.mk
	@mkdir -p $(CTRL_DIR)
	verilator --cc --exe --build -j 2 -O3 -Wall --top-module tb_system \
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
