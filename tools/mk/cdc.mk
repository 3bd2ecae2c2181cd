# tools/mk/cdc.mk -- albatross_wb_cdc: albatross_dpram behind two clock-domain-crossing
# bridges, RAM clock fixed, the two CPU clocks drifting (tb/cdc/test_cdc.cpp and the
# cdc_*.cpp / cdc_tb.h pieces it is split into).
#   make test-cdc            the self-checking run, report build/reports/cdc.json
#   make test-cdc-negative   proves each checker fails on an injected fault
# Overrides: SEED=n (both tests), ACCESSES=n (test-cdc; the negative runs keep
# enough accesses to hit their faults).  The seed is printed.

CDC_DIR         := $(BUILD)/cdc
CDC_BIN         := $(CDC_DIR)/obj/Vtb_dpram_async
CDC_SEED        := $(or $(SEED),20240611)
CDC_ACCESSES    := $(or $(ACCESSES),1000000)
CDC_NEG_ACCESSES:= 50000
CDC_SYNC_STAGES := 2
CDC_ADDR_WIDTH  := 8
CDC_CPP         := tb/cdc/test_cdc.cpp tb/cdc/cdc_model.cpp tb/cdc/cdc_cpu.cpp tb/cdc/cdc_ram.cpp
CDC_SRC         := tb/cdc/tb_dpram_async.v $(CORE_wb_cdc) $(CORE_dpram) \
                   $(CDC_CPP) tb/cdc/cdc_tb.h

$(CDC_BIN): $(CDC_SRC) tools/mk/cdc.mk
	@mkdir -p $(CDC_DIR)
	$(VERILATOR_BUILD) -j 2 -O3 -Wall --top-module tb_dpram_async \
	    -GSYNC_STAGES=$(CDC_SYNC_STAGES) -GADDR_WIDTH=$(CDC_ADDR_WIDTH) \
	    -CFLAGS "-O2 -DSYNC_STAGES=$(CDC_SYNC_STAGES) -DADDR_WIDTH=$(CDC_ADDR_WIDTH)" \
	    --Mdir $(CDC_DIR)/obj -y rtl tb/cdc/tb_dpram_async.v $(abspath $(CDC_CPP)) \
	    > $(CDC_DIR)/build.log 2>&1 || { cat $(CDC_DIR)/build.log; exit 1; }

TESTS += cdc cdc-negative

test-cdc: $(CDC_BIN)
	@tools/run_test.sh cdc $(CDC_BIN) --seed=$(CDC_SEED) --accesses=$(CDC_ACCESSES) \
	    --json=$(REPORTS)/cdc.json

test-cdc-negative: $(CDC_BIN)
	@tools/run_test.sh cdc-negative tb/cdc/negative.sh $(CDC_BIN) $(CDC_SEED) $(CDC_NEG_ACCESSES)
