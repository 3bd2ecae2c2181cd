# tools/mk/bench_pico.mk -- cost of the real driver on PicoRV32 against a plain copy.
#   make bench-pico   tb/pico/firmware/bench.c on one PicoRV32 core (tb/pico/pico_bench.v,
#                     harness tb/pico/bench_pico.cpp): cycles per alb_export,
#                     alb_import (New, Old) and a plain volatile word copy for
#                     payloads of 4, 16, 64 and 256 bytes -> build/reports/bench_pico.json;
#                     it runs driver-size (tools/mk/driver.mk) too, for the rv32i
#                     code size of alb_import / alb_export (build/reports/driver_size.json)
# This file is read before tools/mk/driver.mk and tools/mk/pico.mk (tools/mk/*.mk in sorted
# order), so their variables (PICO_RV32_V, PICO_NEED, FW_CFLAGS, FW_LDFLAGS,
# DRV_RV_CC, ...) are used in recipes only, which make expands late; the
# prerequisites name files directly (picorv32.v, an installed package, is left
# out of them).  pico_bench.v needs picorv32.v: it is kept out of make lint
# and linted (Verilator -Wall, Icarus, Yosys) at the end of bench-pico.

PBN_DIR     := $(BUILD)/pico_bench
PBN_RTL     := tb/pico/pico_bench.v soc/pico_core.v soc/board_memmap.v soc/pico_wb_adapter.v \
               rtl/albatross_dpram.v
PBN_VFLAGS  := -Wall --timescale 1ns/1ps $(VLIB) --top-module pico_bench tb/pico/picorv32.vlt
PBN_BIN     := $(PBN_DIR)/obj/Vpico_bench
PBN_MAX_CYCLES ?= 5000000

$(PBN_DIR)/bench.elf: tb/pico/firmware/bench.c c-driver/albatross.c soc/firmware/crt0.S soc/firmware/link.ld soc/firmware/board.h \
        $(wildcard c-driver/*.h) c-driver/port/mmio/alb_port_impl.h
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -o $@ soc/firmware/crt0.S tb/pico/firmware/bench.c c-driver/albatross.c $(FW_LDFLAGS)

$(PBN_DIR)/bench.dis: $(PBN_DIR)/bench.elf
	$(DRV_RV_PREFIX)objdump -d $< > $@

$(PBN_BIN): $(PBN_RTL) tb/pico/bench_pico.cpp tb/pico/picorv32.vlt tb/common/report.h tools/mk/bench_pico.mk
	$(PICO_NEED)
	@mkdir -p $(PBN_DIR)
	verilator --cc --exe --build -j 2 -O3 $(PBN_VFLAGS) -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" \
	    --Mdir $(PBN_DIR)/obj $(PICO_RV32_V) tb/pico/pico_bench.v $(abspath tb/pico/bench_pico.cpp) \
	    > $(PBN_DIR)/build.log 2>&1 || { cat $(PBN_DIR)/build.log; exit 1; }

BENCHES += bench-pico
.PHONY: bench-pico
bench-pico: $(PBN_BIN) $(PBN_DIR)/bench.hex $(PBN_DIR)/bench.dis driver-size ## cycles of alb_export/alb_import vs a plain copy on PicoRV32
	$(PBN_BIN) +fw0=$(PBN_DIR)/bench.hex --max-cycles $(PBN_MAX_CYCLES) --report $(REPORTS)/bench_pico.json
	verilator --lint-only $(PBN_VFLAGS) $(PICO_RV32_V) tb/pico/pico_bench.v
	iverilog -g2005 $(VLIB) -s pico_bench -o /dev/null $(PICO_RV32_V) tb/pico/pico_bench.v
	yosys -q -p "read_verilog $(PICO_RV32_V) $(PBN_RTL); hierarchy -check -top pico_bench; proc"
	@echo "lint ok  tb/pico/pico_bench.v"
