# tools/mk/sim.mk -- make sim: the main demonstration.  The MOBOT-III-inspired
# robot of tools/mk/pico_boards.mk: four PicoRV32 boards (radar, odometry,
# navigation, motor) run the real driver on their own dual-ported RAMs, and
# albatross_controller moves the channels between them by the schedule the
# compiler made from SIM_DESC.  Prints progress and a report; leaves
# build/reports/sim.json, build/sim/ages.csv, build/sim/ages.svg (each
# channel's data age over time against its bound) and, with TRACE=1,
# build/sim/mobot.vcd.
#   make sim [SIM_CYCLES=N] [FAULT_RATE=R] [BURST=L] [CRASH=board@cycle] [STALL=P]
#            [TRACE=0|1] [TRACE_FROM=N] [TRACE_CYCLES=N] [SIM_DESC=file.toml] [SEED=S]
#            [DRIFT=BOARD=PPM/BOARD=PPM...|random:MAX]
# The boards run the firmware with the local clock (fw-clock/, c-driver/alb_clock.c):
# the report's local_time gives each board's estimate error against the
# controller's time; DRIFT makes board clocks drift (mobot_sim --drift-ppm).
# SIM_DESC must describe the boards radar, odometry, navigation and motor and
# the channels of sim/mobot3.toml (the firmware uses them), for
# example sim/mobot3.toml (one schedule), sim/mobot3_possync.toml or the
# robot with its modes (build/schedule/mobot3-modes/mobot3-modes.toml).  The
# default has the modes cruise and dock and the slow channels of
# sim/mobot3_slow.toml (RadarScan, 4 KB every 20 ms; NavLog, 256 bytes every
# 100 ms; cruise only): the report lists every switch with its latency
# against the compiler's and each slow channel's worst age against its
# bound, and ages.svg shows the modes as bands.  Its 11,000,000 clocks
# (220 ms: the log three times) take about 15 s.

SIM_DIR      := $(BUILD)/sim
ifneq ($(filter command line environment,$(origin SIM_DESC)),)
override SIM_DESC := $(call caller_path,$(SIM_DESC))
MAKEOVERRIDES += SIM_DESC=$(SIM_DESC)
endif
# The default: the robot with its two schedule modes and its slow channels
# (sim/mobot3.toml, sim/mobot3_modes.toml and sim/mobot3_slow.toml, joined by
# tools/mk/compiler.mk): navigation asks for dock and back while it runs
# (sim/firmware/mobot_navigation.c), the radar sends its full scan and
# navigation its log in cruise.
SIM_MODES_DESC := $(BUILD)/schedule/mobot3-modes/mobot3-modes.toml
SIM_SLOW_DESC  := $(BUILD)/schedule/mobot3-slow/mobot3-slow.toml
SIM_DESC     ?= $(SIM_SLOW_DESC)
SIM_NAME     := $(basename $(notdir $(SIM_DESC)))
SIM_SCHED    := $(BUILD)/schedule/$(SIM_NAME)
SIM_FWDIR    := $(PB_DIR)/$(SIM_NAME)/fw-clock
DRIFT        ?=
SIM_CYCLES   ?= 11000000
FAULT_RATE   ?= 0
BURST        ?=
CRASH        ?=
STALL        ?= 0
TRACE        ?= 1
TRACE_FROM   ?= 0
TRACE_CYCLES ?= 20000
SIM_BIN      := $(PB_DIR)/$(if $(filter 1,$(TRACE)),obj-trace,obj)/Vpico_boards

# A description outside sim/ and compiler/examples/ (those have a pattern rule).
ifeq ($(call example_desc,$(SIM_DESC)),)
ifneq ($(abspath $(SIM_DESC)),$(abspath $(SCHEDULE_DESC)))
ifneq ($(abspath $(SIM_DESC)),$(abspath $(SIM_MODES_DESC)))
ifneq ($(abspath $(SIM_DESC)),$(abspath $(SIM_SLOW_DESC)))
$(SIM_SCHED)/rom.hex: $(SIM_DESC) $(SCHEDULE_SRC)
	$(SCHEDULE) $(SIM_DESC) -o $(@D)
