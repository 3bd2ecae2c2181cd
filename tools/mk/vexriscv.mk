# tools/mk/vexriscv.mk -- a core with a data cache: VexRiscv (the LiteX
# standard variant, 4 KiB I$ + 4 KiB write-through D$, soc/vexriscv_core.v)
# on one side of the pair test (tb/pico/pico_pair.v with VEX_MASK set),
# PicoRV32 on the other, both running the unchanged driver; the protocol
# checker watches both RAM ports (harness tb/pico/test_vex_pair.cpp).
#   make test-vex-pair            PicoRV32 producer, VexRiscv consumer
#                                 (VEX_MASK=2), consumer stalled in bursts;
#                                 build/reports/vex_pair.json
#   make test-vex-pair-producer   VexRiscv producer, PicoRV32 consumer
#                                 (VEX_MASK=1); build/reports/vex_pair_producer.json
#   make test-vex-pair-cached-negative
#                                 the VexRiscv producer built with the DPRAM
#                                 window at its CACHED alias 0x1000_0000
#                                 (the pair models have CACHED_ALIAS=1): its loads of
#                                 ReadLocked hit a stale cache line, so it
#                                 overwrites the buffer the consumer reads.
#                                 Passes only if the mutual-exclusion checker
#                                 and the consumer's own checks (torn values)
#                                 catch it; prints how many
#   make test-vex-pair-cached-consumer-negative
#                                 the VexRiscv consumer reaches the channel
#                                 through the cached alias (start flag still
#                                 uncached):
#                                 its loads of Actual hit a stale line.  The
#                                 consumer reports each Import (-DPAIR_EVENTS);
#                                 passes only if the harness finds stale
#                                 Imports (older than the newest value
#                                 published when they began); prints how many
#                                 and how many values got through.  Ends
#                                 VEX_STOP_AFTER cycles after the producer
#                                 (the consumer never sees the last value)
#   make test-vex-boards, test-vex-boards-alias-negative
#                                 a scenario board on VexRiscv, and the guard
#                                 against the cached alias there (below)
#   make test-vex-lint            Verilator -Wall (VexRiscv.v waived, not
#                                 ours), Icarus and Yosys read of the pair
#                                 top with VexRiscv and of the bench top
#   make bench-vex                cycles per Import/Export on VexRiscv, next to
#                                 PicoRV32's (tb/pico/pico_bench.v VEX=1,
#                                 tb/pico/firmware/bench.c); build/reports/bench_vex.json
# VexRiscv firmware: the DPRAM window and the board registers are uncached
# (address bit 31 set: the variant's I/O rule), -DBOARD_DPRAM_BASE=0x90000000
# -DBOARD_REGS_BASE=0xA0000000 (soc/firmware/board.h), and -DBOARD_NO_COUNTERS
# (no cycle CSR: vexriscv_bridge's CYCLE register).  rv32i like the PicoRV32
# images, so both cores run the same code.
# VexRiscv comes from PyPI (pythondata-cpu-vexriscv, make deps); VexRiscv.v is
# located through the package at build time, never copied here.  Cost: a
# Verilator build of a pair model with VexRiscv takes 10 to 30 s (8 s of CPU),
# each run 2 to 10 s; every test here and in tools/mk/litex.mk from a clean
# build/: 80 s wall, 43 s of CPU (2 cores, shared, load 7).
# Reuses PICO_*, FW_* (tools/mk/pico.mk) and PBN_* (tools/mk/bench_pico.mk).

VEX_DIR      := $(BUILD)/vexriscv
VEX_CPU_DIR  := $(shell $(PYTHON) -c 'import pythondata_cpu_vexriscv as p; print(p.data_location)' 2>/dev/null)
VEX_CPU_V    := $(if $(VEX_CPU_DIR),$(wildcard $(VEX_CPU_DIR)/VexRiscv.v))
VEX_NEED      = @test -n "$(VEX_CPU_V)" || { echo "VexRiscv.v not found: the PyPI package \
pythondata-cpu-vexriscv is missing; run make deps"; exit 1; }
VEX_RTL      := $(PICO_RTL) $(CORE_FS_soc_system_vexriscv)
VEX_VFLAGS   := $(PICO_VFLAGS) tb/pico/vexriscv.vlt
VEX_MAX_CYCLES ?= 20000000
VEX_FW_VEX   := -DBOARD_DPRAM_BASE=0x90000000 -DBOARD_REGS_BASE=0xA0000000 -DBOARD_NO_COUNTERS
# The negative: the window at its cached alias, the registers still uncached.
VEX_FW_CACHED := -DBOARD_DPRAM_BASE=0x10000000 -DBOARD_REGS_BASE=0xA0000000 -DBOARD_NO_COUNTERS
VEX_CXX      := -O2 -std=c++17 -U_FORTIFY_SOURCE $(TB_COMMON_INC) -I$(abspath tb/endpoint) -I$(abspath c-driver)

