# tools/mk/serv_boards.mk -- the MOBOT-III robot of tools/mk/pico_boards.mk with the motor
# board's PicoRV32 replaced by SERV (sim/pico_boards.v, SERV_MASK = 8, passed
# on to soc/albatross_system.v):
# the navigation board (PicoRV32) exports MotorCmd, a far slower bit-serial
# core imports it, and every check of sim/mobot_sim.cpp applies.
#   make test-serv-boards   fault-free, PicoRV32 cores stalled in random
#                           bursts; build/reports/serv_boards.json
# Reuses PB_* (tools/mk/pico_boards.mk) and SERV_* (tools/mk/serv.mk), read before this
# file (tools/mk/*.mk are included in sorted order).

SB_BIN := $(PB_DIR)/obj-serv-motor/Vpico_boards
$(SB_BIN): $(PB_RTL) $(RTL_INC) $(PICO_RV32_V) $(PB_SRC) $(PB_HDR) \
        tb/pico/picorv32.vlt tb/pico/serv.vlt tools/mk/pico_boards.mk tools/mk/serv_boards.mk
	$(SERV_NEED)
	$(PICO_NEED)
	@mkdir -p $(@D)
	$(VERILATOR_BUILD) -j 2 -O3 $(PB_VFLAGS) -y $(SERV_CPU_RTL) tb/pico/serv.vlt -GSERV_MASK=8 \
	    -CFLAGS "-O2 -std=c++17 $(TB_COMMON_INC)" --Mdir $(@D) $(PICO_RV32_V) sim/pico_boards.v $(abspath $(PB_SRC)) \
	    > $(@D)/build.log 2>&1 || { cat $(@D)/build.log; exit 1; }

# The motor program for SERV: no counter CSRs, the board registers instead.
$(PB_DIR)/mobot3/fw-serv/motor.elf: sim/firmware/mobot_motor.c sim/firmware/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS)
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -DBOARD_NO_COUNTERS -I$(PB_SCHED) -Isim -o $@ soc/firmware/crt0.S \
	    sim/firmware/mobot_motor.c $(PB_SCHED)/motor.c c-driver/albatross.c $(FW_LDFLAGS)

TESTS += serv-boards
.PHONY: test-serv-boards
test-serv-boards: $(SB_BIN) $(PB_FW) $(PB_DIR)/mobot3/fw-serv/motor.hex $(PB_SCHED)/tb_plan.txt
	@tools/run_test.sh serv-boards $(SB_BIN) $(subst $(PB_FWDIR)/motor.hex,$(PB_DIR)/mobot3/fw-serv/motor.hex,$(PB_FW_ARGS)) \
	    --cycles $(PB_CYCLES) --seed $(SEED) --stall 2048 --require-done --label serv-boards --report $(REPORTS)/serv_boards.json