endif
endif
endif
endif

.PHONY: sim
sim: $(SIM_BIN) $(foreach b,$(PB_BOARDS),$(SIM_FWDIR)/$(b).hex) $(SIM_SCHED)/tb_plan.txt ## main demonstration: the robot (SIM_CYCLES=, FAULT_RATE=, BURST=, CRASH=board@cycle, DRIFT=, TRACE=0|1, SIM_DESC=)
	@test -f $(SIM_DESC) || { echo "sim: no description $(SIM_DESC)"; exit 2; }
	@mkdir -p $(SIM_DIR) $(REPORTS)
	@echo "sim: writes report $(REPORTS)/sim.json, picture $(SIM_DIR)/ages.svg$(if $(filter 1,$(TRACE)), wave $(SIM_DIR)/mobot.vcd); the last line is the verdict"
	$(SIM_BIN) $(call pb_args,$(SIM_SCHED),$(SIM_FWDIR),$(SIM_FWDIR)/radar.hex,$(SIM_FWDIR)/navigation.hex) \
	    --cycles $(SIM_CYCLES) --seed $(SEED) --stall $(STALL) --fault-rate $(FAULT_RATE) $(if $(BURST),--burst $(BURST)) \
	    $(if $(CRASH),--crash $(CRASH)) $(if $(DRIFT),--drift-ppm $(DRIFT)) --label sim --report $(REPORTS)/sim.json --ages $(SIM_DIR)/ages.csv \
	    $(if $(filter 1,$(TRACE)),--trace $(SIM_DIR)/mobot.vcd --trace-from $(TRACE_FROM) --trace-cycles $(TRACE_CYCLES))
	@$(PYTHON) sim/plot_ages.py $(SIM_DIR)/ages.csv $(REPORTS)/sim.json $(SIM_DIR)/ages.svg

# The slow channels (docs/robot.md "Slow channels"): the robot of make sim
# (modes and sim/mobot3_slow.toml, fw-clock/) for 4,500,000 clocks (90 ms:
# scans delivered in the first cruise stay of about 62 ms, a stay in dock, and
# 21 ms of cruise after it, where the values cut by the switch go on and the
# ages are judged by the bound before it plus the time since), every check
# on, the slow channels' ages judged against their bounds from start-up (a
# value never delivered ages from 0) and navigation's quota holding three New
# scans, odometry's one New log (--require-done).  Its negatives (2,500,000
# clocks, no switch):
#   sim-slow-negative-unpublished  RadarScan's destination at navigation never
#                  published (--mute): caught by age (the start value's age
#                  passes the bound at about 39 ms), freshness and liveness
#                  (navigation never meets its quota of scans)
#   sim-slow-negative-torn  the radar puts one word of the next scan in each
#                  scan (sim/mutants/scan_torn.sed): caught by cpu
#                  (navigation's word check, exit code 3 on RadarScan)
SIM_SLOW        := $(BUILD)/schedule/mobot3-slow
SIM_SLOW_FW     := $(PB_DIR)/mobot3-slow/fw-clock
SIM_SLOW_CYCLES ?= 4500000
SIM_SLOW_NEG_CYCLES ?= 2500000
sim_slow_args = $(call pb_args,$(SIM_SLOW),$(SIM_SLOW_FW),$(1),$(SIM_SLOW_FW)/navigation.hex) --seed $(SEED) --require-done
$(PB_DIR)/mutant/scan_torn/radar.elf: sim/mutants/scan_torn.sed sim/firmware/mobot_radar.c sim/firmware/mobot_check.h \
        $(SIM_SLOW)/rom.hex $(FW_DEPS) $(PB_CLOCK_DEPS)
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	sed -f $< sim/firmware/mobot_radar.c > $(@D)/mobot_radar.c
	@if cmp -s $(@D)/mobot_radar.c sim/firmware/mobot_radar.c; then \
	    echo "firmware mutant scan_torn did not apply: sim/firmware/mobot_radar.c no longer has its line"; exit 1; fi
	$(DRV_RV_CC) $(FW_CFLAGS) $(PB_CLOCK_FLAGS) -I$(SIM_SLOW) -Isim -Isim/firmware -o $@ soc/firmware/crt0.S \
	    $(@D)/mobot_radar.c $(SIM_SLOW)/radar.c c-driver/albatross.c c-driver/alb_clock.c $(FW_LDFLAGS)