# $(1) = image name, $(2) = program, $(3) = extra flags.
define vex_fw
$(VEX_DIR)/fw/$(1).elf: tb/pico/firmware/$(2).c c-driver/albatross.c $(FW_DEPS) tools/mk/vexriscv.mk
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(3) -o $$@ soc/firmware/crt0.S tb/pico/firmware/$(2).c c-driver/albatross.c $(FW_LDFLAGS)
endef
$(eval $(call vex_fw,producer-pico,producer,))
$(eval $(call vex_fw,consumer-vex,consumer,$(VEX_FW_VEX) -DPAIR_EVENTS))
# The cached-consumer negative: 300 values are plenty to see them go stale.
$(eval $(call vex_fw,consumer-vex-cached,consumer,$(VEX_FW_VEX) -DBOARD_CHANNEL_BASE=0x10000000 -DPAIR_EVENTS -DPAIR_VALUES=300u))
$(eval $(call vex_fw,producer-pico-short,producer,-DPAIR_VALUES=300u))
$(eval $(call vex_fw,producer-vex,producer,$(VEX_FW_VEX)))
$(eval $(call vex_fw,consumer-pico,consumer,))
$(eval $(call vex_fw,producer-vex-cached,producer,$(VEX_FW_CACHED)))
$(eval $(call vex_fw,consumer-pico-count,consumer,-DPAIR_COUNT_FAULTS))

