# mk/pico_boards.mk -- the first multi-board system with real CPUs: four
# PicoRV32 boards (radar, odometry, navigation, motor of the MOBOT-III
# example), each with its own albatross_dpram, joined by albatross_bus and
# albatross_controller (tb/rtl/pico_boards.v, harness tb/pico/test_pico_boards.cpp).
#   make test-pico-boards   firmware firmware/mobot_<board>.c linked with the
#                           compiler-generated <board>.c and the real driver;
#                           the DPRAMs start from the compiler's RAM images,
#                           the controller runs the compiler's rom.hex; every
#                           Import is checked on the cores; build/reports/pico_boards.json
# Reuses PICO_RV32_V, PICO_NEED, FW_CFLAGS, FW_LDFLAGS, FW_DEPS of mk/pico.mk
# (included before this file: mk/*.mk are read in sorted order).
# pico_boards.v needs picorv32.v from PyPI: it is kept out of make lint here
# and linted (Verilator -Wall, Icarus, Yosys) at the end of test-pico-boards.
TB_RTL := $(filter-out tb/rtl/pico_boards.v,$(TB_RTL))

PB_DIR      := $(BUILD)/pico_boards
PB_SCHED    := $(BUILD)/schedule/mobot3
PB_BOARDS   := radar odometry navigation motor
PB_MAX_CYCLES ?= 5000000
PB_RTL      := tb/rtl/pico_boards.v tb/rtl/pico_core.v tb/rtl/board_memmap.v tb/rtl/pico_wb_adapter.v rtl/albatross_dpram.v \
               rtl/albatross_bus.v rtl/albatross_controller.v
PB_VFLAGS   := -Wall --timescale 1ns/1ps -y rtl -y tb/rtl --top-module pico_boards tb/pico/picorv32.vlt

# $(1) = board: firmware/mobot_<board>.c + generated <board>.c + the driver.
define pb_fw
$(PB_DIR)/fw/$(1).elf: firmware/mobot_$(1).c firmware/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -I$(PB_SCHED) -Icompiler/examples -o $$@ firmware/crt0.S \
	    firmware/mobot_$(1).c $(PB_SCHED)/$(1).c c-driver/albatross.c $(FW_LDFLAGS)
endef
$(foreach b,$(PB_BOARDS),$(eval $(call pb_fw,$(b))))

$(PB_DIR)/fw/%.hex: $(PB_DIR)/fw/%.elf
	$(DRV_RV_PREFIX)objcopy -O verilog --verilog-data-width=4 $< $@

PB_BIN := $(PB_DIR)/obj/Vpico_boards
$(PB_BIN): $(PB_RTL) $(PICO_RV32_V) tb/pico/test_pico_boards.cpp tb/pico/picorv32.vlt tb/report.h mk/pico_boards.mk
	$(PICO_NEED)
	@mkdir -p $(PB_DIR)
	verilator --cc --exe --build -j 2 -O3 $(PB_VFLAGS) -CFLAGS "-O2 -std=c++17" \
	    --Mdir $(PB_DIR)/obj $(PICO_RV32_V) tb/rtl/pico_boards.v $(abspath tb/pico/test_pico_boards.cpp) \
	    > $(PB_DIR)/build.log 2>&1 || { cat $(PB_DIR)/build.log; exit 1; }

PB_FW_ARGS := +fw0=$(PB_DIR)/fw/radar.hex +fw1=$(PB_DIR)/fw/odometry.hex \
              +fw2=$(PB_DIR)/fw/navigation.hex +fw3=$(PB_DIR)/fw/motor.hex \
              +ram0=$(PB_SCHED)/radar_ram.hex +ram1=$(PB_SCHED)/odometry_ram.hex \
              +ram2=$(PB_SCHED)/navigation_ram.hex +ram3=$(PB_SCHED)/motor_ram.hex \
              +rom=$(PB_SCHED)/rom.hex

TESTS += pico-boards
.PHONY: test-pico-boards
test-pico-boards: $(PB_BIN) $(foreach b,$(PB_BOARDS),$(PB_DIR)/fw/$(b).hex)
	@tools/run_test.sh pico-boards bash -c '$(PB_BIN) $(PB_FW_ARGS) --max-cycles $(PB_MAX_CYCLES) \
	    --seed $(SEED) --report $(REPORTS)/pico_boards.json && \
	    verilator --lint-only $(PB_VFLAGS) $(PICO_RV32_V) tb/rtl/pico_boards.v && \
	    iverilog -g2005 -y rtl -y tb/rtl -s pico_boards -o /dev/null $(PICO_RV32_V) tb/rtl/pico_boards.v && \
	    yosys -q -p "read_verilog $(PICO_RV32_V) $(PB_RTL); hierarchy -check -top pico_boards; proc" && \
	    echo "lint ok  tb/rtl/pico_boards.v"'
