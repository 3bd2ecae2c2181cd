# formal/bus_master/tests.mk -- the SymbiYosys tests of formal/bus_master/bus_master.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-bus_master:bus_master:prove:pass \
    formal-bus_master-pdr-reqs2:bus_master:prove_pdr_reqs2:pass \
    formal-bus_master-cover:bus_master:cover:pass \
    formal-bus_master-negative-no_gap:bus_master:neg_no_gap:fail_gap \
    formal-bus_master-negative-tmo_early:bus_master:neg_tmo_early:err_tmo \
    formal-bus_master-negative-ack_first:bus_master:neg_ack_first:own_silent \
    formal-bus_master-negative-board_first:bus_master:neg_board_first:adr_owner \
    formal-bus_master-negative-no_hold:bus_master:neg_no_hold:own_fields \
    formal-bus_master-negative-no_abort:bus_master:neg_no_abort:pass_now \
    formal-bus_master-negative-no_hold_fields:bus_master:neg_no_hold_fields:req_stable \
    formal-bus_master-negative-no_reset_gap:bus_master:neg_no_reset_gap:req_reset
# A second mutant of a property that a negative above already breaks runs
# with make test-slow.
FSBY_SLOW_SPEC += \
    formal-bus_master-negative-tmo_late:bus_master:neg_tmo_late:err_tmo \
    formal-bus_master-negative-drop_raise:bus_master:neg_drop_raise:req_stable
FSBY_MUTANTS += bus_master:no_gap bus_master:tmo_late bus_master:tmo_early \
                bus_master:ack_first bus_master:board_first bus_master:no_hold \
                bus_master:drop_raise bus_master:no_abort bus_master:no_hold_fields \
                bus_master:no_reset_gap
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-bus_master proves (make formal-slow).
FSBY_SLOW_SPEC += formal-bus_master-pdr:bus_master:prove_pdr:pass

# The bus master as the controller instantiates it (tasks with the tag ctrl):
# ctrl_params.py reads REQS, HOLD_FIELDS, TIMEOUT, ADDR_WIDTH and BOARD_BITS from
# rtl/albatross_controller.v's instance into a Yosys chparam script that the
# tasks run, so the proof follows the controller's configuration; the
# ctrlmin/ctrlmax tasks take the controller's TIMEOUT and ADDR_WIDTH at the
# ends of the ranges their declarations state (--at min / max).
FBM_CTRL_DIR := $(BUILD)/formal/sby/bus_master-ctrl
FBM_CTRL_YS  := $(FBM_CTRL_DIR)/ctrl_params.ys $(FBM_CTRL_DIR)/ctrl_params_min.ys $(FBM_CTRL_DIR)/ctrl_params_max.ys
$(FBM_CTRL_YS): formal/bus_master/ctrl_params.py rtl/albatross_controller.v rtl/albatross_bus_master.v \
                formal/bus_master/fbus_master.v
	@$(PYTHON) formal/bus_master/ctrl_params.py $@ --at $(or $(patsubst ctrl_params_%.ys,%,$(filter-out ctrl_params.ys,$(@F))),default)
FBM_CTRL_SPEC := \
    formal-bus_master-ctrl:bus_master:prove_ctrl:pass \
    formal-bus_master-ctrl-min:bus_master:prove_ctrl_min:pass \
    formal-bus_master-ctrl-max:bus_master:prove_ctrl_max:pass \
    formal-bus_master-cover-ctrl:bus_master:cover_ctrl:pass \
    formal-bus_master-negative-ctrl-dat_owner_q:bus_master:neg_ctrl_dat_owner_q:fld_pass \
    formal-bus_master-negative-ctrl-no_abort:bus_master:neg_ctrl_no_abort:pass_now
# The second proof (abc pdr, no probes) and the old master's mutant, which
# the harness at the defaults already catches, run with make formal-slow.
FBM_CTRL_SLOW := \
    formal-bus_master-pdr-ctrl:bus_master:prove_pdr_ctrl:pass \
    formal-bus_master-negative-ctrl-drop_raise:bus_master:neg_ctrl_drop_raise:req_stable
