# mk/pico_boards_negative.mk -- the negative test of the on-core checks of
# make test-pico-boards: the radar firmware is built from a mutated copy of
# firmware/mobot_check.h (tb/mutants/firmware/radar_bad_checksum.sed) and the
# navigation core must report a wrong RadarMap checksum.  Read after
# mk/pico_boards.mk (sorted include order).

PB_MUT := $(PB_DIR)/mutant
$(PB_MUT)/mobot_check.h: firmware/mobot_check.h tb/mutants/firmware/radar_bad_checksum.sed
	@mkdir -p $(@D)
	sed -f tb/mutants/firmware/radar_bad_checksum.sed $< > $@
	@if cmp -s $@ $<; then echo "firmware mutant did not apply: firmware/mobot_check.h changed"; \
	    rm -f $@; exit 1; fi
# The program is copied next to the mutated header, which its #include "..." finds first.
$(PB_MUT)/mobot_radar.c: firmware/mobot_radar.c
	@mkdir -p $(@D)
	cp $< $@
$(PB_MUT)/radar.elf: $(PB_MUT)/mobot_radar.c $(PB_MUT)/mobot_check.h $(PB_SCHED)/rom.hex $(FW_DEPS)
	@$(DRV_RV_NEED)
	$(DRV_RV_CC) $(FW_CFLAGS) -I$(PB_SCHED) -Icompiler/examples -o $@ firmware/crt0.S \
	    $(PB_MUT)/mobot_radar.c $(PB_SCHED)/radar.c c-driver/albatross.c $(FW_LDFLAGS)
$(PB_MUT)/radar.hex: $(PB_MUT)/radar.elf
	$(DRV_RV_PREFIX)objcopy -O verilog --verilog-data-width=4 $< $@

TESTS += pico-boards-negative
.PHONY: test-pico-boards-negative
test-pico-boards-negative: $(PB_BIN) $(PB_MUT)/radar.hex $(foreach b,$(PB_BOARDS),$(PB_DIR)/fw/$(b).hex)
	@tools/run_test.sh pico-boards-negative bash -c '$(PB_BIN) $(subst $(PB_DIR)/fw/radar.hex,$(PB_MUT)/radar.hex,$(PB_FW_ARGS)) \
	    --max-cycles $(PB_MAX_CYCLES) --seed $(SEED) > $(PB_MUT)/run.log 2>&1; rc=$$?; \
	    grep -m 2 -i "checksum" $(PB_MUT)/run.log | sed "s/^/  caught (injected): /"; \
	    if [ $$rc -ne 0 ] && grep -q "checksum wrong, channel RadarMap" $(PB_MUT)/run.log; then \
	        echo "navigation caught the wrong RadarMap checksum, as it must"; \
	    else echo "expected the navigation core to report a wrong RadarMap checksum, came exit $$rc:"; \
	        tail -n 5 $(PB_MUT)/run.log; exit 1; fi'
