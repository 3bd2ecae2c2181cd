# tools/mk/fpga.mk -- the FPGA flow (fpga/, constraints/): the demonstration
# system soc/albatross_system.v (two PicoRV32 boards, their DPRAMs, the bus and
# the controller, running fpga/duo.toml's schedule and fpga/firmware/duo_*.c) in
# a top per board: iCEBreaker (iCE40UP5K; the sensor board on SERV, as two
# PicoRV32 and the controller do not fit), ULX3S (ECP5), Arty A7 (xc7).
#   make synth       Yosys on every family: the DPRAM alone, the controller
#                    alone, one PicoRV32 alone and the board top; iCE40 and
#                    ECP5 Fmax from nextpnr -> build/reports/fpga.json
#   make pnr         place and route the iCEBreaker top (nextpnr-ice40, UP5K
#                    SG48, constraints/icebreaker.pcf, 12 MHz) and the ULX3S
#                    top (nextpnr-ecp5 from PyPI, LFE5U-12F, ulx3s.lpf: its
#                    PLL's 50 MHz CPU and 25 MHz bus clocks), timing per
#                    clock domain and fit -> build/reports/fpga_pnr.json
#   make bitstream   make pnr, then icepack and ecppack ->
#                    build/fpga/icebreaker_top.bin, build/fpga/ulx3s_top.bit
#   make area        the controller by its configuration parameters (full,
#                    each feature off, core), its growth with NB and N_CHAN
#                    and its Fmax, against one PicoRV32 in the same run, and
#                    the core configuration's LUTs by function (a ladder of
#                    rungs, each with one function more taken out:
#                    tools/controller_ladder.py) ->
#                    build/reports/controller_area.json, controller_growth.json,
#                    controller_ladder.json
#   make test-area-ladder   the ladder's edits still apply to rtl/ and every
#                    rung elaborates (no synthesis); -negative: a copy of
#                    rtl/ that the first rung's edit no longer matches fails
#   make test-fpga-soc    the iCEBreaker top simulated (Verilator): both
#                    cores' heartbeats blink, no error LED (-ulx3s, -arty:
#                    those tops; -negative, -ulx3s-negative, -arty-negative:
#                    a corrupted ROM image must light the top's error LED)
#   make test-fpga-icebreaker, test-fpga-ulx3s  (in make test-slow) a board's flow to its
#                    bitstream as a test: fits, meets its clock
#   make test-fpga-icebreaker-pico2  (in make test) the iCEBreaker top
#                    with two PicoRV32 boards (SERV_MASK 0) placed and routed:
#                    fits the UP5K, meets 12 MHz
#   make test-fpga-arty   the Arty top synthesises (Yosys; no open place and
#                    route for 7-series)
#   make test-fpga-lint   Verilator -Wall, Icarus and Yosys on FPGA_LINT (fpga/ and soc/ tops)
# Images: build/fpga/duo/{rom,fw0,fw1,ram0,ram1}.hex, the names the tops'
# parameters give (board 0 = sensor, 1 = actuator).  PicoRV32 from PyPI
# and SERV from PyPI (PICO_RV32_V, tools/mk/pico.mk; SERV_CPU_RTL, tools/mk/serv.mk).

