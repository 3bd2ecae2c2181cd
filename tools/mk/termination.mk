# tools/mk/termination.mk -- one pass of the three-buffer Import loop on PicoRV32 and on
# SERV, the figures of the schedule compiler's core table (compiler/albatross_schedule/
# termination.py CORE_TIMING, docs/compiler.md "Termination bounds").
#   make bench-import-pass   tb/pico/firmware/import_pass.c as core 1 of the pair
#                            harness (PicoRV32 pair, and SERV_MASK=2), a PicoRV32
#                            producer on core 0: cycles of alb_import New (one pass)
#                            and Old (none); one pass = New max - Old min
#                            -> build/reports/import_pass.json
# Reuses PICO_BIN (tools/mk/pico.mk), SERV_BIN2, SERV_DIR, serv_fw (tools/mk/serv.mk),
# read before this file (tools/mk/*.mk are included in sorted order).

$(eval $(call serv_fw,import_pass-serv,import_pass,c-driver/albatross.c,$(SERV_FW_SERV)))
$(eval $(call serv_fw,import_pass-pico,import_pass,c-driver/albatross.c,))

BENCHES += bench-import-pass
.PHONY: bench-import-pass
IMPORT_PASS_NEED := $(PICO_BIN) $(SERV_BIN2) $(SERV_DIR)/fw/producer-pico.hex \
        $(SERV_DIR)/fw/import_pass-pico.hex $(SERV_DIR)/fw/import_pass-serv.hex
bench-import-pass: $(IMPORT_PASS_NEED) ## one Import loop pass on PicoRV32 and SERV (the compiler's T/V table)
	@mkdir -p $(REPORTS)
	$(PICO_BIN) +fw0=$(SERV_DIR)/fw/producer-pico.hex +fw1=$(SERV_DIR)/fw/import_pass-pico.hex \
	    --max-cycles 20000000 --stall-core -1 --label import-pass-pico --report $(SERV_DIR)/import_pass_pico.json
	$(SERV_BIN2) +fw0=$(SERV_DIR)/fw/producer-pico.hex +fw1=$(SERV_DIR)/fw/import_pass-serv.hex \
	    --max-cycles 20000000 --stall-core -1 --label import-pass-serv --report $(SERV_DIR)/import_pass_serv.json
	@$(PYTHON) -c 'import json, sys; out = {};\
	[out.update({c: (lambda d, s3: {"new_min": s3 >> 16, "new_max": d["imports_new"], "old_min": d["cycles_per_import"],\
	  "old_max": s3 & 0xFFFF, "pass_clocks": d["imports_new"] - d["cycles_per_import"]})(d, int(d["consumer_instructions"]))})\
	 for c, d in (("picorv32", json.load(open(sys.argv[1]))), ("serv", json.load(open(sys.argv[2]))))];\
	out["note"] = "core clocks of alb_import (board_cycles around the call, the empty pair subtracted): New = one pass of the loop, Old = none; pass_clocks = new_max - old_min";\
	json.dump(out, open(sys.argv[3], "w"), indent=1); print(json.dumps(out))' \
	    $(SERV_DIR)/import_pass_pico.json $(SERV_DIR)/import_pass_serv.json $(REPORTS)/import_pass.json
