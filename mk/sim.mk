# mk/sim.mk -- make sim: the main demonstration.  Two simulated CPUs, a
# producer and a consumer, run the real C driver against the RTL dual-ported
# RAM under drifting speed ratios; the run is checked as in make test and
# leaves a wave, a JSON report and a picture in build/sim/.
#   make sim [SIM_IMPORTS=N] [SEED=S] [TRACE=0|1] [TRACE_CYCLES=N]

SIM_DIR      := $(BUILD)/sim
SIM_IMPORTS  ?= 300000
TRACE        ?= 1
TRACE_CYCLES ?= 20000
SIM_TB       := $(if $(filter 1,$(TRACE)),$(TB_DIR)/albatross-trace/tb_dpram,$(TB))

.PHONY: sim
sim: $(SIM_TB) ## main demonstration (SIM_IMPORTS=, SEED=, TRACE=0|1, TRACE_CYCLES=)
	@mkdir -p $(SIM_DIR) $(REPORTS)
	$(SIM_TB) random --imports $(SIM_IMPORTS) --seed $(SEED) --report $(REPORTS)/sim.json \
	    $(if $(filter 1,$(TRACE)),--trace $(SIM_DIR)/waves.vcd --trace-cycles $(TRACE_CYCLES))
	@$(PYTHON) sim/plot_termination.py $(REPORTS)/sim.json $(SIM_DIR)/termination.svg
	@echo "sim: report $(REPORTS)/sim.json$(if $(filter 1,$(TRACE)), wave $(SIM_DIR)/waves.vcd)"