FPGA_DIR    := $(BUILD)/fpga
FPGA_IMG    := $(FPGA_DIR)/duo
FPGA_SCHED  := $(BUILD)/schedule/duo
FPGA_BOARDS := sensor actuator
FPGA_RAM    := 2048   # bytes of each core's program RAM (RAM_WORDS 512 in the tops)
# The demonstration's own Verilog (fpga/: duo_system and the board tops; the
# PLL model fpga/EHXPLLL.v is for simulation only) and what it instantiates.
FPGA_TOPS   := $(wildcard fpga/*_top.v)
FPGA_OWN    := fpga/duo_system.v $(FPGA_TOPS)
# (the duo core's files with its dependencies: tools/corefiles.py).
FPGA_RTL    := $(FPGA_TOPS) $(CORE_board_duo)
# Files fpga-lint checks each as a top: the demonstration and the FPGA-only soc/ parts.
FPGA_LINT   := $(FPGA_OWN) soc/albatross_system.v $(CORE_FS_soc_system_picorv32_ooc)
# PicoRV32 and SERV come from PyPI (tools/mk/pico.mk, tools/mk/serv.mk); Verilator flags.
FPGA_VFLAGS  = -Wall --timescale 1ns/1ps $(VLIB) -y fpga -y $(SERV_CPU_RTL) tb/pico/picorv32.vlt tb/pico/serv.vlt
# (tools/mk/pico.mk, read after this file, defines PICO_RV32_V and FW_*: every use
# below is deferred, in recipes or with = / $$.)
# ecppack from PyPI (YoWASP, like nextpnr-ecp5): it works under the current
# directory only, so its paths are relative.
ECPPACK      := yowasp-ecppack --compress
FPGA_REPORT  = $(PYTHON) tools/fpga_report.py --picorv32 $(PICO_RV32_V) --serv $(SERV_CPU_RTL) --out $(FPGA_DIR)/synth
FPGA_FW_DEPS := soc/firmware/crt0.S soc/firmware/link.ld soc/firmware/board.h c-driver/albatross.c c-driver/albatross.h \
                c-driver/albatross_layout.h c-driver/alb_port.h c-driver/port/mmio/alb_port_impl.h

$(FPGA_SCHED)/rom.hex: fpga/duo.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $< --out $(@D) -q

# Each board's firmware links the driver with only the channel kinds and
# directions the board uses (albatross.h, "Kinds compiled in"): the flags
# come from its generated set-up file, $(2)/<board>.c (tools/board_kinds.py;
# the duo sensor, a three-buffer Export and a four-slot Import:
# -DALB_FOUR_SLOT_EXPORT=0 -DALB_THREE_BUFFER_IMPORT=0).  A call of a kind
# compiled out returns ALB_ERR_ARG.  The sensor's program is also built
# with link-time optimisation and the save/restore millicode: 1,364 B of
# text and 64 B of bss, 620 B left for the stack (without them 1,720 B of
# text, 264 B of stack: barely above link.ld's 256 B).
# Maps: $(3)/<board>.map.
FPGA_FW_CFLAGS_sensor   := -flto -msave-restore
FPGA_FW_DEPS += tools/board_kinds.py

# $(1) = board name, $(2) = schedule directory, $(3) = firmware directory.
define fpga_fw
$(3)/$(1).elf: fpga/firmware/duo_$(1).c $(2)/rom.hex $(FPGA_FW_DEPS) tools/mk/fpga.mk
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	@kinds=$$$$($(PYTHON) tools/board_kinds.py $(2)/$(1).c) && echo "$$@: driver kinds: $$$${kinds:-all}" && \
	$$(DRV_RV_CC) $$(FPGA_FW_CFLAGS_$(1)) $$(FW_CFLAGS) $$$$kinds -ffunction-sections -fdata-sections -I$(2) -o $$@ \
	    soc/firmware/crt0.S fpga/firmware/duo_$(1).c $(2)/$(1).c c-driver/albatross.c \
	    $$(FW_LDFLAGS) -Wl,--gc-sections -Wl,--defsym=__board_ram_bytes=$(strip $(FPGA_RAM)) -Wl,-Map=$(3)/$(1).map
endef
$(eval $(call fpga_fw,sensor,$(FPGA_SCHED),$(FPGA_DIR)/fw))
$(eval $(call fpga_fw,actuator,$(FPGA_SCHED),$(FPGA_DIR)/fw))

# The negative of the four-slot GlobalTime: fpga/duo.toml with a three-buffer
# GlobalTime (the four_slot line deleted) and a wrong, fast Import loop for
# the sensor (T = V = 1 clock instead of the SERV's), so that the compiler
# neither spaces the time slots nor rejects the plan.  Its RAM images equal
# the demo's (the same bases, the same initial control words); its ROM and
# programs are passed as +rom, +fw0, +fw1.
FPGA_3B_SCHED := $(BUILD)/schedule/duo3b
FPGA_3B_FW    := $(FPGA_DIR)/fw3b
$(FPGA_DIR)/duo3b.toml: fpga/duo.toml
	@mkdir -p $(@D)
	sed -e '/^four_slot *= *true/d' -e 's/^core = "serv" .*/import_t_clocks = 1   # WRONG on purpose (negative test)/' $< > $@
	@! grep -q '^four_slot' $@ && grep -q 'WRONG on purpose' $@ || { echo "duo3b.toml: the sed did not apply"; exit 1; }
$(FPGA_3B_SCHED)/rom.hex: $(FPGA_DIR)/duo3b.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $< --out $(@D) -q
	cmp $(@D)/sensor_ram.hex $(FPGA_SCHED)/sensor_ram.hex && cmp $(@D)/actuator_ram.hex $(FPGA_SCHED)/actuator_ram.hex
$(eval $(call fpga_fw,sensor,$(FPGA_3B_SCHED),$(FPGA_3B_FW)))
$(eval $(call fpga_fw,actuator,$(FPGA_3B_SCHED),$(FPGA_3B_FW)))
FPGA_3B_IMG    := $(FPGA_DIR)/duo3b
$(FPGA_3B_IMG)/rom.hex: $(FPGA_3B_SCHED)/rom.hex
	@mkdir -p $(@D)
	cp $< $@
$(FPGA_3B_IMG)/fw0.hex: $(FPGA_3B_FW)/sensor.hex
	@mkdir -p $(@D)
	cp $< $@
$(FPGA_3B_IMG)/fw1.hex: $(FPGA_3B_FW)/actuator.hex
	@mkdir -p $(@D)
	cp $< $@
FPGA_3B_IMAGES := $(addprefix $(FPGA_3B_IMG)/,rom.hex fw0.hex fw1.hex)

# $(1) = board index, $(2) = board name.
define fpga_board
$(FPGA_IMG)/fw$(1).hex: $(FPGA_DIR)/fw/$(2).hex
	@mkdir -p $$(@D)
	cp $$< $$@
$(FPGA_IMG)/ram$(1).hex: $(FPGA_SCHED)/rom.hex
	@mkdir -p $$(@D)
	cp $(FPGA_SCHED)/$(2)_ram.hex $$@
endef
$(eval $(call fpga_board,0,sensor))
$(eval $(call fpga_board,1,actuator))
$(FPGA_IMG)/rom.hex: $(FPGA_SCHED)/rom.hex
	@mkdir -p $(@D)
	cp $< $@
FPGA_IMAGES := $(FPGA_IMG)/rom.hex $(foreach i,0 1,$(FPGA_IMG)/fw$(i).hex $(FPGA_IMG)/ram$(i).hex)

.PHONY: synth pnr bitstream area
synth: $(FPGA_IMAGES) $(BUILD)/schedule/mobot3/rom.hex ## Yosys on iCE40, ECP5, xc7: DPRAM, controller, PicoRV32, board top (+ iCE40, ECP5 Fmax) -> build/reports/fpga.json
	$(PICO_NEED)
	$(FPGA_REPORT) --pnr --report $(REPORTS)/fpga.json

pnr: $(FPGA_IMAGES) ## place and route the iCEBreaker and ULX3S tops, timing against their clocks, fit
	$(PICO_NEED)
	$(FPGA_REPORT) --designs top --families ice40,ecp5 --pnr --report $(REPORTS)/fpga_pnr.json
	@for f in ice40 ecp5; do grep "Max frequency" $(FPGA_DIR)/synth/top_$${f}_pnr.log | tail -n 1; done

# The controller's size and speed by its configuration parameters (full
# function, each optional feature off, the core configuration; growth with
# NB and N_CHAN; Fmax placed out of context), against one PicoRV32 in the
# same run (tools/controller_area.py).  AREA_JOBS syntheses at a time (at
# most 2: each takes a minute or more).
AREA_JOBS ?= 2
area: $(BUILD)/schedule/mobot3/rom.hex ## the controller's LUTs, FFs, BRAMs, Fmax by configuration and growth, against PicoRV32, and the core's cost by function -> build/reports/controller_area.json, controller_growth.json, controller_ladder.json
	$(PICO_NEED)
	$(PYTHON) tools/controller_area.py --picorv32 $(PICO_RV32_V) --out $(FPGA_DIR)/area --jobs $(AREA_JOBS) \
	    --report $(REPORTS)/controller_area.json --growth-report $(REPORTS)/controller_growth.json
	$(PYTHON) tools/controller_ladder.py --out $(FPGA_DIR)/ladder --jobs $(AREA_JOBS) \
	    --report $(REPORTS)/controller_ladder.json --area $(REPORTS)/controller_area.json

bitstream: pnr ## pack the iCEBreaker and ULX3S tops -> build/fpga/icebreaker_top.bin, ulx3s_top.bit
	icepack $(FPGA_DIR)/synth/top_ice40.asc $(FPGA_DIR)/icebreaker_top.bin
	$(ECPPACK) $(FPGA_DIR)/synth/top_ecp5.config $(FPGA_DIR)/ulx3s_top.bit
	@echo "bitstream: $(FPGA_DIR)/icebreaker_top.bin (iceprog it to the iCEBreaker)"
	@echo "bitstream: $(FPGA_DIR)/ulx3s_top.bit (fujprog or openFPGALoader it to the ULX3S)"

# Each board top in Verilator (fpga/test_fpga_soc.cpp): the demonstration
# must run and the top's LEDs show it.  The negative tests run the same
# models on a schedule ROM whose header word H1 is changed (its checksum
# fails; the controller's simulation model reads +rom=FILE instead of
# ROM_FILE): the error LED must light.  $(1) = top, $(2) = harness define,
# $(3) = parameters.  The ULX3S and Arty models divide their heartbeat LEDs
# by 2 (BEAT_LOG2 = 1) instead of 64 and 128: the only difference from the
# synthesised tops, so that a few million clocks show the LEDs blink.  The
# ULX3S model's PLL is fpga/EHXPLLL.v (its two clocks at the real 2:1).
FPGA_SIM_DEPS := $(FPGA_RTL) $(RTL_INC) fpga/EHXPLLL.v fpga/test_fpga_soc.cpp tb/common/report.h tb/pico/picorv32.vlt tools/mk/fpga.mk
# Recipe: the model of top $(1) from file $(4), harness define $(2), parameters $(3), into $(@D).
FPGA_VERILATE = $(VERILATOR_BUILD) -j 2 -O3 $(FPGA_VFLAGS) --top-module $(1) $(3) \
    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC) -D$(2)" --Mdir $(@D) $(PICO_RV32_V) $(4) $(abspath fpga/test_fpga_soc.cpp) \
    > $(@D)/build.log 2>&1 || { cat $(@D)/build.log; exit 1; }
