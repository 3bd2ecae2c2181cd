# tools/mk/driver.mk -- the C driver (c-driver/): host unit tests against a
# counting, trapping port (tb/unit/), the checker's negative test, the
# warning-free rv32i cross build and host build, and the code-size figure.
# Outputs under $(BUILD)/ only.

DRV_SRC       := c-driver/albatross.c
DRV_HDRS      := $(wildcard c-driver/*.h) c-driver/port/mmio/alb_port_impl.h
DRV_CFLAGS    := -std=c99 -Wall -Wextra -Werror -pedantic
DRV_HOST_CC   ?= gcc
DRV_RV_PREFIX ?= riscv64-unknown-elf-
DRV_RV_CC     := $(DRV_RV_PREFIX)gcc
DRV_RV_FLAGS  := -march=rv32i -mabi=ilp32 -ffreestanding -nostdlib $(DRV_CFLAGS) \
                 -Ic-driver -Ic-driver/port/mmio
DRV_RV_LEVELS := Os O2
DRV_RV_OBJS   := $(foreach O,$(DRV_RV_LEVELS),$(BUILD)/rv32i/albatross-$(O).o)
DRV_HOST_OBJ  := $(BUILD)/host/albatross.o
DRV_UNIT      := $(BUILD)/unit
DRV_UNIT_SRC  := tb/unit/test_driver.c tb/unit/test_transfer.c tb/unit/test_errors.c \
                 tb/unit/test_four_slot.c tb/unit/test_sample.c tb/unit/test_cold_start.c \
                 tb/unit/unit_helpers.c
DRV_UNIT_DEPS := $(DRV_UNIT_SRC) tb/unit/unit_test.h tb/unit/port/alb_port_impl.h \
                 $(DRV_SRC) $(wildcard c-driver/*.h)
DRV_BROKEN    := 1 2
# Any rv32i program built under build/ becomes a $readmemh image of 32-bit
# words (the soft-core boards' program RAM) with the same name, .hex.
$(BUILD)/%.hex: $(BUILD)/%.elf
	$(DRV_RV_PREFIX)objcopy -O verilog --verilog-data-width=4 $< $@

DRV_RV_NEED    = command -v $(DRV_RV_CC) >/dev/null 2>&1 || { echo "driver-rv32i: \
$(DRV_RV_CC) not found: run make deps (installs gcc-riscv64-unknown-elf)"; exit 1; }

TESTS   += driver-unit driver-unit-negative driver-cold-start-negative driver-rv32i
BENCHES += driver-size

.PHONY: test-driver-unit test-driver-unit-negative test-driver-cold-start-negative \
        test-driver-rv32i driver-size

# Host unit tests: the driver with tb/unit/port/alb_port_impl.h (all kinds).
$(DRV_UNIT)/test_driver: $(DRV_UNIT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -Itb/unit/port -Ic-driver -o $@ \
	    $(DRV_UNIT_SRC) $(DRV_SRC)

# The same tests against a deliberately broken port (UNIT_BROKEN_PORT=N).
$(DRV_UNIT)/test_driver_broken%: $(DRV_UNIT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -DUNIT_BROKEN_PORT=$* -Itb/unit/port -Ic-driver \
	    -o $@ $(DRV_UNIT_SRC) $(DRV_SRC)

# The driver with kinds compiled out (albatross.h, "Kinds compiled in"):
# tb/unit/test_kinds.c, once per flag set; together the two sets compile
# each kind's each direction out once (the first is the FPGA sensor's).
DRV_KINDS_1   := -DALB_FOUR_SLOT_EXPORT=0 -DALB_THREE_BUFFER_IMPORT=0
DRV_KINDS_2   := -DALB_THREE_BUFFER_EXPORT=0 -DALB_FOUR_SLOT_IMPORT=0
DRV_KINDS_SRC := tb/unit/test_kinds.c tb/unit/unit_helpers.c
$(DRV_UNIT)/test_kinds_%: $(DRV_UNIT_DEPS) tb/unit/test_kinds.c
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 $(DRV_KINDS_$*) -Itb/unit/port -Ic-driver -o $@ \
	    $(DRV_KINDS_SRC) $(DRV_SRC)

test-driver-unit: $(DRV_UNIT)/test_driver $(DRV_UNIT)/test_kinds_1 $(DRV_UNIT)/test_kinds_2
	@tools/run_test.sh driver-unit bash -c 'set -e; for t in $^; do $$t; done'

test-driver-unit-negative: $(foreach N,$(DRV_BROKEN),$(DRV_UNIT)/test_driver_broken$(N))
	@tools/run_test.sh driver-unit-negative tb/unit/expect_fail.sh $^

# The cold start's negative: the driver as it was before the cold-start
# contract (tb/unit/mutants/cold_zero_corrupt.sed: a control byte of 0 is
# ALB_ERR_CORRUPT) must fail the unit tests (test_cold_start.c above all).
# The sed must change the source, or the test fails on its own.
$(DRV_UNIT)/cold_zero_corrupt/albatross.c: tb/unit/mutants/cold_zero_corrupt.sed $(DRV_SRC)
	@mkdir -p $(@D)
	sed -f $< $(DRV_SRC) > $@
	@test $$(diff $(DRV_SRC) $@ | grep -c '^>') -eq 4 || \
	    { echo "$@: expected 4 lines changed by $<"; rm -f $@; exit 1; }
$(DRV_UNIT)/test_driver_cold_zero_corrupt: $(DRV_UNIT_DEPS) $(DRV_UNIT)/cold_zero_corrupt/albatross.c
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -Itb/unit/port -Ic-driver -o $@ \
	    $(DRV_UNIT_SRC) $(DRV_UNIT)/cold_zero_corrupt/albatross.c

test-driver-cold-start-negative: $(DRV_UNIT)/test_driver_cold_zero_corrupt
	@tools/run_test.sh driver-cold-start-negative tb/unit/expect_fail.sh $^

# Cross build for rv32i (one object per optimisation level) and host build,
# both with the memory-mapped port and warnings as errors.
$(BUILD)/rv32i/albatross-%.o: $(DRV_SRC) $(DRV_HDRS)
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(DRV_RV_FLAGS) -$* -c -o $@ $<

$(DRV_HOST_OBJ): $(DRV_SRC) $(DRV_HDRS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -Ic-driver -Ic-driver/port/mmio -c -o $@ $<

driver-size: $(DRV_RV_OBJS) ## rv32i code size of the driver -> build/reports/driver_size.json
	@mkdir -p $(REPORTS)
	@$(PYTHON) tools/code_size.py --prefix $(DRV_RV_PREFIX) --flags "$(DRV_RV_FLAGS)" \
	    --out $(REPORTS)/driver_size.json \
	    $(foreach O,$(DRV_RV_LEVELS),$(O)=$(BUILD)/rv32i/albatross-$(O).o)

test-driver-rv32i:
	@tools/run_test.sh driver-rv32i bash -c '$(DRV_RV_NEED); \
	    $(MAKE) -s --no-print-directory $(DRV_HOST_OBJ) driver-size'
