# tools/mk/compiler.mk -- the schedule compiler (the package compiler/albatross_schedule/,
# installed into build/venv by make deps, run as albatross-schedule DESC.toml -o DIR):
# a system description (TOML) -> schedule ROM, board headers and sources, RAM
# images, reports and a timeline picture.  Standard-library Python only.
#   make schedule [SCHEDULE_DESC=file.toml]   -> build/schedule/<file name>/
#   make build/schedule/<example>/rom.hex     any sim/<example>.toml or compiler/examples/<example>.toml
#   make test-compiler                        compiler/tests (examples, bad
#                                             descriptions, gcc, end-to-end)
#   make test-compiler-MODULE                 compiler/tests/test_MODULE.py alone

# A description named on the command line (SCHEDULE_DESC=, SIM_DESC=) is a file
# of the caller: a relative path is taken from the directory make was started in
# (the shell's PWD, also under make -C; a recipe's shell sets it to the recipe's
# directory), not from the checkout.  The absolute path is handed on to sub-makes
# (MAKEOVERRIDES), so that they do not take the relative one from another place.
ALB_CALLER_DIR := $(or $(PWD),$(CURDIR))
caller_path    = $(abspath $(if $(filter /%,$(1)),,$(ALB_CALLER_DIR)/)$(1))
ifneq ($(filter command line environment,$(origin SCHEDULE_DESC)),)
override SCHEDULE_DESC := $(call caller_path,$(SCHEDULE_DESC))
MAKEOVERRIDES  += SCHEDULE_DESC=$(SCHEDULE_DESC)
endif
SCHEDULE_DESC ?= sim/mobot3.toml
# SCHEDULE runs the compiler (the console command of compiler/pyproject.toml, in
# build/venv/bin); rules that run it depend on SCHEDULE_SRC (every module).
SCHEDULE      := albatross-schedule
SCHEDULE_SRC  := $(sort $(wildcard compiler/albatross_schedule/*.py)) rtl/albatross_contract.toml
SCHEDULE_DIR  := $(BUILD)/schedule/$(basename $(notdir $(SCHEDULE_DESC)))

# One test per module of compiler/tests (compiler-schedule, compiler-faults,
# ...), so that make test runs them side by side (test_schedule alone is about
# 40 s of CPU time, all of them about 60 s); make test-compiler runs them all
# in one go.
COMPILER_TESTS := $(patsubst compiler/tests/test_%.py,compiler-%,$(sort $(wildcard compiler/tests/test_*.py)))
TESTS += $(COMPILER_TESTS) schedule-caller-dir
.PHONY: test-compiler schedule test-schedule-caller-dir bench-compile-time $(addprefix test-,$(COMPILER_TESTS))

test-compiler: ## [test] the schedule compiler's tests (examples, bad descriptions, gcc, end to end)
	@tools/run_test.sh compiler $(PYTHON) -m unittest discover -s compiler/tests -v

$(addprefix test-,$(COMPILER_TESTS)): test-compiler-%:
	@tools/run_test.sh compiler-$* $(PYTHON) -m unittest discover -s compiler/tests -p 'test_$*.py' -v


# make schedule always runs the compiler (its time: make bench-compile-time,
# docs/compiler.md "Usage"), so the report it prints is this description's,
# never an older output found in the folder; a missing description stops it
# with the path that was looked for.
schedule: ## compile SCHEDULE_DESC (default: the MOBOT-III example) -> build/schedule/<name>/
	@test -f $(SCHEDULE_DESC) || { echo "schedule: no description $(SCHEDULE_DESC)$(if $(filter /%,$(SCHEDULE_DESC)),, (relative to $(CURDIR)))" >&2; exit 2; }
	@$(SCHEDULE) $(SCHEDULE_DESC) -o $(SCHEDULE_DIR)
	@sed -n "1,/^RAM per board/{/^RAM per board/!p}" $(SCHEDULE_DIR)/report.txt
	@echo "schedule: $(SCHEDULE_DIR)/ (rom.hex, <board>.h/.c, <board>_ram.hex, report.json, timeline.svg;"
	@echo "          report.txt also lists each board's RAM map and the ROM entries)"

# make -C <checkout> schedule from another directory, with a relative and a
# missing description (tools/schedule_caller_test.sh).
test-schedule-caller-dir:
	@tools/run_test.sh schedule-caller-dir tools/schedule_caller_test.sh

# For test 5 of schedule-caller-dir: what a sub-make sees.
.PHONY: schedule-probe schedule-probe-leaf
schedule-probe:
	@$(MAKE) --no-print-directory schedule-probe-leaf
schedule-probe-leaf:
	@echo "probe: SCHEDULE_DESC=$(SCHEDULE_DESC)"

# The example descriptions have the pattern rules below, the FPGA demo's its
# own rule (tools/mk/fpga.mk); any other description gets this one.
example_desc   = $(filter $(CURDIR)/sim/$(notdir $(1)) $(CURDIR)/compiler/examples/$(notdir $(1)) \
                          $(CURDIR)/fpga/$(notdir $(1)),$(abspath $(1)))
ifeq ($(call example_desc,$(SCHEDULE_DESC)),)
$(SCHEDULE_DIR)/rom.hex: $(SCHEDULE_DESC) $(SCHEDULE_SRC)
	$(SCHEDULE) $(SCHEDULE_DESC) -o $(@D)
endif

# Any example description: the robot's (sim/) or the compiler's own (compiler/examples/).
$(BUILD)/schedule/%/rom.hex: sim/%.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $< -o $(@D)
$(BUILD)/schedule/%/rom.hex: compiler/examples/%.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $< -o $(@D)
# The robot with two modes: sim/mobot3_modes.toml's [[mode]] tables appended to
# its description (cruise, the robot as it is, first).
$(BUILD)/schedule/mobot3-modes/rom.hex: sim/mobot3.toml sim/mobot3_modes.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	cat sim/mobot3.toml sim/mobot3_modes.toml > $(@D)/mobot3-modes.toml
	$(SCHEDULE) $(@D)/mobot3-modes.toml -o $(@D) -q
# The robot with its modes and its slow channels (sim/mobot3_slow.toml,
# cruise only): RAM 16 KiB per board (the copy's ram_bytes; sim/pico_boards.v
# ADDR_WIDTH 12), the default of make sim and of the docs' pictures.
$(BUILD)/schedule/mobot3-slow/rom.hex: sim/mobot3.toml sim/mobot3_modes.toml sim/mobot3_slow.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	sed 's/^ram_bytes *= *4096 .*/ram_bytes    = 16384               # sim\/mobot3_slow.toml: 12 KB of RadarScan buffers/' \
	    sim/mobot3.toml > $(@D)/mobot3-slow.toml.tmp
	@grep -q '^ram_bytes    = 16384' $(@D)/mobot3-slow.toml.tmp || \
	    { echo "$@: sim/mobot3.toml no longer has the line ram_bytes = 4096"; exit 1; }
	cat $(@D)/mobot3-slow.toml.tmp sim/mobot3_modes.toml sim/mobot3_slow.toml > $(@D)/mobot3-slow.toml
	rm -f $(@D)/mobot3-slow.toml.tmp
	$(SCHEDULE) $(@D)/mobot3-slow.toml -o $(@D) -q
# ... and planned for 20 % independent faults (the system test at its planned rate).
$(BUILD)/schedule/mobot3-modes-f20/rom.hex: sim/mobot3.toml sim/mobot3_modes.toml $(SCHEDULE_SRC)
	@mkdir -p $(@D)
	cat sim/mobot3.toml sim/mobot3_modes.toml > $(@D)/mobot3-modes.toml
	$(SCHEDULE) $(@D)/mobot3-modes.toml -o $(@D) -q --faults 0.2
# Compiled schedules are kept when make reaches them only through another
# file (tb_plan.txt).  Named by this pattern: a bare .SECONDARY: would cover every
# file, and make would then take a missing description for a deleted
# intermediate file and print an old report as if it were current.
.PRECIOUS: $(BUILD)/schedule/%/rom.hex

# The compiler's predictions for the robot under several fault hypotheses
# (5, 20, 30, 50 % with and without bursts of mean 2):
# build/reports/fault_plan.json, the table of docs/compiler.md "Fault hypothesis".
BENCHES += bench-fault-plan
bench-fault-plan: $(SCHEDULE_SRC) tools/fault_plan_bench.py ## the robot's planned delivery and age bounds at 5/20/30/50 % faults
	$(PYTHON) tools/fault_plan_bench.py sim/mobot3.toml $(REPORTS)/fault_plan.json

# The compiler's time (CPU and wall, median of 3 runs) on the robot, the robot
# with its modes, with its modes at 20 % faults, and two modes that fill the
# ROM (compiler/examples/modes_share.toml): build/reports/compile_time.json,
# the table of docs/compiler.md "Usage".
BENCHES += bench-compile-time
bench-compile-time: $(SCHEDULE_SRC) tools/compile_time_bench.py ## the schedule compiler's CPU and wall time on the robot, its modes and a full ROM
	$(PYTHON) tools/compile_time_bench.py $(REPORTS)/compile_time.json

# The robot planned for other fault hypotheses (--faults replaces its [faults]):
#   build/schedule/mobot3-f<percent>/       rate <percent> %, independent accesses
#   build/schedule/mobot3-f<percent>b<L>/   rate <percent> %, bursts of mean L accesses
#   build/schedule/mobot3-f<percent>p<N>/   independent, target probability 1 - 10^-N
# for the percentages, bursts and N below (tests at true fault rates;
# at 50 % the robot plans only from a target of 0.99 down, make bench-fault-plan).
FAULT_PLAN_PCTS   := 5 20 30 50
FAULT_PLAN_BURSTS := 2 5
FAULT_PLAN_NINES  := 2 3 6
define fault_plan_rule
$(BUILD)/schedule/mobot3-f$(1)/rom.hex: sim/mobot3.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $$< -o $$(@D) -q --faults $(shell awk 'BEGIN { print $(1) / 100 }')
$(foreach b,$(FAULT_PLAN_BURSTS),
$(BUILD)/schedule/mobot3-f$(1)b$(b)/rom.hex: sim/mobot3.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $$< -o $$(@D) -q --faults $(shell awk 'BEGIN { print $(1) / 100 }'),$(b))
$(foreach n,$(FAULT_PLAN_NINES),
$(BUILD)/schedule/mobot3-f$(1)p$(n)/rom.hex: sim/mobot3.toml $(SCHEDULE_SRC)
	$(SCHEDULE) $$< -o $$(@D) -q --faults $(shell awk 'BEGIN { print $(1) / 100 }'),,$(shell awk 'BEGIN { printf "%.12g", 1 - 10 ^ -$(n) }'))
endef
$(foreach p,$(FAULT_PLAN_PCTS),$(eval $(call fault_plan_rule,$(p))))