define fpga_sim
$(FPGA_DIR)/sim-$(1)/V$(1): $(FPGA_SIM_DEPS)
	$$(PICO_NEED)
	$$(SERV_NEED)
	@mkdir -p $$(@D)
	$$(call FPGA_VERILATE,$(1),$(2),$(3),fpga/$(1).v)
endef
$(eval $(call fpga_sim,icebreaker_top,TOP_ICEBREAKER))
$(eval $(call fpga_sim,ulx3s_top,TOP_ULX3S,-GBEAT_LOG2=1))
$(eval $(call fpga_sim,arty_top,TOP_ARTY,-GBEAT_LOG2=1))
FPGA_SIM = $(FPGA_DIR)/sim-$(1)/V$(1)

# Broken systems, each built from a sed of one file, for the negative tests
# of the harness's checks.  $(1) = name, $(2) = top, $(3) = define,
# $(4) = sed expression (it must change the file), $(5) = parameters,
# $(6) = the file to break (default: the top, fpga/$(2).v).
fpga_victim = $(or $(1),fpga/$(2).v)
define fpga_mutant
$(FPGA_DIR)/mutant-$(1)/V$(2): $(FPGA_SIM_DEPS)
	$$(PICO_NEED)
	$$(SERV_NEED)
	@mkdir -p $$(@D)
	sed -e '$(4)' $(call fpga_victim,$(6),$(2)) > $$(@D)/$(notdir $(call fpga_victim,$(6),$(2)))
	@! cmp -s $(call fpga_victim,$(6),$(2)) $$(@D)/$(notdir $(call fpga_victim,$(6),$(2))) || \
	    { echo "fpga_mutant $(1): the sed changed nothing in $(call fpga_victim,$(6),$(2))"; exit 1; }
	$$(call FPGA_VERILATE,$(2),$(3),$(5),$(if $(6),fpga/$(2).v) $$(@D)/$(notdir $(call fpga_victim,$(6),$(2))))
