# tools/mk/sim.mk -- make sim: the main demonstration.  The MOBOT-III-inspired
# robot of tools/mk/pico_boards.mk: four PicoRV32 boards (radar, odometry,
# navigation, motor) run the real driver on their own dual-ported RAMs, and
# albatross_controller moves the channels between them by the schedule the
# compiler made from SIM_DESC.  Prints progress and a report; leaves
# build/reports/sim.json, build/sim/ages.csv, build/sim/ages.svg (each
# channel's data age over time against its bound) and, with TRACE=1,
# build/sim/mobot.vcd.
#   make sim [SIM_CYCLES=N] [FAULT_RATE=R] [CRASH=board@cycle] [STALL=P]
#            [TRACE=0|1] [TRACE_FROM=N] [TRACE_CYCLES=N] [SIM_DESC=file.toml] [SEED=S]
# SIM_DESC must describe the boards radar, odometry, navigation and motor and
# the channels of sim/mobot3.toml (the firmware uses them), for
# example sim/mobot3_possync.toml.

SIM_DIR      := $(BUILD)/sim
SIM_DESC     ?= sim/mobot3.toml
SIM_NAME     := $(basename $(notdir $(SIM_DESC)))
SIM_SCHED    := $(BUILD)/schedule/$(SIM_NAME)
SIM_FWDIR    := $(PB_DIR)/$(SIM_NAME)/fw
SIM_CYCLES   ?= 2000000
FAULT_RATE   ?= 0
CRASH        ?=
STALL        ?= 0
TRACE        ?= 1
TRACE_FROM   ?= 0
TRACE_CYCLES ?= 20000
SIM_BIN      := $(PB_DIR)/$(if $(filter 1,$(TRACE)),obj-trace,obj)/Vpico_boards

# A description outside sim/ and compiler/examples/ (those have a pattern rule).
ifeq ($(filter sim/% compiler/examples/%,$(SIM_DESC)),)
ifneq ($(SIM_DESC),$(SCHEDULE_DESC))
$(SIM_SCHED)/rom.hex: $(SIM_DESC) $(SCHEDULE_SRC)
	$(SCHEDULE) $(SIM_DESC) --out $(@D)
endif
endif

.PHONY: sim
sim: $(SIM_BIN) $(foreach b,$(PB_BOARDS),$(SIM_FWDIR)/$(b).hex) $(SIM_SCHED)/tb_plan.txt ## main demonstration: the robot (SIM_CYCLES=, FAULT_RATE=, CRASH=board@cycle, TRACE=0|1, SIM_DESC=)
	@test -f $(SIM_DESC) || { echo "sim: no description $(SIM_DESC)"; exit 2; }
	@mkdir -p $(SIM_DIR) $(REPORTS)
	$(SIM_BIN) $(call pb_args,$(SIM_SCHED),$(SIM_FWDIR),$(SIM_FWDIR)/radar.hex,$(SIM_FWDIR)/navigation.hex) \
	    --cycles $(SIM_CYCLES) --seed $(SEED) --stall $(STALL) --fault-rate $(FAULT_RATE) \
	    $(if $(CRASH),--crash $(CRASH)) --label sim --report $(REPORTS)/sim.json --ages $(SIM_DIR)/ages.csv \
	    $(if $(filter 1,$(TRACE)),--trace $(SIM_DIR)/mobot.vcd --trace-from $(TRACE_FROM) --trace-cycles $(TRACE_CYCLES))
	@$(PYTHON) sim/plot_ages.py $(SIM_DIR)/ages.csv $(REPORTS)/sim.json $(SIM_DIR)/ages.svg
	@echo "sim: report $(REPORTS)/sim.json, picture $(SIM_DIR)/ages.svg$(if $(filter 1,$(TRACE)), wave $(SIM_DIR)/mobot.vcd)"

# Whole-system simulation speed, Verilator against Icarus Verilog (one run each).
SIM_ICARUS  := $(PB_DIR)/icarus/pico_boards_tb.vvp
$(SIM_ICARUS): $(PB_RTL) $(RTL_INC) sim/pico_boards_tb.v $(PICO_RV32_V)
	$(PICO_NEED)
	@mkdir -p $(@D)
	iverilog -g2005 $(VLIB) -y sim -s pico_boards_tb -o $@ $(PICO_RV32_V) sim/pico_boards_tb.v
BENCHES += bench-sim-speed
.PHONY: bench-sim-speed
bench-sim-speed: $(PB_BIN) $(SIM_ICARUS) $(PB_FW) $(PB_SCHED)/tb_plan.txt
	$(PYTHON) sim/bench_speed.py --report $(REPORTS)/sim_speed.json \
	    --verilator-cycles 2000000 --verilator "$(PB_BIN) $(PB_FW_ARGS) --cycles 2000000 --progress 0 --label bench" \
	    --icarus-cycles 40000 --icarus "vvp -n $(SIM_ICARUS) $(filter +%,$(PB_FW_ARGS)) +cycles=40000"
