# tools/mk/corefiles.mk -- the FuseSoC cores are the one list of the RTL
# files (tools/corefiles.py; the Makefile's CORE_* lists, $(BUILD)/corefiles.mk):
#   make test-corefiles   every file a core names exists; every Verilog file
#                         of rtl/, soc/, fpga/ is named by exactly one core; the
#                         small YAML reader agrees with PyYAML; the Makefile's
#                         RTL lists (COREFILES_VARS) hold exactly their cores'
#                         files (tools/corefiles_check.py)
#   make test-corefiles-negative-orphan   a copy of the cores and sources with
#                         a Verilog file in rtl/ that no core names: must fail
#   make test-corefiles-negative-missing  a copy where the controller's core
#                         names a file that does not exist: must fail
#   make corefiles-print  the lists, one "NAME: files" line each

COREFILES_DIR  := $(BUILD)/corefiles
COREFILES_VARS := CTRL_RTL FPGA_RTL PB_RTL PICO_RTL PBN_RTL VEX_RTL EP_CORE EP_ENGINES CDC_SRC AXIL_SRC CTRL_SRC
COREFILES_CHECK := python3 tools/corefiles_check.py
# A copy of the cores with their sources, for the negatives: $(1) = name.
corefiles_copy = rm -rf $(COREFILES_DIR)/$(1) && mkdir -p $(COREFILES_DIR)/$(1) && \
    cp -r rtl soc fpga constraints $(COREFILES_DIR)/$(1)/

TESTS += corefiles corefiles-negative-orphan corefiles-negative-missing
.PHONY: corefiles-print test-corefiles test-corefiles-negative-orphan test-corefiles-negative-missing

corefiles-print:
	@$(foreach v,$(COREFILES_VARS),echo '$(v): $($(v))';)

test-corefiles: $(BUILD)/corefiles.mk
	@mkdir -p $(COREFILES_DIR)
	@env -u ALB_SUITE $(MAKE) -s --no-print-directory corefiles-print > $(COREFILES_DIR)/vars.txt
	@tools/run_test.sh corefiles $(COREFILES_CHECK) --vars $(COREFILES_DIR)/vars.txt

test-corefiles-negative-orphan:
	@$(call corefiles_copy,neg-orphan)
	@printf '`default_nettype none\nmodule albatross_orphan;\nendmodule\n' > $(COREFILES_DIR)/neg-orphan/rtl/albatross_orphan.v
	@tools/run_test.sh corefiles-negative-orphan bash -c 'if $(COREFILES_CHECK) --root $(COREFILES_DIR)/neg-orphan \
	    > $(COREFILES_DIR)/neg-orphan.log; then cat $(COREFILES_DIR)/neg-orphan.log; \
	    echo "expected the check to reject rtl/albatross_orphan.v (in no core), it passed"; exit 1; fi; \
	    grep "rtl/albatross_orphan.v: expected one core to name it, no core does" $(COREFILES_DIR)/neg-orphan.log || \
	    { cat $(COREFILES_DIR)/neg-orphan.log; echo "expected the failure to name rtl/albatross_orphan.v"; exit 1; }'

test-corefiles-negative-missing:
	@$(call corefiles_copy,neg-missing)
	@sed -i 's/^\(      - albatross_controller.v\)$$/\1\n      - albatross_gone.v/' $(COREFILES_DIR)/neg-missing/rtl/albatross_controller.core
	@grep -q albatross_gone.v $(COREFILES_DIR)/neg-missing/rtl/albatross_controller.core || \
	    { echo "corefiles-negative-missing: the sed did not apply to rtl/albatross_controller.core"; exit 1; }
	@tools/run_test.sh corefiles-negative-missing bash -c 'if $(COREFILES_CHECK) --root $(COREFILES_DIR)/neg-missing \
	    > $(COREFILES_DIR)/neg-missing.log; then cat $(COREFILES_DIR)/neg-missing.log; \
	    echo "expected the check to reject a core naming albatross_gone.v (no such file), it passed"; exit 1; fi; \
	    grep "names albatross_gone.v, which does not exist" $(COREFILES_DIR)/neg-missing.log || \
	    { cat $(COREFILES_DIR)/neg-missing.log; echo "expected the failure to name albatross_gone.v"; exit 1; }'
