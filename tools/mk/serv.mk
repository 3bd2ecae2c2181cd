# tools/mk/serv.mk -- the pair test with a SERV core (bit-serial RISC-V, 32+ clocks
# per instruction) on one side of the channel and PicoRV32 on the other: the
# same tb/pico/pico_pair.v with SERV_MASK set (soc/serv_core.v,
# soc/serv_bridge.v) and the same harness tb/pico/test_pico_pair.cpp.
#   make test-serv-pair           PicoRV32 producer, SERV consumer (SERV_MASK=2):
#                                 every import checked on the core;
#                                 build/reports/serv_pair.json
#   make test-serv-pair-producer  SERV producer, PicoRV32 consumer (SERV_MASK=1);
#                                 build/reports/serv_pair_producer.json
#   make test-serv-pair-four-slot, test-serv-pair-producer-four-slot
#                                 the same two on a four-slot channel
#                                 (-DPAIR_KIND=ALB_FOUR_SLOT)
#   make test-serv-pair-negative  the real SERV consumer against a PicoRV32
#                                 producer built from the ignore_readlocked
#                                 driver mutant: the consumer's checks must
#                                 catch it (seeds 1..5: all caught)
#   make serv-while-as-if         not a test: the SERV consumer built from the
#                                 while_as_if mutant (the reader's While as
#                                 If), seeds 1..8, both cores stalled; prints
#                                 which seeds are caught (see below)
#   make test-serv-lint           Verilator -Wall (SERV's files waived, not
#                                 ours), Icarus and Yosys read of serv_core.v
#                                 and of pico_pair.v with SERV_MASK=3
#   make bench-serv-pair          test-serv-pair without stalls: cycles per
#                                 alb_import on SERV, build/reports/serv_pair_bench.json
# SERV firmware is built with -DBOARD_NO_COUNTERS: SERV has no cycle/instret
# CSRs, serv_bridge provides them as board registers (soc/firmware/board.h).
# Reuses PICO_VFLAGS, PICO_RTL, PICO_NEED, FW_CFLAGS, FW_LDFLAGS, FW_DEPS of
# tools/mk/pico.mk (included before this file: tools/mk/*.mk are read in sorted order).
# SERV comes from PyPI (pythondata-cpu-serv, make deps); its rtl/ folder is
# located through the package at build time, never copied here.  serv_core.v
# needs it: it is kept out of make lint here and linted by test-serv-lint.

SERV_DIR       := $(BUILD)/serv
SERV_CPU_DIR   := $(shell $(PYTHON) -c 'import pythondata_cpu_serv as p; print(p.data_location)' 2>/dev/null)
SERV_CPU_RTL   := $(if $(SERV_CPU_DIR),$(wildcard $(SERV_CPU_DIR)/rtl))
# SERV's own files (serv_synth_wrapper.v is an OpenLane top, not needed).
SERV_CPU_V     := $(if $(SERV_CPU_RTL),$(filter-out %/serv_synth_wrapper.v,$(wildcard $(SERV_CPU_RTL)/serv_*.v)))
SERV_NEED       = @test -n "$(SERV_CPU_V)" || { echo "SERV not found: the PyPI package \
pythondata-cpu-serv is missing; run make deps"; exit 1; }
SERV_RTL       := $(PICO_RTL)
SERV_VFLAGS    := $(PICO_VFLAGS) -y $(SERV_CPU_RTL) tb/pico/serv.vlt
SERV_MAX_CYCLES ?= 20000000
# Values per run: 2000 (as the PicoRV32 pair) where PicoRV32 produces; fewer
# where SERV produces (its Exports, bit-serial, take far longer).
SERV_PAIR_VALUES     ?= 2000
SERV_PRODUCER_VALUES ?= 300