endef
$(eval $(call fpga_mutant,green_led,icebreaker_top,TOP_ICEBREAKER,s/assign led_g_n_o = ~beat\[1\];/assign led_g_n_o = ~beat[0];/))
$(eval $(call fpga_mutant,wifi_gpio0,ulx3s_top,TOP_ULX3S,s/assign wifi_gpio0_o = 1'"'"'b1;/assign wifi_gpio0_o = 1'"'"'b0;/,-GBEAT_LOG2=1))
$(eval $(call fpga_mutant,rgb_green,arty_top,TOP_ARTY,s/assign led0_g_o = ~bad & ~rst;/assign led0_g_o = ~bad \& rst;/,-GBEAT_LOG2=1))
# The ULX3S's cores on their own clock but without albatross_wb_cdc: each
# core's bus goes straight to its DPRAM on the other clock.
$(eval $(call fpga_mutant,no_cdc,ulx3s_top,TOP_ULX3S,s/if (CPU_CDC != 0) begin : g_cdc/if (CPU_CDC == 2) begin : g_cdc/,\
    -GBEAT_LOG2=1,soc/albatross_system.v))
$(FPGA_DIR)/badrom/rom.hex: $(FPGA_IMG)/rom.hex
	@mkdir -p $(@D)
	sed '2s/^.*$$/00000001/' $< > $@