SIM_SLOW_DEPS = $(PB_BIN) $(foreach b,$(PB_BOARDS),$(SIM_SLOW_FW)/$(b).hex) $(SIM_SLOW)/tb_plan.txt
TESTS += sim-slow sim-slow-negative-unpublished sim-slow-negative-torn
.PHONY: test-sim-slow test-sim-slow-negative-unpublished test-sim-slow-negative-torn
test-sim-slow: $(SIM_SLOW_DEPS)
	@tools/run_test.sh sim-slow $(PB_BIN) $(call sim_slow_args,$(SIM_SLOW_FW)/radar.hex) --cycles $(SIM_SLOW_CYCLES) \
	    --min-switches 2 --label sim-slow --report $(REPORTS)/sim_slow.json
test-sim-slow-negative-unpublished: $(SIM_SLOW_DEPS)
	@tools/run_test.sh sim-slow-negative-unpublished $(PB_BIN) $(call sim_slow_args,$(SIM_SLOW_FW)/radar.hex) \
	    --cycles $(SIM_SLOW_NEG_CYCLES) --mute RadarScan@navigation --label sim-slow-negative-unpublished --expect-caught-by age,freshness,liveness \
	    --report $(REPORTS)/sim_slow_negative_unpublished.json
test-sim-slow-negative-torn: $(SIM_SLOW_DEPS) $(PB_DIR)/mutant/scan_torn/radar.hex
	@tools/run_test.sh sim-slow-negative-torn $(PB_BIN) $(call sim_slow_args,$(PB_DIR)/mutant/scan_torn/radar.hex) \
	    --cycles $(SIM_SLOW_NEG_CYCLES) --label sim-slow-negative-torn --expect-caught-by cpu --report $(REPORTS)/sim_slow_negative_torn.json

# Whole-system simulation speed, Verilator against Icarus Verilog (one run each).
SIM_ICARUS  := $(PB_DIR)/icarus/pico_boards_tb.vvp
$(SIM_ICARUS): $(PB_RTL) $(RTL_INC) sim/pico_boards_tb.v $(PICO_RV32_V)
	$(PICO_NEED)
	@mkdir -p $(@D)
	iverilog -g2005 $(VLIB) -y sim -s pico_boards_tb -o $@ $(PICO_RV32_V) sim/pico_boards_tb.v
BENCHES += bench-sim-speed
.PHONY: bench-sim-speed
bench-sim-speed: $(PB_BIN) $(SIM_ICARUS) $(PB_FW) $(PB_SCHED)/tb_plan.txt ## [bench] whole-system simulation speed, Verilator against Icarus
	$(PYTHON) sim/bench_speed.py --report $(REPORTS)/sim_speed.json \
	    --verilator-cycles 2000000 --verilator "$(PB_BIN) $(PB_FW_ARGS) --cycles 2000000 --progress 0 --label bench" \
	    --icarus-cycles 40000 --icarus "vvp -n $(SIM_ICARUS) $(filter +%,$(PB_FW_ARGS)) +cycles=40000"

