# tools/mk/pico.mk -- two PicoRV32 soft cores run the real C driver (firmware/)
# against one albatross_dpram (tb/pico/pico_pair.v, harness tb/pico/).
#   make test-pico-pair           producer and consumer firmware, every import
#                                 checked on the core; build/reports/pico_pair.json
#   make test-pico-pair-four-slot the same on a four-slot channel (both programs
#                                 built with -DPAIR_KIND=ALB_FOUR_SLOT)
#   make test-pico-pair-negative  the producer built from the ignore_readlocked
#                                 driver mutant (tb/mutants/driver/): the real consumer
#                                 must report a torn or out-of-order value
#   make bench-pico-pair          the same run without stalls: cycles per
#                                 alb_export / alb_import, build/reports/pico_pair_bench.json
#   make test-pico-lint           Verilator -Wall (picorv32.v waived, not ours),
#                                 Icarus and Yosys read of pico_pair.v
# The tests stall the consumer core's local RAM in random bursts (SEED=n), so
# that Exports overtake it inside an Import (tb/pico/test_pico_pair.cpp).
# PicoRV32 comes from PyPI (pythondata-cpu-picorv32, make deps); picorv32.v is
# located through the package at build time, never copied here.

PICO_DIR      := $(BUILD)/pico
PICO_RV32_DIR := $(shell $(PYTHON) -c 'import pythondata_cpu_picorv32 as p; print(p.data_location)' 2>/dev/null)
PICO_RV32_V   := $(if $(PICO_RV32_DIR),$(firstword $(shell find $(PICO_RV32_DIR) -name picorv32.v 2>/dev/null)))
PICO_NEED      = @test -n "$(PICO_RV32_V)" || { echo "picorv32.v not found: the PyPI package \
pythondata-cpu-picorv32 is missing; run make deps"; exit 1; }
PICO_MAX_CYCLES ?= 20000000
PICO_RTL      := tb/pico/pico_pair.v $(CORE_FS_soc_system_board) $(CORE_dpram)
PICO_VFLAGS   := -Wall --timescale 1ns/1ps $(VLIB) --top-module pico_pair tb/pico/picorv32.vlt

# Firmware: rv32i, the real driver with the mmio port (TOOLCHAIN.md flags).
FW_CFLAGS     := -march=rv32i -mabi=ilp32 -ffreestanding -nostdlib -nostartfiles -Os -std=c99 \
                 -Wall -Wextra -Werror -pedantic -Ic-driver -Ic-driver/port/mmio -Isoc/firmware
FW_LDFLAGS    := -T soc/firmware/link.ld -Wl,--no-warn-rwx-segments -lgcc
FW_DEPS       := soc/firmware/crt0.S soc/firmware/link.ld soc/firmware/board.h $(DRV_HDRS)

# $(1) = image name, $(2) = program, $(3) = driver source, $(4) = extra flags.
define pico_fw
$(PICO_DIR)/fw/$(1).elf: tb/pico/firmware/$(2).c $(3) $(FW_DEPS)
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) $(4) -o $$@ soc/firmware/crt0.S tb/pico/firmware/$(2).c $(3) $(FW_LDFLAGS)
endef
$(eval $(call pico_fw,producer,producer,c-driver/albatross.c))
$(eval $(call pico_fw,consumer,consumer,c-driver/albatross.c))
# The four-slot kind: the same programs and checks on a four-slot channel.
PAIR_FOUR_SLOT := -DPAIR_KIND=ALB_FOUR_SLOT
$(eval $(call pico_fw,producer-four_slot,producer,c-driver/albatross.c,$(PAIR_FOUR_SLOT)))
$(eval $(call pico_fw,consumer-four_slot,consumer,c-driver/albatross.c,$(PAIR_FOUR_SLOT)))
# The negative test's producer: the writer ignores ReadLocked, so it overwrites
# the buffer the consumer reads.  (while_as_if, the reader's While as If, is
# not caught reliably: it fails only if the producer exports twice inside the
# consumer's few-instruction window between its load of Actual and its store
# of ReadLocked; one Export takes about 600 cycles on PicoRV32.  Never caught
# without stalls, caught with seed 2, 3, 4, 5, 9 of 1..11 with them.)
$(eval $(call pico_fw,producer-ignore_readlocked,producer,$(TB_DIR)/mutants/ignore_readlocked.c))

