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
PBN_RTL     := tb/pico/pico_bench.v $(CORE_FS_soc_system_board) $(CORE_dpram)
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
	$(VERILATOR_BUILD) -j 2 -O3 $(PBN_VFLAGS) -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" \
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

# Both channel kinds on both cores: bench.c built with
# -DBENCH_KIND=ALB_FOUR_SLOT for the four-slot kind; pico_bench.v with
# SERV = 1 for SERV (its firmware -DBOARD_NO_COUNTERS: serv_bridge's cycle
# register).  Reports build/reports/bench_{pico,serv}{,_four_slot}.json
# (bench_pico.json is bench-pico's) and channel_ram.json (the bytes of one
# channel instance per kind and payload, from the compiler's layout module).
#   make bench-kinds   all four runs and channel_ram.json
PBN_SERV_BIN := $(PBN_DIR)/serv/Vpico_bench
PBN_SERV_MAX_CYCLES ?= 200000000
$(PBN_SERV_BIN): $(PBN_RTL) tb/pico/bench_pico.cpp tb/pico/picorv32.vlt \
        tb/pico/serv.vlt tb/common/report.h tools/mk/bench_pico.mk
	$(PICO_NEED)
	$(SERV_NEED)
	@mkdir -p $(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(PBN_VFLAGS) -y $(SERV_CPU_RTL) tb/pico/serv.vlt -GSERV=1 \
	    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" --Mdir $(@D) $(PICO_RV32_V) tb/pico/pico_bench.v \
	    $(abspath tb/pico/bench_pico.cpp) > $(@D)/build.log 2>&1 || { cat $(@D)/build.log; exit 1; }

# $(1) = image name, $(2) = extra flags.
define pbn_fw
$(PBN_DIR)/$(1).elf: tb/pico/firmware/bench.c c-driver/albatross.c soc/firmware/crt0.S soc/firmware/link.ld \
        soc/firmware/board.h $(wildcard c-driver/*.h) c-driver/port/mmio/alb_port_impl.h tools/mk/bench_pico.mk
	@$$(DRV_RV_NEED)
	@mkdir -p $$(@D)
	$$(DRV_RV_CC) $$(FW_CFLAGS) $(2) -o $$@ soc/firmware/crt0.S tb/pico/firmware/bench.c c-driver/albatross.c $$(FW_LDFLAGS)
endef
$(eval $(call pbn_fw,bench-four_slot,-DBENCH_KIND=ALB_FOUR_SLOT))
$(eval $(call pbn_fw,bench-serv,-DBOARD_NO_COUNTERS))
$(eval $(call pbn_fw,bench-serv-four_slot,-DBOARD_NO_COUNTERS -DBENCH_KIND=ALB_FOUR_SLOT))

BENCHES += bench-kinds
.PHONY: bench-kinds
PBN_KINDS_DEPS := $(PBN_BIN) $(PBN_SERV_BIN) $(addprefix $(PBN_DIR)/,bench.hex bench-four_slot.hex bench-serv.hex \
        bench-serv-four_slot.hex)
bench-kinds: $(PBN_KINDS_DEPS) ## cycles per Import/Export, both channel kinds, PicoRV32 and SERV; RAM per channel
	$(PBN_BIN) +fw0=$(PBN_DIR)/bench.hex --max-cycles $(PBN_MAX_CYCLES) --report $(REPORTS)/bench_pico.json
	$(PBN_BIN) +fw0=$(PBN_DIR)/bench-four_slot.hex --max-cycles $(PBN_MAX_CYCLES) --label bench-pico-four-slot \
	    --kind four_slot --report $(REPORTS)/bench_pico_four_slot.json
	$(PBN_SERV_BIN) +fw0=$(PBN_DIR)/bench-serv.hex --max-cycles $(PBN_SERV_MAX_CYCLES) --label bench-serv \
	    --cpu "SERV rv32i (tb/pico/pico_bench.v SERV=1), firmware -Os" --report $(REPORTS)/bench_serv.json
	$(PBN_SERV_BIN) +fw0=$(PBN_DIR)/bench-serv-four_slot.hex --max-cycles $(PBN_SERV_MAX_CYCLES) \
	    --label bench-serv-four-slot --kind four_slot --cpu "SERV rv32i (tb/pico/pico_bench.v SERV=1), firmware -Os" \
	    --report $(REPORTS)/bench_serv_four_slot.json
	$(PYTHON) -c 'import json; from albatross_schedule.fourslot import channel_bytes as b; \
	    json.dump({"label": "channel-ram", "note": "bytes of one channel instance (control word and buffers) for a payload of N bytes; a destination adds taken_at (4 bytes) to the payload", \
	    "sizes": [{"bytes": n, "three_buffer": b(n, "three_buffer"), "four_slot": b(n, "four_slot")} for n in (4, 16, 64, 256)]}, \
	    open("$(REPORTS)/channel_ram.json", "w"), indent=2)'
	@echo "bench-kinds: $(REPORTS)/bench_{pico,serv}{,_four_slot}.json, $(REPORTS)/channel_ram.json"