FSBY_TESTS_SPEC += $(FBM_CTRL_SPEC)
FSBY_SLOW_SPEC  += $(FBM_CTRL_SLOW)
FSBY_MUTANTS    += bus_master:dat_owner_q
$(foreach t,$(FBM_CTRL_SPEC) $(FBM_CTRL_SLOW),test-$(call neg_field,$(t),1)): $(FBM_CTRL_YS)

# ctrl_params.py on doctored copies of the controller: an instance with REQS 3
# must give REQS 3 (the proof follows the controller), TIMEOUT's range ending
# at 50 must give TIMEOUT 50 with --at max, and a value it cannot resolve
# (HOLD_FIELDS an expression) must be refused, naming the parameter.
FBM_CTRL_NEG := $(BUILD)/formal/sby/bus_master-ctrl/negative
TESTS += formal-bus_master-ctrl-params-negative
.PHONY: test-formal-bus_master-ctrl-params-negative
test-formal-bus_master-ctrl-params-negative: formal/bus_master/ctrl_params.py rtl/albatross_controller.v
	@tools/run_test.sh formal-bus_master-ctrl-params-negative bash -c 'set -u; d=$(FBM_CTRL_NEG); rm -rf $$d; mkdir -p $$d; \
	    sed "s/\(albatross_bus_master #(.*\)\.REQS(2)/\1.REQS(3)/" rtl/albatross_controller.v > $$d/reqs3.v; \
	    sed "s/\(albatross_bus_master #(.*\)\.HOLD_FIELDS(0)/\1.HOLD_FIELDS(HAS_SYNC - 1)/" rtl/albatross_controller.v > $$d/expr.v; \
	    sed "s/\(^ *parameter TIMEOUT *=.*\)3\.\.60/\13..50/" rtl/albatross_controller.v > $$d/tmo50.v; \
	    for f in reqs3 expr tmo50; do if cmp -s $$d/$$f.v rtl/albatross_controller.v; then \
	        echo "the edit $$f did not apply: the bus master instance in rtl/albatross_controller.v no longer has the field it changes"; exit 1; fi; done; \
	    fail=0; \
	    if $(PYTHON) formal/bus_master/ctrl_params.py $$d/reqs3.ys --controller $$d/reqs3.v && grep -q -- "-set REQS 3 " $$d/reqs3.ys; then \
	        echo "  an instance with REQS 3 gives: $$(grep chparam $$d/reqs3.ys)"; \
	    else echo "FAIL: expected -set REQS 3 from an instance with .REQS(3), came: $$(cat $$d/reqs3.ys 2>/dev/null)"; fail=1; fi; \
	    if $(PYTHON) formal/bus_master/ctrl_params.py $$d/tmo50.ys --at max --controller $$d/tmo50.v && grep -q -- "-set TIMEOUT 50 " $$d/tmo50.ys; then \
	        echo "  TIMEOUT declared 3..50, --at max gives: $$(grep chparam $$d/tmo50.ys)"; \
	    else echo "FAIL: expected -set TIMEOUT 50 with --at max from a TIMEOUT declared 3..50, came: $$(cat $$d/tmo50.ys 2>/dev/null)"; fail=1; fi; \
	    $(PYTHON) formal/bus_master/ctrl_params.py $$d/expr.ys --controller $$d/expr.v 2> $$d/expr.log; rc=$$?; \
	    sed "s/^/  /" $$d/expr.log; \
	    if [ $$rc = 2 ] && grep -q "HOLD_FIELDS to .HAS_SYNC - 1." $$d/expr.log; then echo "  an expression is refused, naming HOLD_FIELDS"; \
	    else echo "FAIL: expected status 2 and a message naming HOLD_FIELDS for .HOLD_FIELDS(HAS_SYNC - 1), came status $$rc"; fail=1; fi; \
	    exit $$fail'