# $(1) = image name, $(2) = program, $(3) = driver source, $(4) = extra flags.
define serv_fw
$(SERV_DIR)/fw/$(1).elf: tb/pico/firmware/$(2).c $(3) $(FW_DEPS) tools/mk/serv.mk
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(4) -o $$@ soc/firmware/crt0.S tb/pico/firmware/$(2).c $(3) $(FW_LDFLAGS)
endef
SERV_FW_SERV := -DBOARD_NO_COUNTERS
$(eval $(call serv_fw,producer-pico,producer,c-driver/albatross.c,-DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,consumer-serv,consumer,c-driver/albatross.c,$(SERV_FW_SERV) -DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,consumer-serv-while_as_if,consumer,$(TB_DIR)/mutants/while_as_if.c,$(SERV_FW_SERV) -DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,producer-pico-ignore_readlocked,producer,$(TB_DIR)/mutants/ignore_readlocked.c,-DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,producer-serv,producer,c-driver/albatross.c,$(SERV_FW_SERV) -DPAIR_VALUES=$(SERV_PRODUCER_VALUES)u))
$(eval $(call serv_fw,consumer-pico,consumer,c-driver/albatross.c,-DPAIR_VALUES=$(SERV_PRODUCER_VALUES)u))
# The four-slot kind: the same programs with -DPAIR_KIND=ALB_FOUR_SLOT (PAIR_FOUR_SLOT, pico.mk).
$(eval $(call serv_fw,producer-pico-four_slot,producer,c-driver/albatross.c,$(PAIR_FOUR_SLOT) -DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,consumer-serv-four_slot,consumer,c-driver/albatross.c,$(PAIR_FOUR_SLOT) $(SERV_FW_SERV) -DPAIR_VALUES=$(SERV_PAIR_VALUES)u))
$(eval $(call serv_fw,producer-serv-four_slot,producer,c-driver/albatross.c,$(PAIR_FOUR_SLOT) $(SERV_FW_SERV) -DPAIR_VALUES=$(SERV_PRODUCER_VALUES)u))
$(eval $(call serv_fw,consumer-pico-four_slot,consumer,c-driver/albatross.c,$(PAIR_FOUR_SLOT) -DPAIR_VALUES=$(SERV_PRODUCER_VALUES)u))

