# tools/mk/endpoint.mk -- the hardware endpoints (rtl/albatross_export_endpoint.v,
# rtl/albatross_import_endpoint.v, engines rtl/albatross_export.v with
# rtl/albatross_export_dest.v, and rtl/albatross_import.v) against a PicoRV32
# running the real C driver, with the protocol checker watching both ports of
# the RAM (tb/endpoint/):
#   make test-endpoint-export            pair_source + export endpoint on port A,
#                                        PicoRV32 consumer (tb/pico/firmware/consumer.c)
#                                        on port B; build/reports/endpoint_export.json
#   make test-endpoint-import            PicoRV32 producer (tb/pico/firmware/producer.c)
#                                        on port A, import endpoint on port B checked
#                                        by the harness; build/reports/endpoint_import.json
#   make test-endpoint-<dir>-negative-<mutant>
#                                        a sed mutant of an engine (below): passes only
#                                        if the named checker fails
#   make test-endpoint-lint              Verilator -Wall, Icarus, Yosys of the test tops
#   make endpoint-report                 build/reports/endpoint.json from both runs
# Every run is bounded by a watchdog in simulated cycles (EP_MAX_CYCLES).
# PicoRV32 and the firmware rules come from tools/mk/pico.mk, which is read
# after this file: prerequisites that name its variables are written $$(...)
# and expanded a second time (.SECONDEXPANSION; no prerequisite in the tree
# holds a literal '$', so the other fragments are unaffected).
.SECONDEXPANSION:

EP_DIR        := $(BUILD)/endpoint
EP_VALUES     ?= 20000
EP_MAX_CYCLES ?= 20000000
EP_VFLAGS     := -Wall --timescale 1ns/1ps $(VLIB) -y tb/endpoint/export -y tb/endpoint/import tb/pico/picorv32.vlt
EP_CXXFLAGS   := -O2 -std=c++17 -U_FORTIFY_SOURCE $(TB_COMMON_INC) -I$(abspath c-driver)
EP_ENGINES    := $(CORE_export_endpoint) $(CORE_OWN_import_endpoint) $(CORE_dpram) $(RTL_INC)
EP_CORE       := $(CORE_FS_soc_system_board)
EP_CHECK      := tb/common/protocol_checker.cpp tb/common/protocol_checker.h tb/endpoint/channel_watch.h tb/endpoint/bench_options.h \
                 tb/common/report.h
TB_RTL        += tb/endpoint/export/pair_source.v

# The consumer firmware of the export test: consumer.c waiting for seq EP_VALUES.
$(EP_DIR)/fw/consumer.elf: tb/pico/firmware/consumer.c c-driver/albatross.c $$(FW_DEPS) tools/mk/endpoint.mk
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -DPAIR_VALUES=$(EP_VALUES)u -o $@ soc/firmware/crt0.S \
	    tb/pico/firmware/consumer.c c-driver/albatross.c $(FW_LDFLAGS)

$(EP_DIR)/export_image.hex: tb/endpoint/export/channel_image.py rtl/albatross_contract.toml
	@mkdir -p $(@D)
	$(PYTHON) tb/endpoint/export/channel_image.py $@