BENCHES += synth area

# tools/lut_cones.py (make area's LUTs by register): its self-test on a
# synthesised design and a hand-written one with a shared LUT; the negative
# runs it on a copy that counts a shared LUT whole toward each register.
TESTS += lut-cones lut-cones-negative
.PHONY: test-lut-cones test-lut-cones-negative
test-lut-cones:
	@tools/run_test.sh lut-cones python3 tools/lut_cones.py --self-test

test-lut-cones-negative:
	@mkdir -p $(FPGA_DIR)/lut-cones-neg
	@sed 's|share\[x\] += 1.0 / max(1, len(e))|share[x] += 1.0|' tools/lut_cones.py > $(FPGA_DIR)/lut-cones-neg/lut_cones.py
	@! cmp -s tools/lut_cones.py $(FPGA_DIR)/lut-cones-neg/lut_cones.py || \
	    { echo "lut-cones-negative: the sed did not apply to tools/lut_cones.py"; exit 1; }
	@tools/run_test.sh lut-cones-negative bash -c 'if python3 $(FPGA_DIR)/lut-cones-neg/lut_cones.py --self-test \
	    > $(FPGA_DIR)/lut-cones-neg/log 2>&1; then cat $(FPGA_DIR)/lut-cones-neg/log; \
	    echo "expected the self-test to fail on a copy that counts a shared LUT whole toward each register, it passed"; \
	    exit 1; fi; grep "b_q: expected 0.5 LUTs, came 1.00" $(FPGA_DIR)/lut-cones-neg/log || \
	    { cat $(FPGA_DIR)/lut-cones-neg/log; echo "expected the failure to name b_q s half share"; exit 1; }'

# The function ladder of make area (tools/controller_ladder.py) is a set of
# literal edits of rtl/: every edit must still apply and every rung
# elaborate (no synthesis, seconds); the negative gives it a copy of rtl/
# where the CRC compare the first rung edits is written differently.
LADDER_DIR := $(FPGA_DIR)/ladder-check
TESTS += area-ladder area-ladder-negative
.PHONY: test-area-ladder test-area-ladder-negative
test-area-ladder: $(BUILD)/schedule/mobot3/rom.hex
	@tools/run_test.sh area-ladder python3 tools/controller_ladder.py --check --out $(LADDER_DIR)/ok

test-area-ladder-negative: $(BUILD)/schedule/mobot3/rom.hex
	@rm -rf $(LADDER_DIR)/neg && mkdir -p $(LADDER_DIR)/neg && cp -r rtl $(LADDER_DIR)/neg/
	@sed -i "s/assign crc_ok_o = crc_q == 32'd0;/assign crc_ok_o = 32'd0 == crc_q;/" $(LADDER_DIR)/neg/rtl/albatross_rom_check.v
	@grep -q "assign crc_ok_o = 32'd0 == crc_q;" $(LADDER_DIR)/neg/rtl/albatross_rom_check.v || \
	    { echo "area-ladder-negative: the sed did not apply to rtl/albatross_rom_check.v"; exit 1; }
	@tools/run_test.sh area-ladder-negative bash -c 'if python3 tools/controller_ladder.py --check \
	    --rtl $(LADDER_DIR)/neg/rtl --out $(LADDER_DIR)/neg/out > $(LADDER_DIR)/neg.log 2>&1; then cat $(LADDER_DIR)/neg.log; \
	    echo "expected the ladder check to fail on a copy whose CRC compare its first rung cannot find, it passed"; exit 1; fi; \
	    grep "rung 1 (start-up CRC): expected the text .assign crc_ok_o = crc_q == 32.d0;. once in albatross_rom_check.v, found it 0 times" \
	    $(LADDER_DIR)/neg.log || { cat $(LADDER_DIR)/neg.log; echo "expected the failure to name rung 1 and its text"; exit 1; }'

