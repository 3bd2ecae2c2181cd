# tools/mk/pico_boards.mk -- the multi-board system with real CPUs: four PicoRV32
# boards (radar, odometry, navigation, motor of the MOBOT-III example), each
# with its own albatross_dpram, joined by albatross_bus and
# albatross_controller behind a bus fault injector (sim/pico_boards.v: the
# shared soc/albatross_system.v, the injector and the images' plusargs);
# harness sim/mobot_sim.cpp with sim/mobot_sim_options.cpp, sim/mobot_sim_ages.cpp, sim/mobot_sim_clock.cpp,
# sim/mobot_sim_report.cpp
# and sim/mobot_sim.h (make sim runs the same model, tools/mk/sim.mk).
# Each board's firmware is sim/firmware/mobot_<board>.c linked with the
# compiler-generated <board>.c and the real driver; the DPRAMs start from the
# compiler's RAM images, the controller runs the compiler's rom.hex; every
# Import is checked on the cores and reported to the harness as an event.
#   make test-pico-boards           fault-free, cores stalled in random bursts
#   make test-pico-boards-faults    5 % of the controller's requests faulted
#   make test-pico-boards-crash     the radar crashes inside an Export
#   make test-pico-boards-negative-*  one per check of the harness, each
#                                   with a firmware/driver mutant
#                                   (sim/mutants/) or an option
# Reuses PICO_RV32_V, PICO_NEED, FW_CFLAGS, FW_LDFLAGS, FW_DEPS of tools/mk/pico.mk
# (included before this file: tools/mk/*.mk are read in sorted order).
# pico_boards.v needs picorv32.v from PyPI: it is kept out of make lint and
# linted (Verilator -Wall, Icarus, Yosys) by test-pico-boards-lint, with
# its Icarus bench sim/pico_boards_tb.v (make bench-sim-speed, tools/mk/sim.mk).

PB_DIR      := $(BUILD)/pico_boards
PB_SCHED    := $(BUILD)/schedule/mobot3
PB_BOARDS   := radar odometry navigation motor
PB_CYCLES   ?= 1500000
PB_RTL      := sim/pico_boards.v tb/common/bus_fault_injector.v $(CORE_soc_system)
PB_VFLAGS   := -Wall --timescale 1ns/1ps $(VLIB) --top-module pico_boards tb/pico/picorv32.vlt
PB_SRC      := sim/mobot_sim.cpp sim/mobot_sim_options.cpp sim/mobot_sim_ages.cpp sim/mobot_sim_clock.cpp sim/mobot_sim_modes.cpp \
               sim/mobot_sim_report.cpp tb/common/plan.cpp
PB_HDR      := sim/mobot_sim.h tb/common/fault_model.h tb/common/report.h tb/common/plan.h tb/common/albatross_contract.h

