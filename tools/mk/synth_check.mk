# tools/mk/synth_check.mk -- Yosys synthesis of the RAM on iCE40, ECP5 and Xilinx 7-series
# (tools/synth_report.py, ADDR_WIDTH=10, 4 KiB): the array must infer block RAM
# on every family.  The negative test proves the check can fail: the broken
# two-write-port RAM (tb/dpram/dpram_no_arbitration.v) must not map on iCE40.
# Logs in build/synth/<module>/, figures in build/reports/synth_<module>.json.
# Without yosys the tool fails with "yosys not found: run `make deps`".

SYNTH_REPORT := $(PYTHON) tools/synth_report.py

TESTS += dpram-bram dpram-bram-negative
.PHONY: test-dpram-bram test-dpram-bram-negative synth-dpram

test-dpram-bram:
	@tools/run_test.sh dpram-bram $(SYNTH_REPORT) albatross_dpram \
	    --file $(subst $(space),$(comma),$(strip $(CORE_dpram))) --require-bram

test-dpram-bram-negative:
	@tools/run_test.sh dpram-bram-negative $(SYNTH_REPORT) dpram_no_arbitration \
	    --file tb/dpram/dpram_no_arbitration.v --require-bram --expect-fail ice40

BENCHES += synth-dpram
synth-dpram: ## [fpga] LUT/FF/BRAM figures of the RAM on iCE40, ECP5, xc7 (Yosys)
	$(SYNTH_REPORT) albatross_dpram --file $(subst $(space),$(comma),$(strip $(CORE_dpram))) \
	    --report $(REPORTS)/synth_albatross_dpram.json