# $(1) = model folder (export, import, or a mutant's name), $(2) = test top,
# $(3) = extra prerequisites (a mutant's copy), $(4) = folder searched before
# rtl/ (a mutant's copy of an engine), $(5) = -G parameters.
define ep_model
$(EP_DIR)/$(1)/V$(2): $(EP_ENGINES) $(3) $(EP_CORE) $$$$(PICO_RV32_V) tb/endpoint/$(2:_pico=)/$(2).v \
        tb/endpoint/$(2:_pico=)/test_$(2).cpp $(EP_CHECK) tools/mk/endpoint.mk
	$$(PICO_NEED)
	@mkdir -p $$(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(if $(4),-y $(4)) $$(EP_VFLAGS) --top-module $(2) $(5) \
	    -CFLAGS "$$(EP_CXXFLAGS)" --Mdir $$(@D)/obj -o ../V$(2) \
	    $$(PICO_RV32_V) tb/endpoint/$(2:_pico=)/$(2).v $$(abspath tb/endpoint/$(2:_pico=)/test_$(2).cpp) \
	    $$(abspath tb/common/protocol_checker.cpp) > $$(@D)/build.log 2>&1 || { cat $$(@D)/build.log; exit 1; }
endef
EP_EXPORT_G := -GVALUES=$(EP_VALUES) -GINIT_FILE='"$(abspath $(EP_DIR)/export_image.hex)"'
$(eval $(call ep_model,export,export_pico,$(EP_DIR)/export_image.hex,,$(EP_EXPORT_G)))
$(eval $(call ep_model,import,import_pico,,,))

TESTS += endpoint-export
.PHONY: test-endpoint-export
test-endpoint-export: $(EP_DIR)/export/Vexport_pico $(EP_DIR)/fw/consumer.hex
	@tools/run_test.sh endpoint-export $(EP_DIR)/export/Vexport_pico +fw1=$(EP_DIR)/fw/consumer.hex \
	    --values $(EP_VALUES) --max-cycles $(EP_MAX_CYCLES) --seed $(SEED) --label endpoint-export \
	    --report $(REPORTS)/endpoint_export.json

TESTS += endpoint-import
.PHONY: test-endpoint-import
test-endpoint-import: $(EP_DIR)/import/Vimport_pico $$(PICO_DIR)/fw/producer.hex
	@tools/run_test.sh endpoint-import $(EP_DIR)/import/Vimport_pico +fw0=$(BUILD)/pico/fw/producer.hex \
	    --max-cycles $(EP_MAX_CYCLES) --seed $(SEED) --label endpoint-import \
	    --report $(REPORTS)/endpoint_import.json

# Negative tests: a sed mutant of an engine (tb/mutants/engines/NAME.sed, its
# header says what it breaks) built into the test top in place of the engine;
# the test passes only if the named checker of the protocol checker fails.
# name : engine file : test top : checker
EP_NEGATIVES := export_writes_locked:albatross_export_dest:export_pico:mutual_exclusion \
                export_early_publish:albatross_export:export_pico:definite_results \
                import_no_readlocked:albatross_import:import_pico:mutual_exclusion
EP_FW_export_pico := +fw1=$(EP_DIR)/fw/consumer.hex --values $(EP_VALUES)
EP_FW_export_pico_DEP := $(EP_DIR)/fw/consumer.hex
EP_FW_import_pico := +fw0=$(BUILD)/pico/fw/producer.hex
EP_FW_import_pico_DEP := $(BUILD)/pico/fw/producer.hex
EP_G_export_pico := $(EP_EXPORT_G)
EP_G_export_pico_DEP := $(EP_DIR)/export_image.hex

# $(1) = mutant name, $(2) = engine, $(3) = test top, $(4) = checker
define ep_negative
$(EP_DIR)/mut-$(1)/src/$(2).v: rtl/$(2).v tb/mutants/engines/$(1).sed
	@mkdir -p $$(@D)
	sed -f tb/mutants/engines/$(1).sed $$< > $$@
	@if cmp -s $$< $$@; then echo "mutant $(1): the sed script changed nothing in rtl/$(2).v"; rm -f $$@; exit 1; fi
$(call ep_model,mut-$(1),$(3),$(EP_DIR)/mut-$(1)/src/$(2).v $(EP_G_$(3)_DEP),$(EP_DIR)/mut-$(1)/src,-Wno-fatal $(EP_G_$(3)))
TESTS += endpoint-negative-$(1)
.PHONY: test-endpoint-negative-$(1)
test-endpoint-negative-$(1): $(EP_DIR)/mut-$(1)/V$(3) $(EP_FW_$(3)_DEP)
	@tools/run_test.sh endpoint-negative-$(1) $(EP_DIR)/mut-$(1)/V$(3) $(EP_FW_$(3)) \
	    --max-cycles $(EP_MAX_CYCLES) --seed $(SEED) --label endpoint-negative-$(1) --expect-checker $(4)
endef
$(foreach n,$(EP_NEGATIVES),$(eval $(call ep_negative,$(call neg_field,$(n),1),$(call neg_field,$(n),2),$(call neg_field,$(n),3),$(call neg_field,$(n),4))))

# The test tops hold picorv32.v (from PyPI), so make lint does not reach them.
TESTS += endpoint-lint
.PHONY: test-endpoint-lint
test-endpoint-lint:
	@tools/run_test.sh endpoint-lint bash -c '$(PICO_NEED:@%=%) && for top in export_pico import_pico; do \
	    d=tb/endpoint/$${top%_pico}; \
	    verilator --lint-only $(EP_VFLAGS) --top-module $$top $(PICO_RV32_V) $$d/$$top.v && \
	    iverilog -g2005 $(VLIB) -y tb/endpoint/export -s $$top -o /dev/null $(PICO_RV32_V) $$d/$$top.v && \
	    yosys -q -p "verilog_defaults -add -Irtl; read_verilog $(PICO_RV32_V) $$d/$$top.v; \
	        hierarchy -check -libdir rtl -libdir soc -libdir tb/endpoint/export -top $$top; proc" && \
	    echo "lint ok  $$d/$$top.v" || exit 1; done'

# Figures of both runs (values, clocks and accesses per transfer) in one file.
BENCHES += endpoint-report
.PHONY: endpoint-report
endpoint-report: test-endpoint-export test-endpoint-import ## [bench] the hardware endpoints' figures (values, clocks, accesses per transfer) -> build/reports/endpoint.json
	@$(PYTHON) -c 'import json,sys; e=json.load(open(sys.argv[1])); i=json.load(open(sys.argv[2])); \
	    json.dump({"export": e, "import": i}, open(sys.argv[3], "w"), indent=2); \
	    print("endpoint: export %d values, %d accesses and %.2f clocks per undisturbed Export (W=%d); " \
	          "import %d Imports (%d New), %d/%d accesses and %.2f/%.2f clocks per undisturbed Old/New Import" % \
	          (e["values"], e["accesses_per_export"], e["clocks_per_export_mean"], e["words"], i["imports"], \
	           i["imports_new"], i["accesses_per_import_old"], i["accesses_per_import_new"], \
	           i["clocks_per_import_old_mean"], i["clocks_per_import_new_mean"]))' \
	    $(REPORTS)/endpoint_export.json $(REPORTS)/endpoint_import.json $(REPORTS)/endpoint.json