# $(1) = board: sim/firmware/mobot_<board>.c + the generated <board>.c of the
# schedule build/schedule/<sched>/ + the driver -> $(PB_DIR)/<sched>/fw/.
# Local time: fw-clock/ also links c-driver/alb_clock.c
# and reads TIMER (soc/board_memmap.v) as alb_local_time(), so every board
# syncs its clock and reports its estimates (tools/mk/sim.mk, test-sim-clock*);
# fw-clock-norate/ is the same without rate correction (-DALB_CLOCK_NO_RATE,
# the negative test).  The clock costs each loop some hundred cycles on
# rv32i (no multiply instruction), so the scenario tests above keep fw/.
PB_CLOCK_FLAGS := -DALB_LOCAL_TIMER_ADDR=0x20000040u
PB_CLOCK_DEPS  := c-driver/alb_clock.c c-driver/alb_clock.h
define pb_fw
$(PB_DIR)/%/fw/$(1).elf: sim/firmware/mobot_$(1).c sim/firmware/mobot_check.h $(BUILD)/schedule/%/rom.hex $(FW_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -I$(BUILD)/schedule/$$* -Isim -o $$@ soc/firmware/crt0.S \
	    sim/firmware/mobot_$(1).c $(BUILD)/schedule/$$*/$(1).c c-driver/albatross.c $(FW_LDFLAGS)
$(PB_DIR)/%/fw-clock/$(1).elf: sim/firmware/mobot_$(1).c sim/firmware/mobot_check.h $(BUILD)/schedule/%/rom.hex $(FW_DEPS) $(PB_CLOCK_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(PB_CLOCK_FLAGS) -I$(BUILD)/schedule/$$* -Isim -o $$@ soc/firmware/crt0.S \
	    sim/firmware/mobot_$(1).c $(BUILD)/schedule/$$*/$(1).c c-driver/albatross.c c-driver/alb_clock.c $(FW_LDFLAGS)
$(PB_DIR)/%/fw-clock-norate/$(1).elf: sim/firmware/mobot_$(1).c sim/firmware/mobot_check.h $(BUILD)/schedule/%/rom.hex $(FW_DEPS) $(PB_CLOCK_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(PB_CLOCK_FLAGS) -DALB_CLOCK_NO_RATE -I$(BUILD)/schedule/$$* -Isim -o $$@ soc/firmware/crt0.S \
	    sim/firmware/mobot_$(1).c $(BUILD)/schedule/$$*/$(1).c c-driver/albatross.c c-driver/alb_clock.c $(FW_LDFLAGS)
endef
$(foreach b,$(PB_BOARDS),$(eval $(call pb_fw,$(b))))

# The model, without and with waves (--trace, for make sim TRACE=1).
# $(1) = variant dir, $(2) = extra Verilator flags.
define pb_model
$(PB_DIR)/$(1)/Vpico_boards: $(PB_RTL) $(RTL_INC) $(PICO_RV32_V) $(PB_SRC) $(PB_HDR) tb/pico/picorv32.vlt tools/mk/pico_boards.mk
	$$(PICO_NEED)
	@mkdir -p $$(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(2) $(PB_VFLAGS) -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" \
	    --Mdir $$(@D) $(PICO_RV32_V) sim/pico_boards.v $(abspath $(PB_SRC)) \
	    > $$(@D)/build.log 2>&1 || { cat $$(@D)/build.log; exit 1; }
endef
$(eval $(call pb_model,obj,))
$(eval $(call pb_model,obj-trace,--trace))
PB_BIN := $(PB_DIR)/obj/Vpico_boards

# Arguments of a run: $(1) = schedule dir, $(2) = firmware dir, $(3) = radar
# image, $(4) = navigation image.
pb_args = +fw0=$(3) +fw1=$(2)/odometry.hex +fw2=$(4) +fw3=$(2)/motor.hex \
          +ram0=$(1)/radar_ram.hex +ram1=$(1)/odometry_ram.hex +ram2=$(1)/navigation_ram.hex \
          +ram3=$(1)/motor_ram.hex +rom=$(1)/rom.hex --plan $(1)/tb_plan.txt
PB_FWDIR  := $(PB_DIR)/mobot3/fw
PB_FW     := $(foreach b,$(PB_BOARDS),$(PB_FWDIR)/$(b).hex)
pb_fw_args = $(call pb_args,$(PB_SCHED),$(PB_FWDIR),$(1),$(2))
PB_FW_ARGS = $(call pb_fw_args,$(PB_FWDIR)/radar.hex,$(PB_FWDIR)/navigation.hex)

# Cold start on zeroed RAMs: every board's RAM image is all zero (no image
# from the compiler) and its firmware, built with -DMOBOT_COLD_START, calls
# alb_<board>_init_all instead of _attach_all (docs/protocol.md "Cold
# start").  Every check of the harness must pass, as from the image.
PB_COLD_DIR := $(PB_DIR)/mobot3/cold
define pb_fw_cold
$(PB_COLD_DIR)/fw/$(1).elf: sim/firmware/mobot_$(1).c sim/firmware/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -DMOBOT_COLD_START -I$(PB_SCHED) -Isim -o $$@ soc/firmware/crt0.S \
	    sim/firmware/mobot_$(1).c $(PB_SCHED)/$(1).c c-driver/albatross.c $(FW_LDFLAGS)
$(PB_COLD_DIR)/fw-old/$(1).elf: sim/firmware/mobot_$(1).c sim/firmware/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS) \
                                  $(DRV_UNIT)/cold_zero_corrupt/albatross.c
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -DMOBOT_COLD_START -I$(PB_SCHED) -Isim -o $$@ soc/firmware/crt0.S \
	    sim/firmware/mobot_$(1).c $(PB_SCHED)/$(1).c $(DRV_UNIT)/cold_zero_corrupt/albatross.c $(FW_LDFLAGS)
$(PB_COLD_DIR)/$(1)_ram.hex: $(PB_SCHED)/$(1)_ram.hex
	@mkdir -p $$(@D)
	sed 's/./0/g' $$< > $$@
endef
$(foreach b,$(PB_BOARDS),$(eval $(call pb_fw_cold,$(b))))
PB_COLD_FILES := $(foreach b,$(PB_BOARDS),$(PB_COLD_DIR)/fw/$(b).hex $(PB_COLD_DIR)/$(b)_ram.hex)
# Its negative: the same with the driver as it was before the cold-start
# contract (tb/unit/mutants/cold_zero_corrupt.sed, a 0 is ALB_ERR_CORRUPT):
# the motor's first Import, before the controller's first Export, fails.
PB_COLD_OLD := $(foreach b,$(PB_BOARDS),$(PB_COLD_DIR)/fw-old/$(b).hex $(PB_COLD_DIR)/$(b)_ram.hex)
pb_cold_args = $(subst $(PB_SCHED)/,$(PB_COLD_DIR)/,$(filter +ram%,$(call pb_args,$(PB_SCHED),$(1),$(1)/radar.hex,$(1)/navigation.hex))) \
    $(filter-out +ram%,$(call pb_args,$(PB_SCHED),$(1),$(1)/radar.hex,$(1)/navigation.hex))
TESTS += pico-boards-cold-start pico-boards-cold-start-negative
.PHONY: test-pico-boards-cold-start test-pico-boards-cold-start-negative
test-pico-boards-cold-start-negative: $(PB_BIN) $(PB_COLD_OLD) $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh pico-boards-cold-start-negative $(PB_BIN) $(call pb_cold_args,$(PB_COLD_DIR)/fw-old) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --label pico-boards-cold-start-negative \
	    --expect-caught-by cpu
test-pico-boards-cold-start: $(PB_BIN) $(PB_COLD_FILES) $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh pico-boards-cold-start $(PB_BIN) $(call pb_cold_args,$(PB_COLD_DIR)/fw) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --require-done --label pico-boards-cold-start \
	    --report $(REPORTS)/pico_boards_cold_start.json

# Scenario tests: NAME:OPTIONS (commas for spaces).
PB_SCENARIOS := \
  pico-boards:--stall,2048,--require-done \
  pico-boards-faults:--stall,2048,--fault-rate,0.05,--require-done \
  pico-boards-crash:--stall,2048,--crash,radar@200000
define pb_scenario
TESTS += $(call neg_field,$(1),1)
.PHONY: test-$(call neg_field,$(1),1)
test-$(call neg_field,$(1),1): $(PB_BIN) $(PB_FW) $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh $(call neg_field,$(1),1) $(PB_BIN) $(PB_FW_ARGS) --cycles $(PB_CYCLES) --seed $(SEED) \
	    --label $(call neg_field,$(1),1) $(subst $(comma), ,$(call neg_field,$(1),2)) \
	    --report $(REPORTS)/$(subst -,_,$(call neg_field,$(1),1)).json
endef
$(foreach s,$(PB_SCENARIOS),$(eval $(call pb_scenario,$(s))))

# The robot on the image of its two modes (build/schedule/mobot3-modes,
# cruise and dock): navigation asks for dock and back (its firmware built
# against that plan), every check of pico-boards holds with each age judged
# by the bound of the mode in force, RadarMap goes stale in dock, and check
# "mode" wants at least three switches, each within the compiler's
# switch_latency and published as Mode (sim/mobot_sim_modes.cpp).
# pico-boards-modes-faults does it at 5 % faults (the age and latency checks
# are off under faults, as in pico-boards-faults), pico-boards-modes-crash
# with the radar crashing in cruise (stale before and after); the negatives judge the
# same run against half the compiler's switch latency (check mode must fail)
# and half the age bounds in force (check age must fail).
PB_MODES := $(BUILD)/schedule/mobot3-modes
PB_MODES_SCENARIOS := \
  pico-boards-modes:--min-switches,3,--require-done \
  pico-boards-modes-faults:--min-switches,3,--fault-rate,0.05,--require-done \
  pico-boards-modes-crash:--min-switches,3,--crash,radar@800000 \
  pico-boards-modes-negative-latency:--min-switches,3,--require-done,--switch-scale,0.5,--expect-caught-by,mode \
  pico-boards-modes-negative-age:--min-switches,3,--require-done,--age-scale,0.5,--expect-caught-by,age
define pb_modes_scenario
TESTS += $(call neg_field,$(1),1)
.PHONY: test-$(call neg_field,$(1),1)
test-$(call neg_field,$(1),1): $(PB_BIN) $(foreach b,$(PB_BOARDS),$(PB_DIR)/mobot3-modes/fw/$(b).hex) $(PB_MODES)/tb_plan.txt
	@tools/run_test.sh $(call neg_field,$(1),1) $(PB_BIN) \
	    $(call pb_args,$(PB_MODES),$(PB_DIR)/mobot3-modes/fw,$(PB_DIR)/mobot3-modes/fw/radar.hex,$(PB_DIR)/mobot3-modes/fw/navigation.hex) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --label $(call neg_field,$(1),1) \
	    $(subst $(comma), ,$(call neg_field,$(1),2)) --report $(REPORTS)/$(subst -,_,$(call neg_field,$(1),1)).json
endef
$(foreach s,$(PB_MODES_SCENARIOS),$(eval $(call pb_modes_scenario,$(s))))

# Firmware mutants (sim/mutants/NAME.sed): NAME:BOARD:FILE, where
# FILE (sim/firmware/mobot_<board>.c, sim/firmware/mobot_check.h or
# c-driver/albatross.c) is the file the script edits; the board's program is
# built from copies of the three in $(PB_DIR)/mutant/NAME/, one of them
# mutated (its #include "..." finds the copied header first).
PB_MUTANTS := \
  radar_bad_checksum:radar:sim/firmware/mobot_check.h \
  nav_never_stale:navigation:sim/firmware/mobot_navigation.c \
  nav_stale_early:navigation:sim/firmware/mobot_navigation.c \
  nav_wrong_status:navigation:sim/firmware/mobot_navigation.c
define pb_mutant
$(PB_DIR)/mutant/$(1)/$(2).elf: sim/mutants/$(1).sed sim/firmware/mobot_$(2).c sim/firmware/mobot_check.h \
        c-driver/albatross.c $(PB_SCHED)/rom.hex $(FW_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	cp sim/firmware/mobot_$(2).c sim/firmware/mobot_check.h c-driver/albatross.c $$(@D)/
	sed -f $$< $(3) > $$(@D)/$(notdir $(3))
	@if cmp -s $$(@D)/$(notdir $(3)) $(3); then \
	    echo "firmware mutant $(1) did not apply: $(3) no longer has the line sim/mutants/$(1).sed edits"; \
	    exit 1; fi
	$(DRV_RV_CC) $(FW_CFLAGS) -I$(PB_SCHED) -Isim -o $$@ soc/firmware/crt0.S \
	    $$(@D)/mobot_$(2).c $(PB_SCHED)/$(2).c $$(@D)/albatross.c $(FW_LDFLAGS)
endef
$(foreach m,$(PB_MUTANTS),$(eval $(call pb_mutant,$(call neg_field,$(m),1),$(call neg_field,$(m),2),$(call neg_field,$(m),3))))

# Negative tests: NAME:CHECK:RADAR:NAVIGATION:OPTIONS -- the run passes only
# if CHECK (a comma list: every one of them, no other) fails.  RADAR and
# NAVIGATION name the firmware images (fw = the real one, else a mutant).
PB_NEGATIVE := \
  radar_bad_checksum:cpu:radar_bad_checksum:fw: \
  nav_never_stale:staleness:fw:nav_never_stale:--crash,radar@200000 \
  nav_stale_early:staleness:fw:nav_stale_early: \
  nav_wrong_status:faults:fw:nav_wrong_status:--fault-rate,0.05 \
  age:age:fw:fw:--age-scale,0.5 \
  unpublished:age,liveness,freshness:fw:fw:--mute,MotorCmd@motor \
  hang:liveness:fw:fw:--hang,motor@200000 \
  fault_per_clock:faults:fw:fw:--fault-rate,0.2,--burst,10,--fault-clocking,clock
pb_img = $(if $(filter fw,$(1)),$(PB_FWDIR)/$(2).hex,$(PB_DIR)/mutant/$(1)/$(2).hex)
define pb_negative
TESTS += pico-boards-negative-$(call neg_field,$(1),1)
.PHONY: test-pico-boards-negative-$(call neg_field,$(1),1)
test-pico-boards-negative-$(call neg_field,$(1),1): $(PB_BIN) $(PB_FW) $(PB_SCHED)/tb_plan.txt \
        $(call pb_img,$(call neg_field,$(1),3),radar) $(call pb_img,$(call neg_field,$(1),4),navigation)
	@tools/run_test.sh pico-boards-negative-$(call neg_field,$(1),1) $(PB_BIN) \
	    $(call pb_fw_args,$(call pb_img,$(call neg_field,$(1),3),radar),$(call pb_img,$(call neg_field,$(1),4),navigation)) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --require-done --label pico-boards-negative-$(call neg_field,$(1),1) \
	    --expect-caught-by $(call neg_field,$(1),2) $(subst $(comma), ,$(call neg_field,$(1),5)) \
	    --report $(REPORTS)/pico_boards_negative_$(call neg_field,$(1),1).json
endef
$(foreach n,$(PB_NEGATIVE),$(eval $(call pb_negative,$(n))))

TESTS += pico-boards-lint
.PHONY: test-pico-boards-lint
test-pico-boards-lint:
	$(PICO_NEED)
	@tools/run_test.sh pico-boards-lint bash -c 'verilator --lint-only $(PB_VFLAGS) $(PICO_RV32_V) sim/pico_boards.v && \
	    iverilog -g2005 $(VLIB) -s pico_boards -o /dev/null $(PICO_RV32_V) sim/pico_boards.v && \
	    verilator --lint-only --timing -y sim $(subst pico_boards,pico_boards_tb,$(PB_VFLAGS)) $(PICO_RV32_V) sim/pico_boards_tb.v && \
	    iverilog -g2005 $(VLIB) -y sim -s pico_boards_tb -o /dev/null $(PICO_RV32_V) sim/pico_boards_tb.v && \
	    yosys -q -p "read_verilog $(PICO_RV32_V) $(PB_RTL); hierarchy -check -top pico_boards; proc" && \
	    echo "lint ok  sim/pico_boards.v sim/pico_boards_tb.v"'