PICO_BIN := $(PICO_DIR)/obj/Vpico_pair
$(PICO_BIN): $(PICO_RTL) $(PICO_RV32_V) tb/pico/test_pico_pair.cpp tb/pico/picorv32.vlt tb/common/report.h tools/mk/pico.mk
	$(PICO_NEED)
	@mkdir -p $(PICO_DIR)
	$(VERILATOR_BUILD) -j 2 -O3 $(PICO_VFLAGS) -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" \
	    --Mdir $(PICO_DIR)/obj $(PICO_RV32_V) tb/pico/pico_pair.v $(abspath tb/pico/test_pico_pair.cpp) \
	    > $(PICO_DIR)/build.log 2>&1 || { cat $(PICO_DIR)/build.log; exit 1; }

TESTS += pico-pair pico-pair-four-slot pico-pair-negative pico-lint
.PHONY: test-pico-pair test-pico-pair-four-slot test-pico-pair-negative test-pico-lint

test-pico-pair-four-slot: $(PICO_BIN) $(PICO_DIR)/fw/producer-four_slot.hex $(PICO_DIR)/fw/consumer-four_slot.hex
	@tools/run_test.sh pico-pair-four-slot $(PICO_BIN) +fw0=$(PICO_DIR)/fw/producer-four_slot.hex \
	    +fw1=$(PICO_DIR)/fw/consumer-four_slot.hex --max-cycles $(PICO_MAX_CYCLES) --seed $(SEED) \
	    --label pico-pair-four-slot --report $(REPORTS)/pico_pair_four_slot.json

test-pico-pair: $(PICO_BIN) $(PICO_DIR)/fw/producer.hex $(PICO_DIR)/fw/consumer.hex
	@tools/run_test.sh pico-pair $(PICO_BIN) +fw0=$(PICO_DIR)/fw/producer.hex \
	    +fw1=$(PICO_DIR)/fw/consumer.hex --max-cycles $(PICO_MAX_CYCLES) --seed $(SEED) \
	    --label pico-pair --report $(REPORTS)/pico_pair.json

test-pico-pair-negative: $(PICO_BIN) $(PICO_DIR)/fw/producer-ignore_readlocked.hex $(PICO_DIR)/fw/consumer.hex
	@tools/run_test.sh pico-pair-negative $(PICO_BIN) +fw0=$(PICO_DIR)/fw/producer-ignore_readlocked.hex \
	    +fw1=$(PICO_DIR)/fw/consumer.hex --max-cycles $(PICO_MAX_CYCLES) \
	    --seed $(SEED) --label pico-pair-negative --expect-consumer-failure \
	    --report $(REPORTS)/pico_pair_negative.json

BENCHES += bench-pico-pair
.PHONY: bench-pico-pair
bench-pico-pair: $(PICO_BIN) $(PICO_DIR)/fw/producer.hex $(PICO_DIR)/fw/consumer.hex ## [bench] two PicoRV32 boards, one channel: cycles per Import/Export
	$(PICO_BIN) +fw0=$(PICO_DIR)/fw/producer.hex +fw1=$(PICO_DIR)/fw/consumer.hex \
	    --max-cycles $(PICO_MAX_CYCLES) --stall-core -1 --label pico-pair-bench \
	    --report $(REPORTS)/pico_pair_bench.json

# pico_pair.v (and pico_core.v, which it instantiates) is kept out of make lint (root Makefile, TB_RTL): tools/lint.sh
# finds modules in rtl/, soc/ and tb/common/ only, and picorv32.v lives in the package.
test-pico-lint:
	@tools/run_test.sh pico-lint bash -c '$(PICO_NEED:@%=%) && \
	    verilator --lint-only $(PICO_VFLAGS) $(PICO_RV32_V) tb/pico/pico_pair.v && \
	    iverilog -g2005 $(VLIB) -s pico_pair -o /dev/null $(PICO_RV32_V) tb/pico/pico_pair.v && \
	    yosys -q -p "read_verilog $(PICO_RV32_V) $(PICO_RTL); hierarchy -check -top pico_pair; proc" && \
	    echo "lint ok  tb/pico/pico_pair.v (picorv32.v from $(PICO_RV32_V))"'