# pico_pair with $(2) (-G parameters) in $(VEX_DIR)/$(1)/; the class keeps the
# name Vpico_pair.
define vex_model
$(VEX_DIR)/$(1)/Vpico_pair: $(VEX_RTL) tb/pico/test_vex_pair.cpp tb/pico/picorv32.vlt tb/pico/vexriscv.vlt \
        tb/common/protocol_checker.cpp tb/common/protocol_checker.h tb/endpoint/channel_watch.h tb/common/report.h \
        tools/mk/pico.mk tools/mk/vexriscv.mk
	$$(VEX_NEED)
	$$(PICO_NEED)
	@mkdir -p $$(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $$(VEX_VFLAGS) $(2) --prefix Vpico_pair -CFLAGS "$(VEX_CXX)" \
	    --Mdir $$(@D) $$(PICO_RV32_V) $$(VEX_CPU_V) tb/pico/pico_pair.v $$(abspath tb/pico/test_vex_pair.cpp) \
	    $$(abspath tb/common/protocol_checker.cpp) > $(VEX_DIR)/build-$(1).log 2>&1 \
	    || { cat $(VEX_DIR)/build-$(1).log; exit 1; }
endef
# Two models serve the pair tests: both map the cached alias (the negatives
# need it; the positive programs never touch it).  The guard against the
# alias (CACHED_ALIAS = 0: unmapped) is tested on the robot's VexRiscv
# board below (test-vex-boards-alias-negative), whose model is built anyway.
$(eval $(call vex_model,consumer,-GVEX_MASK=2 -GCACHED_ALIAS=1))
$(eval $(call vex_model,producer,-GVEX_MASK=1 -GCACHED_ALIAS=1))
VEX_BIN_C := $(VEX_DIR)/consumer/Vpico_pair
VEX_BIN_P := $(VEX_DIR)/producer/Vpico_pair
VEX_STOP_AFTER ?= 100000

TESTS += vex-pair vex-pair-producer vex-pair-cached-negative vex-pair-cached-consumer-negative vex-lint
.PHONY: test-vex-pair test-vex-pair-producer test-vex-pair-cached-negative test-vex-pair-cached-consumer-negative \
        test-vex-lint

test-vex-pair: $(VEX_BIN_C) $(VEX_DIR)/fw/producer-pico.hex $(VEX_DIR)/fw/consumer-vex.hex
	@tools/run_test.sh vex-pair $(VEX_BIN_C) +fw0=$(VEX_DIR)/fw/producer-pico.hex +fw1=$(VEX_DIR)/fw/consumer-vex.hex \
	    --max-cycles $(VEX_MAX_CYCLES) --seed $(SEED) --label vex-pair --report $(REPORTS)/vex_pair.json

test-vex-pair-producer: $(VEX_BIN_P) $(VEX_DIR)/fw/producer-vex.hex $(VEX_DIR)/fw/consumer-pico.hex
	@tools/run_test.sh vex-pair-producer $(VEX_BIN_P) +fw0=$(VEX_DIR)/fw/producer-vex.hex \
	    +fw1=$(VEX_DIR)/fw/consumer-pico.hex --max-cycles $(VEX_MAX_CYCLES) --seed $(SEED) \
	    --label vex-pair-producer --report $(REPORTS)/vex_pair_producer.json

test-vex-pair-cached-negative: $(VEX_BIN_P) $(VEX_DIR)/fw/producer-vex-cached.hex $(VEX_DIR)/fw/consumer-pico-count.hex
	@tools/run_test.sh vex-pair-cached-negative $(VEX_BIN_P) +fw0=$(VEX_DIR)/fw/producer-vex-cached.hex \
	    +fw1=$(VEX_DIR)/fw/consumer-pico-count.hex --max-cycles $(VEX_MAX_CYCLES) --seed $(SEED) \
	    --label vex-pair-cached-negative --expect-caught-by mutual_exclusion \
	    --report $(REPORTS)/vex_pair_cached_negative.json

test-vex-pair-cached-consumer-negative: $(VEX_BIN_C) $(VEX_DIR)/fw/producer-pico-short.hex $(VEX_DIR)/fw/consumer-vex-cached.hex
	@tools/run_test.sh vex-pair-cached-consumer-negative $(VEX_BIN_C) +fw0=$(VEX_DIR)/fw/producer-pico-short.hex \
	    +fw1=$(VEX_DIR)/fw/consumer-vex-cached.hex --max-cycles $(VEX_MAX_CYCLES) --seed $(SEED) \
	    --stop-after $(VEX_STOP_AFTER) --label vex-pair-cached-consumer-negative --expect-stale \
	    --report $(REPORTS)/vex_pair_cached_consumer_negative.json

# Lint: the pair top with both cores VexRiscv (and the cached alias), the
# bench top with VEX = 1.
test-vex-lint:
	@tools/run_test.sh vex-lint bash -c '$(VEX_NEED:@%=%) && $(PICO_NEED:@%=%) && \
	    verilator --lint-only $(VEX_VFLAGS) -GVEX_MASK=3 -GCACHED_ALIAS=1 $(PICO_RV32_V) $(VEX_CPU_V) tb/pico/pico_pair.v && \
	    iverilog -g2005 $(VLIB) -s pico_pair -P pico_pair.VEX_MASK=3 -o /dev/null $(PICO_RV32_V) $(VEX_CPU_V) tb/pico/pico_pair.v && \
	    yosys -q -p "read_verilog $(PICO_RV32_V) $(VEX_CPU_V) $(VEX_RTL); chparam -set VEX_MASK 3 pico_pair; \
	        hierarchy -check -top pico_pair; proc" && \
	    verilator --lint-only $(subst pico_pair,pico_bench,$(VEX_VFLAGS)) -GVEX=1 $(PICO_RV32_V) $(VEX_CPU_V) tb/pico/pico_bench.v && \
	    echo "lint ok  soc/vexriscv_core.v, tb/pico/pico_pair.v VEX_MASK=3, tb/pico/pico_bench.v VEX=1 (VexRiscv.v from $(VEX_CPU_V))"'

# The bench: tb/pico/pico_bench.v with VEX = 1, bench.c built for the
# VexRiscv map.  bench-vex also reruns PicoRV32's (bench_pico.json) so the two
# tables come from one build of the same source.
VEX_BENCH_BIN := $(VEX_DIR)/bench/Vpico_bench
$(VEX_BENCH_BIN): $(PBN_RTL) $(VEX_RTL) tb/pico/bench_pico.cpp tb/pico/picorv32.vlt tb/pico/vexriscv.vlt \
        tb/common/report.h tools/mk/vexriscv.mk
	$(VEX_NEED)
	$(PICO_NEED)
	@mkdir -p $(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(PBN_VFLAGS) tb/pico/vexriscv.vlt -GVEX=1 --prefix Vpico_bench \
	    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" --Mdir $(@D) $(PICO_RV32_V) $(VEX_CPU_V) tb/pico/pico_bench.v \
	    $(abspath tb/pico/bench_pico.cpp) > $(@D)/build.log 2>&1 || { cat $(@D)/build.log; exit 1; }
$(VEX_DIR)/fw/bench.elf: tb/pico/firmware/bench.c c-driver/albatross.c $(FW_DEPS) tools/mk/vexriscv.mk
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(VEX_FW_VEX) -o $@ soc/firmware/crt0.S tb/pico/firmware/bench.c c-driver/albatross.c $(FW_LDFLAGS)

BENCHES += bench-vex
.PHONY: bench-vex
bench-vex: $(VEX_BENCH_BIN) $(VEX_DIR)/fw/bench.hex $(PBN_BIN) $(PBN_DIR)/bench.hex ## cycles per Import/Export on VexRiscv (D$, window uncached) next to PicoRV32
	$(PBN_BIN) +fw0=$(PBN_DIR)/bench.hex --max-cycles $(PBN_MAX_CYCLES) --report $(REPORTS)/bench_pico.json
	$(VEX_BENCH_BIN) +fw0=$(VEX_DIR)/fw/bench.hex --max-cycles $(PBN_MAX_CYCLES) --label bench-vex \
	    --cpu "VexRiscv (LiteX standard variant: 4 KiB I-cache, 4 KiB D-cache) rv32i code, window uncached, firmware -Os" \
	    --report $(REPORTS)/bench_vex.json

# A board of a scenario: the MOBOT-III robot of tools/mk/pico_boards.mk with
# the motor board's PicoRV32 replaced by VexRiscv (sim/pico_boards.v,
# VEX_MASK = 8, passed on to soc/albatross_system.v), as
# tools/mk/serv_boards.mk does with SERV: the navigation board exports
# MotorCmd, the cached core imports it through its uncached window, and every
# check of sim/mobot_sim.cpp applies.
#   make test-vex-boards   fault-free, cores stalled in random bursts;
#                          build/reports/vex_boards.json
VB_BIN := $(PB_DIR)/obj-vex-motor/Vpico_boards
$(VB_BIN): $(PB_RTL) $(RTL_INC) $(CORE_FS_soc_system_vexriscv) $(PICO_RV32_V) $(PB_SRC) $(PB_HDR) \
        tb/pico/picorv32.vlt tb/pico/vexriscv.vlt tools/mk/pico_boards.mk tools/mk/vexriscv.mk
	$(VEX_NEED)
	$(PICO_NEED)
	@mkdir -p $(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(PB_VFLAGS) tb/pico/vexriscv.vlt -GVEX_MASK=8 \
	    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" --Mdir $(@D) $(PICO_RV32_V) $(VEX_CPU_V) sim/pico_boards.v \
	    $(abspath $(PB_SRC)) > $(@D)/build.log 2>&1 || { cat $(@D)/build.log; exit 1; }

# The motor program for VexRiscv: its map (uncached window and registers).
$(PB_DIR)/mobot3/fw-vex/motor.elf: sim/firmware/mobot_motor.c sim/firmware/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS) \
        tools/mk/vexriscv.mk
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(VEX_FW_VEX) -I$(PB_SCHED) -Isim -o $@ soc/firmware/crt0.S \
	    sim/firmware/mobot_motor.c $(PB_SCHED)/motor.c c-driver/albatross.c $(FW_LDFLAGS)

TESTS += vex-boards
.PHONY: test-vex-boards
test-vex-boards: $(VB_BIN) $(PB_FW) $(PB_DIR)/mobot3/fw-vex/motor.hex $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh vex-boards $(VB_BIN) $(subst $(PB_FWDIR)/motor.hex,$(PB_DIR)/mobot3/fw-vex/motor.hex,$(PB_FW_ARGS)) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --require-done --label vex-boards --report $(REPORTS)/vex_boards.json

# The cached-alias guard on a scenario board: the motor program built with
# its DPRAM window at the cached alias 0x1000_0000 on the normal VexRiscv
# board (CACHED_ALIAS = 0) must stop at its first access there with an
# unmapped access, which the robot simulation's liveness check names
# (--expect-caught-by liveness: that check and no other).
#   make test-vex-boards-alias-negative
$(PB_DIR)/mobot3/fw-vex-cached/motor.elf: sim/firmware/mobot_motor.c sim/firmware/mobot_check.h $(PB_SCHED)/rom.hex \
        $(FW_DEPS) tools/mk/vexriscv.mk
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(VEX_FW_CACHED) -I$(PB_SCHED) -Isim -o $@ soc/firmware/crt0.S \
	    sim/firmware/mobot_motor.c $(PB_SCHED)/motor.c c-driver/albatross.c $(FW_LDFLAGS)

TESTS += vex-boards-alias-negative
.PHONY: test-vex-boards-alias-negative
test-vex-boards-alias-negative: $(VB_BIN) $(PB_FW) $(PB_DIR)/mobot3/fw-vex-cached/motor.hex $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh vex-boards-alias-negative $(VB_BIN) \
	    $(subst $(PB_FWDIR)/motor.hex,$(PB_DIR)/mobot3/fw-vex-cached/motor.hex,$(PB_FW_ARGS)) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --label vex-boards-alias-negative --expect-caught-by liveness \
	    --report $(REPORTS)/vex_boards_alias_negative.json