TESTS += fpga-soc fpga-soc-threebuffer-negative fpga-soc-bound-negative fpga-soc-ulx3s fpga-soc-ulx3s-drift fpga-soc-ulx3s-drift-negative fpga-soc-arty fpga-soc-negative fpga-soc-ulx3s-negative fpga-soc-arty-negative \
         fpga-soc-pins-negative fpga-report-negative fpga-lint
# First in the list: the longest test of make test, so that a run with no
# timing report yet to order it by (a fresh clone) does not end with it alone;
# its images are built before the suite starts (SUITE_PREP_, Makefile).
TESTS := fpga-icebreaker-pico2 $(TESTS)
SUITE_PREP_fpga-icebreaker-pico2 := $(FPGA_IMAGES)
# The iCEBreaker with two PicoRV32 boards is placed and routed in make test
# (about 2.5 min of one core: the fullest top, and the one a controller that
# grows would stop fitting).  The other boards' flows (synthesis, place and
# route, fit and clock; about 3.5 min of CPU time together) run with make
# test-slow: make test checks those tops in simulation, their lint and the
# fit/clock checker itself (fpga-report-negative).
SLOW_TESTS += fpga-icebreaker fpga-ulx3s fpga-arty
.PHONY: test-fpga-soc test-fpga-soc-threebuffer-negative test-fpga-soc-bound-negative test-fpga-soc-ulx3s test-fpga-soc-ulx3s-drift test-fpga-soc-ulx3s-drift-negative test-fpga-soc-arty test-fpga-soc-negative test-fpga-soc-ulx3s-negative \
        test-fpga-soc-arty-negative test-fpga-soc-pins-negative test-fpga-icebreaker test-fpga-icebreaker-pico2 test-fpga-ulx3s \
        test-fpga-report-negative test-fpga-arty test-fpga-lint
# Per top: test-fpga-soc$(1) runs it for $(3) clocks (the iCEBreaker, whose
# sensor is on SERV and slow to start, gets more than the PicoRV32-only
# ULX3S and Arty); test-fpga-soc$(1)-negative runs it on the corrupted ROM.
# $(1) = test suffix, $(2) = top.
# The harness's GlobalTime checks from a generated sensor.h ($(1)): the
# instance's first word, its payload words (with taken_at), the Import bound.
fpga_gt_macro = $$$$(sed -n 's/^\#define ALB_GLOBALTIME_$(2) *\([0-9a-fx]*\)u.*/\1/p' $(1))
FPGA_GT_ARGS = --gt-base $$$$(( $(call fpga_gt_macro,$(1),BASE) / 4 )) \
    --gt-words $$$$(( $(call fpga_gt_macro,$(1),SIZE) / 4 )) --import-bound $(call fpga_gt_macro,$(1),IMPORT_MAX_ACCESSES)
define fpga_soc_tests
test-fpga-soc$(1): $(call FPGA_SIM,$(2)) $$(FPGA_IMAGES)
	@tools/run_test.sh fpga-soc$(1) $(call FPGA_SIM,$(2)) --cycles $(3) $(call FPGA_GT_ARGS,$(FPGA_SCHED)/sensor.h) \
	    --report $$(REPORTS)/fpga_soc$(subst -,_,$(1)).json
test-fpga-soc$(1)-negative: $(call FPGA_SIM,$(2)) $$(FPGA_IMAGES) $(FPGA_DIR)/badrom/rom.hex
	@tools/run_test.sh fpga-soc$(1)-negative $(call FPGA_SIM,$(2)) --cycles 100000 --expect-error \
	    +rom=$(FPGA_DIR)/badrom/rom.hex
endef
$(eval $(call fpga_soc_tests,,icebreaker_top,16000000))
$(eval $(call fpga_soc_tests,-ulx3s,ulx3s_top,4000000))
$(eval $(call fpga_soc_tests,-arty,arty_top,4000000))