# pico_pair with SERV_MASK=$(1), in its own --Mdir; the class keeps the name
# Vpico_pair, so the harness is the PicoRV32 pair's.
define serv_model
$(SERV_DIR)/mask$(1)/Vpico_pair: $(SERV_RTL) tb/pico/test_pico_pair.cpp tb/pico/picorv32.vlt tb/pico/serv.vlt \
        tb/common/report.h tools/mk/pico.mk tools/mk/serv.mk
	$$(SERV_NEED)
	$$(PICO_NEED)
	@mkdir -p $$(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $$(SERV_VFLAGS) -GSERV_MASK=$(1) --prefix Vpico_pair \
	    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" --Mdir $$(@D) $$(PICO_RV32_V) tb/pico/pico_pair.v \
	    $$(abspath tb/pico/test_pico_pair.cpp) > $(SERV_DIR)/build-mask$(1).log 2>&1 \
	    || { cat $(SERV_DIR)/build-mask$(1).log; exit 1; }
endef
$(eval $(call serv_model,2))
$(eval $(call serv_model,1))
SERV_BIN2 := $(SERV_DIR)/mask2/Vpico_pair
SERV_BIN1 := $(SERV_DIR)/mask1/Vpico_pair

TESTS += serv-pair serv-pair-producer serv-pair-four-slot serv-pair-producer-four-slot serv-pair-negative serv-lint
.PHONY: test-serv-pair test-serv-pair-producer test-serv-pair-four-slot test-serv-pair-producer-four-slot \
        test-serv-pair-negative test-serv-lint

# $(1) = test name, $(2) = model, $(3) = producer image, $(4) = consumer image.
define serv_pair_test
test-$(1): $(2) $(SERV_DIR)/fw/$(3).hex $(SERV_DIR)/fw/$(4).hex
	@tools/run_test.sh $(1) $(2) +fw0=$(SERV_DIR)/fw/$(3).hex +fw1=$(SERV_DIR)/fw/$(4).hex \
	    --max-cycles $$(SERV_MAX_CYCLES) --seed $$(SEED) --label $(1) --report $$(REPORTS)/$(subst -,_,$(1)).json
endef
$(eval $(call serv_pair_test,serv-pair-four-slot,$(SERV_BIN2),producer-pico-four_slot,consumer-serv-four_slot))
$(eval $(call serv_pair_test,serv-pair-producer-four-slot,$(SERV_BIN1),producer-serv-four_slot,consumer-pico-four_slot))

test-serv-pair: $(SERV_BIN2) $(SERV_DIR)/fw/producer-pico.hex $(SERV_DIR)/fw/consumer-serv.hex
	@tools/run_test.sh serv-pair $(SERV_BIN2) +fw0=$(SERV_DIR)/fw/producer-pico.hex \
	    +fw1=$(SERV_DIR)/fw/consumer-serv.hex --max-cycles $(SERV_MAX_CYCLES) --seed $(SEED) \
	    --label serv-pair --report $(REPORTS)/serv_pair.json

test-serv-pair-producer: $(SERV_BIN1) $(SERV_DIR)/fw/producer-serv.hex $(SERV_DIR)/fw/consumer-pico.hex
	@tools/run_test.sh serv-pair-producer $(SERV_BIN1) +fw0=$(SERV_DIR)/fw/producer-serv.hex \
	    +fw1=$(SERV_DIR)/fw/consumer-pico.hex --max-cycles $(SERV_MAX_CYCLES) --seed $(SEED) \
	    --label serv-pair-producer --report $(REPORTS)/serv_pair_producer.json

test-serv-pair-negative: $(SERV_BIN2) $(SERV_DIR)/fw/producer-pico-ignore_readlocked.hex $(SERV_DIR)/fw/consumer-serv.hex
	@tools/run_test.sh serv-pair-negative $(SERV_BIN2) +fw0=$(SERV_DIR)/fw/producer-pico-ignore_readlocked.hex \
	    +fw1=$(SERV_DIR)/fw/consumer-serv.hex --max-cycles $(SERV_MAX_CYCLES) \
	    --seed $(SEED) --label serv-pair-negative --expect-consumer-failure \
	    --report $(REPORTS)/serv_pair_negative.json

# while_as_if on the SERV reader is NOT caught reliably, so it is no test.  The
# mutant fails only if a second Export picks the reader's buffer (its Load of
# ReadLocked inside the reader's window between the Load of Actual and the
# Store of ReadLocked, about 8 SERV instructions, some 300 clocks) AND is
# still writing it when the reader reads it.  On SERV the reader's data loads
# come about 25 instructions (some 1000 clocks) after its Store of ReadLocked,
# while a PicoRV32 Export is done in about 330: the writer has finished and the
# reader gets a whole, newer value, which no check can fault.  Measured: 0 of
# seeds 1..5 caught with the consumer stalled (the pair tests' stalls), 0 of 3
# without stalls or with the producer stalled, 2 of 8 (seeds 2, 6) with both
# cores stalled (--stall-core 2), which lengthens the reader's window and the
# writer's Export at once.
.PHONY: serv-while-as-if
serv-while-as-if: $(SERV_BIN2) $(SERV_DIR)/fw/producer-pico.hex $(SERV_DIR)/fw/consumer-serv-while_as_if.hex ## [sim] the While-as-If mutant on a SERV consumer, seeds 1..8 (an observation)
	@for s in 1 2 3 4 5 6 7 8; do $(SERV_BIN2) +fw0=$(SERV_DIR)/fw/producer-pico.hex \
	    +fw1=$(SERV_DIR)/fw/consumer-serv-while_as_if.hex --max-cycles $(SERV_MAX_CYCLES) --seed $$s \
	    --stall-core 2 --label serv-while-as-if-seed$$s --expect-consumer-failure | tail -n 1; done; true

BENCHES += bench-serv-pair
.PHONY: bench-serv-pair
bench-serv-pair: $(SERV_BIN2) $(SERV_DIR)/fw/producer-pico.hex $(SERV_DIR)/fw/consumer-serv.hex ## [bench] a PicoRV32 producer and a SERV consumer: cycles per Import/Export
	$(SERV_BIN2) +fw0=$(SERV_DIR)/fw/producer-pico.hex +fw1=$(SERV_DIR)/fw/consumer-serv.hex \
	    --max-cycles $(SERV_MAX_CYCLES) --stall-core -1 --label serv-pair-bench \
	    --report $(REPORTS)/serv_pair_bench.json

# serv_core.v as its own top, and pico_pair.v with both cores SERV (SERV_MASK=3).
# Yosys reads SERV with -defer: serv_rf_ram's default width 0 would warn if
# elaborated before hierarchy sets the parameters.
test-serv-lint:
	@tools/run_test.sh serv-lint bash -c '$(SERV_NEED:@%=%) && $(PICO_NEED:@%=%) && \
	    verilator --lint-only -Wall --timescale 1ns/1ps $(VLIB) -y $(SERV_CPU_RTL) \
	        --top-module serv_core tb/pico/serv.vlt soc/serv_core.v && \
	    verilator --lint-only $(SERV_VFLAGS) -GSERV_MASK=3 $(PICO_RV32_V) tb/pico/pico_pair.v && \
	    iverilog -g2005 $(VLIB) -y $(SERV_CPU_RTL) -s serv_core -o /dev/null soc/serv_core.v && \
	    iverilog -g2005 $(VLIB) -y $(SERV_CPU_RTL) -Ppico_pair.SERV_MASK=3 -s pico_pair -o /dev/null \
	        $(PICO_RV32_V) tb/pico/pico_pair.v && \
	    yosys -q -p "read_verilog -defer $(SERV_CPU_V); read_verilog $(SERV_RTL); \
	        hierarchy -check -top serv_core; proc" && \
	    yosys -q -p "read_verilog -defer $(SERV_CPU_V); read_verilog $(PICO_RV32_V) $(SERV_RTL); \
	        hierarchy -check -top pico_pair -chparam SERV_MASK 3; proc" && \
	    echo "lint ok  soc/serv_core.v, tb/pico/pico_pair.v SERV_MASK=3 (SERV from $(SERV_CPU_RTL))"'