# Local time (docs/robot.md "Local time between updates"): the robot with
# every board syncing c-driver/alb_clock.c on GlobalTime and reporting its
# estimates ($(PB_DIR)/mobot3/fw-clock/, tools/mk/pico_boards.mk); the check
# "clock" of sim/mobot_sim.cpp bounds each board's error against the
# controller's time.  Per-board figures: build/reports/sim_clock*.json
# (local_time) and the console.
#   test-sim-clock           no drift
#   test-sim-clock-drift     the boards' clocks +5000, -3000, +1000, -5000 ppm
#   test-sim-clock-negative  the same drift, estimator without rate correction
#                            (-DALB_CLOCK_NO_RATE): must be caught by clock
SIM_CLOCK_FW     := $(PB_DIR)/mobot3/fw-clock
SIM_CLOCK_DRIFT  := radar=5000/odometry=-3000/navigation=1000/motor=-5000
SIM_CLOCK_CYCLES ?= 1500000
sim_clock_args = $(call pb_args,$(PB_SCHED),$(1),$(1)/radar.hex,$(1)/navigation.hex) --cycles $(SIM_CLOCK_CYCLES) \
                 --seed $(SEED) --require-done
SIM_CLOCK_TESTS := \
  sim-clock:fw-clock: \
  sim-clock-drift:fw-clock:--drift-ppm,$(SIM_CLOCK_DRIFT) \
  sim-clock-negative:fw-clock-norate:--drift-ppm,$(SIM_CLOCK_DRIFT),--expect-caught-by,clock
# No --stall here: under stall bursts navigation's own RadarMap staleness
# arithmetic fires on a healthy bus (its age includes navigation's work since
# the map's Import; seen without the clock too, more often with the clock's
# cost in every loop: some hundred cycles per alb_clock_now, about a thousand
# per alb_clock_sync on PicoRV32 without a multiplier).  docs/robot.md.
define sim_clock_test
TESTS += $(call neg_field,$(1),1)
.PHONY: test-$(call neg_field,$(1),1)
test-$(call neg_field,$(1),1): $(PB_BIN) $(foreach b,$(PB_BOARDS),$(PB_DIR)/mobot3/$(call neg_field,$(1),2)/$(b).hex) $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh $(call neg_field,$(1),1) $(PB_BIN) $(call sim_clock_args,$(PB_DIR)/mobot3/$(call neg_field,$(1),2)) \
	    --label $(call neg_field,$(1),1) $(subst $(comma), ,$(call neg_field,$(1),3)) \
	    --report $(REPORTS)/$(subst -,_,$(call neg_field,$(1),1)).json
endef
$(foreach t,$(SIM_CLOCK_TESTS),$(eval $(call sim_clock_test,$(t))))