# The negative of the four-slot GlobalTime: the iCEBreaker model
# with the ROM and programs of duo3b.toml given as +rom, +fw0 and +fw1
# (GlobalTime three-buffer, not spaced for the SERV sensor).  The controller
# overtakes the sensor's Import loop:
# the Import exceeds its (wrongly computed) bound, or never finishes, and the
# harness must say so.
define fpga_soc_3b_test
test-fpga-soc-threebuffer-negative: $(call FPGA_SIM,icebreaker_top) $$(FPGA_IMAGES) $$(FPGA_3B_IMAGES)
	@tools/run_test.sh fpga-soc-threebuffer-negative $(call FPGA_SIM,icebreaker_top) --cycles 4000000 \
	    +rom=$(FPGA_3B_IMG)/rom.hex +fw0=$(FPGA_3B_IMG)/fw0.hex +fw1=$(FPGA_3B_IMG)/fw1.hex \
	    $(call FPGA_GT_ARGS,$(FPGA_3B_SCHED)/sensor.h) --expect-fail "the sensor's GlobalTime Import"
# The count itself: the demo checked against a bound one access below the
# compiler's must fail on it (a New four-slot Import takes exactly 3 + W).
test-fpga-soc-bound-negative: $(call FPGA_SIM,icebreaker_top) $$(FPGA_IMAGES)
	@tools/run_test.sh fpga-soc-bound-negative $(call FPGA_SIM,icebreaker_top) --cycles 4000000 \
	    $(call FPGA_GT_ARGS,$(FPGA_SCHED)/sensor.h) --import-bound $$$$(( $(call fpga_gt_macro,$(FPGA_SCHED)/sensor.h,IMPORT_MAX_ACCESSES) - 1 )) \
	    --expect-fail "the sensor's GlobalTime Import exceeded its bound"
endef
$(eval $(call fpga_soc_3b_test))

# The ULX3S top with its bus clock wandering against the cores' clock
# (fpga/EHXPLLL.v with +pll_drift: half-periods of 1 to 4 half-periods
# of the cores' clock, edges on either of its edges): the whole system on
# two unrelated clocks, checked as above.
define fpga_soc_drift_test
test-fpga-soc-ulx3s-drift: $(call FPGA_SIM,ulx3s_top) $$(FPGA_IMAGES)
	@tools/run_test.sh fpga-soc-ulx3s-drift $(call FPGA_SIM,ulx3s_top) --cycles 4000000 +pll_drift=4242 \
	    $(call FPGA_GT_ARGS,$(FPGA_SCHED)/sensor.h) --report $$(REPORTS)/fpga_soc_ulx3s_drift.json
endef
$(eval $(call fpga_soc_drift_test))
# Its negative: the cores' buses straight to their DPRAMs, no bridge (the
# no_cdc mutant below).  At the PLL's fixed 2:1 that system happens to run;
# with the clocks unrelated it must fail.  How it fails depends on where the
# missing bridge first tears an access: the sensor's GlobalTime Import may read
# a torn control byte (ALB_ERR_CORRUPT, the sensor stops with 0x4, error LED),
# or the cores' start-up goes wrong and no heartbeat ever changes; either
# message counts.
test-fpga-soc-ulx3s-drift-negative: $(FPGA_DIR)/mutant-no_cdc/Vulx3s_top $(FPGA_IMAGES)
	@tools/run_test.sh fpga-soc-ulx3s-drift-negative $(FPGA_DIR)/mutant-no_cdc/Vulx3s_top --cycles 4000000 \
	    +pll_drift=4242 --expect-fail "expected the error LED off|expected both heartbeats to change"

# The pin checks catch a broken top (a green LED on the wrong heartbeat, the
# ESP32's GPIO0 pulled low, the RGB LED green only in reset).
test-fpga-soc-pins-negative: $(foreach m,green_led/Vicebreaker_top wifi_gpio0/Vulx3s_top rgb_green/Varty_top,\
                               $(FPGA_DIR)/mutant-$(m)) $(FPGA_IMAGES)
	@tools/run_test.sh fpga-soc-pins-negative bash -c 'set -e; \
	    $(FPGA_DIR)/mutant-green_led/Vicebreaker_top --cycles 16000000 --expect-fail "green LED"; \
	    $(FPGA_DIR)/mutant-wifi_gpio0/Vulx3s_top --cycles 4000000 --expect-fail "wifi_gpio0"; \
	    $(FPGA_DIR)/mutant-rgb_green/Varty_top --cycles 4000000 --expect-fail "RGB LED green"'