# Host unit test of c-driver/alb_clock.c (tb/clock/test_clock.c) and its
# negative: the estimator without rate correction must fail it.  clock-unit
# also needs the warning-free builds of alb_clock.c with the memory-mapped
# port: rv32i at -Os and -O2, and the host.
CLOCK_UNIT := $(BUILD)/clock
CLOCK_OBJS := $(CLOCK_UNIT)/alb_clock-rv32i-Os.o $(CLOCK_UNIT)/alb_clock-rv32i-O2.o $(CLOCK_UNIT)/alb_clock-host.o
$(CLOCK_UNIT)/alb_clock-rv32i-%.o: c-driver/alb_clock.c c-driver/alb_clock.h $(DRV_HDRS)
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(DRV_RV_FLAGS) -DALB_LOCAL_TIMER_ADDR=0x20000040u -$* -c -o $@ $<
$(CLOCK_UNIT)/alb_clock-host.o: c-driver/alb_clock.c c-driver/alb_clock.h $(DRV_HDRS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -DALB_LOCAL_TIMER_ADDR=0x20000040u -Ic-driver -Ic-driver/port/mmio -c -o $@ $<
$(CLOCK_UNIT)/test_clock-%: tb/clock/test_clock.c tb/clock/port/alb_port_impl.h c-driver/alb_clock.c c-driver/alb_clock.h tools/mk/sim.mk
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 $(if $(filter norate,$*),-DALB_CLOCK_NO_RATE) -Itb/clock/port -Ic-driver -o $@ \
	    tb/clock/test_clock.c c-driver/alb_clock.c
# alb_clock.c built with the memory-mapped port but without ALB_LOCAL_TIMER_ADDR
# must stop with the #error that names the macro (not an implicit declaration).
TESTS += clock-unit clock-unit-negative clock-no-timer
.PHONY: test-clock-unit test-clock-unit-negative test-clock-no-timer
test-clock-no-timer: c-driver/alb_clock.c c-driver/alb_clock.h $(DRV_HDRS)
	@mkdir -p $(CLOCK_UNIT)
	@tools/run_test.sh clock-no-timer bash -c 'if $(DRV_HOST_CC) $(DRV_CFLAGS) -Ic-driver -Ic-driver/port/mmio -c \
	    -o $(CLOCK_UNIT)/no-timer.o c-driver/alb_clock.c > $(CLOCK_UNIT)/no-timer.log 2>&1; then \
	    echo "expected alb_clock.c without ALB_LOCAL_TIMER_ADDR to fail to compile, it compiled"; exit 1; fi; \
	    if grep -q "#error.*ALB_LOCAL_TIMER_ADDR" $(CLOCK_UNIT)/no-timer.log && \
	       ! grep -q "implicit" $(CLOCK_UNIT)/no-timer.log; then \
	    echo "clock-no-timer: stops with: $$(grep -o "#error.*ALB_LOCAL_TIMER_ADDR[^,]*" $(CLOCK_UNIT)/no-timer.log | head -n 1)"; \
	    else echo "expected an #error naming ALB_LOCAL_TIMER_ADDR and no implicit declaration, got:"; \
	    head -n 5 $(CLOCK_UNIT)/no-timer.log; exit 1; fi'
test-clock-unit: $(CLOCK_UNIT)/test_clock-rate $(CLOCK_OBJS)
	@tools/run_test.sh clock-unit $<
test-clock-unit-negative: $(CLOCK_UNIT)/test_clock-norate
	@tools/run_test.sh clock-unit-negative bash -c '$< > $<.log; rc=$$?; tail -n 1 $<.log; \
	    if [ $$rc -eq 1 ] && tail -n 1 $<.log | grep -q "failed$$" && ! tail -n 1 $<.log | grep -q " 0 failed$$"; then \
	    echo "clock-unit-negative: caught (no rate correction fails the unit test)"; else echo "NOT CAUGHT"; exit 1; fi'

# Import termination (docs/robot.md "Import termination"):
# sim/mobot3.toml and sim/mobot3_possync.toml give every board's core
# ([board.<name>]), so the compiler bounds each three-buffer Import
# (report.txt, ALB_<N>_IMPORT_MAX_*), and every robot run (test-pico-boards*,
# test-serv-boards, test-sim-clock*, make sim) checks the measured passes and
# accesses per Import against it (check "termination", sim/mobot_sim.cpp);
# the runs with --stall judge only the Imports whose loop kept within the
# compiler's T and V.  Added here:
#   test-termination-serv      the SERV motor board without stall bursts: every
#                              Import judged, SERV's loop against T = V = 909
#   test-termination-negative  the same system described with a PicoRV32 motor
#                              board (T = V = 90, while SERV's loop takes up to
#                              ~900 clocks): the compiler leaves MotorCmd and
#                              GlobalTime unspaced (D 269 and 253) and bounds
#                              the motor's Imports at 2 passes; the SERV motor
#                              makes more: caught by termination
#   test-termination-negative-scale  the robot (fw/) with the bounds scaled by
#                              0.5 (--termination-scale): caught by termination
TERM_UNDER      := mobot3_serv_understated
TERM_UNDER_DESC := $(BUILD)/desc/$(TERM_UNDER).toml
TERM_UNDER_SCHED := $(BUILD)/schedule/$(TERM_UNDER)
TERM_UNDER_FW   := $(PB_DIR)/$(TERM_UNDER)/fw
$(TERM_UNDER_DESC): sim/mobot3.toml tools/mk/sim.mk
	@mkdir -p $(@D)
	sed '/^\[board.motor\]/,/^core/s/^core *= *"serv"/core = "picorv32"   # understated: the motor is SERV/' $< > $@
	@grep -q 'understated' $@ || { echo "$@: sim/mobot3.toml no longer has [board.motor] core = \"serv\""; exit 1; }
$(TERM_UNDER_SCHED)/rom.hex: $(TERM_UNDER_DESC) $(SCHEDULE_SRC)
	$(SCHEDULE) $< --out $(@D) -q
$(TERM_UNDER_FW)-serv/motor.elf: sim/firmware/mobot_motor.c sim/firmware/mobot_check.h $(TERM_UNDER_SCHED)/rom.hex $(FW_DEPS)
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -DBOARD_NO_COUNTERS -I$(TERM_UNDER_SCHED) -Isim -o $@ soc/firmware/crt0.S \
	    sim/firmware/mobot_motor.c $(TERM_UNDER_SCHED)/motor.c c-driver/albatross.c $(FW_LDFLAGS)
TERM_SERV_ARGS = $(call pb_args,$(PB_SCHED),$(PB_FWDIR),$(PB_FWDIR)/radar.hex,$(PB_FWDIR)/navigation.hex)
TERM_UNDER_ARGS = $(call pb_args,$(TERM_UNDER_SCHED),$(TERM_UNDER_FW),$(TERM_UNDER_FW)/radar.hex,$(TERM_UNDER_FW)/navigation.hex)
TESTS += termination-serv termination-negative termination-negative-scale
.PHONY: test-termination-serv test-termination-negative test-termination-negative-scale
test-termination-serv: $(SB_BIN) $(PB_FW) $(PB_DIR)/mobot3/fw-serv/motor.hex $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh termination-serv $(SB_BIN) $(subst $(PB_FWDIR)/motor.hex,$(PB_DIR)/mobot3/fw-serv/motor.hex,$(TERM_SERV_ARGS)) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --require-done --label termination-serv --report $(REPORTS)/termination_serv.json
test-termination-negative: $(SB_BIN) $(foreach b,radar odometry navigation,$(TERM_UNDER_FW)/$(b).hex) \
        $(TERM_UNDER_FW)-serv/motor.hex $(TERM_UNDER_SCHED)/tb_plan.txt
	@tools/run_test.sh termination-negative $(SB_BIN) $(subst $(TERM_UNDER_FW)/motor.hex,$(TERM_UNDER_FW)-serv/motor.hex,$(TERM_UNDER_ARGS)) \
	    --cycles $(TERM_NEG_CYCLES) --seed $(SEED) --label termination-negative --expect-caught-by termination \
	    --report $(REPORTS)/termination_negative.json
TERM_NEG_CYCLES ?= 600000
test-termination-negative-scale: $(PB_BIN) $(PB_FW) $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh termination-negative-scale $(PB_BIN) $(PB_FW_ARGS) --cycles $(TERM_NEG_CYCLES) --seed $(SEED) \
	    --termination-scale 0.5 --label termination-negative-scale --expect-caught-by termination \
	    --report $(REPORTS)/termination_negative_scale.json

# test-docs-pictures (tools/mk/docs.mk) runs make sim with its defaults (no
# trace): what that needs is built by the suite as a shared build, once, not
# inside the test's own make while other tests build the same model.
test-docs-pictures: $(PB_BIN) $(foreach b,$(PB_BOARDS),$(PB_DIR)/mobot3/fw-clock/$(b).hex) \
    $(BUILD)/schedule/mobot3/tb_plan.txt $(BUILD)/schedule/mobot3/rom.hex \
    $(foreach b,$(PB_BOARDS),$(SIM_SLOW_FW)/$(b).hex) $(SIM_SLOW)/tb_plan.txt