# A board's whole flow as a test: synthesis, place and route, fit, timing
# against its clock, bitstream.  $(1) = board, $(2) = family, $(3) = pack
# command (input, output), $(4) = bitstream file.
define fpga_board_flow
test-fpga-$(1): $$(FPGA_IMAGES)
	$$(PICO_NEED)
	@tools/run_test.sh fpga-$(1) bash -c '$$(FPGA_REPORT) --designs top --families $(2) --pnr \
	    --report $$(REPORTS)/fpga_pnr_$(1).json && $(3) $$(FPGA_DIR)/$(4) && \
	    echo "bitstream $$(FPGA_DIR)/$(4): $$$$(stat -c %s $$(FPGA_DIR)/$(4)) bytes"'
endef
$(eval $(call fpga_board_flow,icebreaker,ice40,icepack $(FPGA_DIR)/synth/top_ice40.asc,icebreaker_top.bin))
$(eval $(call fpga_board_flow,ulx3s,ecp5,$$(ECPPACK) $(FPGA_DIR)/synth/top_ecp5.config,ulx3s_top.bit))

# The iCEBreaker top with two PicoRV32 boards (SERV_MASK 0) instead of a
# SERV and a PicoRV32, placed and routed at 12 MHz on the UP5K and checked
# for fit and clock like test-fpga-icebreaker.  It fits because
# fpga/duo_system.v builds the controller without the features its schedule
# does not use (STATUS counters, sync poll); the report shows the margin.
test-fpga-icebreaker-pico2: $(FPGA_IMAGES)
	$(PICO_NEED)
	@tools/run_test.sh fpga-icebreaker-pico2 bash -c '$(FPGA_REPORT) --designs top_pico2 --families ice40 --pnr \
	    --report $(REPORTS)/fpga_pnr_icebreaker_pico2.json > $(FPGA_DIR)/pico2.log 2>&1; rc=$$?; \
	    grep -E "top_pico2|LUT|cells|BRAM|RAM|fit|failed" $(FPGA_DIR)/pico2.log | tail -n 8; \
	    if [ $$rc -ne 0 ]; then echo "expected the iCEBreaker top with two PicoRV32 boards to fit the UP5K and meet 12 MHz, came (exit $$rc): $$(tail -n 1 $(FPGA_DIR)/pico2.log)"; exit 1; fi'

# The fit and clock checks of those tests fail a slow or oversized top.
test-fpga-report-negative:
	@tools/run_test.sh fpga-report-negative $(PYTHON) tools/fpga_report.py --self-test

# The Arty (7-series) top synthesises: no open place and route for it in
# Debian or PyPI.
test-fpga-arty: $(FPGA_IMAGES)
	$(PICO_NEED)
	@tools/run_test.sh fpga-arty $(FPGA_REPORT) --designs top --families xc7 --report $(REPORTS)/fpga_arty.json

# Each file of fpga/ as a top: Verilator -Wall, Icarus, Yosys (with the images
# the tops load).  Yosys reads the sources once and elaborates each top from
# that saved design (one run, not one per top).
test-fpga-lint: $(FPGA_IMAGES)
	$(PICO_NEED)
	$(SERV_NEED)
	@tools/run_test.sh fpga-lint bash -c 'set -e; for f in $(FPGA_LINT); do t=$$(basename $$f .v); \
	    verilator --lint-only $(FPGA_VFLAGS) --top-module $$t $(PICO_RV32_V) $$f; \
	    iverilog -g2005 $(VLIB) -y fpga -y $(SERV_CPU_RTL) -s $$t -o /dev/null $(PICO_RV32_V) $$f; \
	    echo "Verilator and Icarus ok  $$f"; done; \
	    yosys -q -p "read_verilog -lib +/ecp5/cells_bb.v; read_verilog -DSYNTHESIS $(PICO_RV32_V) $(SERV_CPU_V) $(FPGA_RTL) $(CORE_FS_soc_system_picorv32_ooc); design -save sources; \
	        $(foreach f,$(FPGA_LINT),design -load sources; hierarchy -check -top $(basename $(notdir $(f))); proc;)"; \
	    echo "Yosys ok  $(foreach f,$(FPGA_LINT),$(f))"'
