# tools/mk/contract.mk -- the contract, defined once (docs/contract.md): the schedule
# ROM format and the channel memory layout in rtl/albatross_contract.toml.
# compiler/albatross_schedule/contract_gen.py generates from it
#   rtl/albatross_contract.vh  c-driver/albatross_layout.h  tb/common/albatross_contract.h
# and the tables between <!-- contract:NAME --> markers in README.md and docs/*.md.
#   make contract                   regenerate them all
#   make test-contract-current      fails naming every generated file that is stale
#   make test-contract-oracles      the independent test oracles agree with the definition
#   make test-contract-negative     a definition with one field width changed: the
#                                   current check, the oracles and the controller's lint all fail
#   make test-contract-negative-four-slot
#                                   a [layout.four_slot] with Slot1 moved past the control
#                                   word: the generator refuses it, naming the byte

CONTRACT      := $(PYTHON) -m albatross_schedule.contract_gen
CONTRACT_DEF  := rtl/albatross_contract.toml
CONTRACT_MD    = $(wildcard README.md docs/*.md)
CONTRACT_NEG  := $(BUILD)/contract-negative

.PHONY: contract test-contract-current test-contract-oracles test-contract-negative test-contract-negative-four-slot
contract: ## regenerate the files derived from rtl/albatross_contract.toml (Verilog include, C/C++ headers, doc tables)
	@$(CONTRACT) $(CONTRACT_MD)

TESTS += contract-current contract-oracles contract-negative contract-negative-four-slot
test-contract-current:
	@tools/run_test.sh contract-current $(CONTRACT) --check $(CONTRACT_MD)

test-contract-oracles:
	@tools/run_test.sh contract-oracles $(PYTHON) -m unittest -v compiler/tests/test_contract.py

# E0.w narrowed from 12 to 11 bits in a copy of the definition: the files generated
# from the copy differ from the committed ones (check fails, naming them), the
# oracles disagree with it, and the controller with the copy's include fails lint.
test-contract-negative:
	@tools/run_test.sh contract-negative bash -c 'set -u; rm -rf $(CONTRACT_NEG); mkdir -p $(CONTRACT_NEG)/rtl; \
	    sed "s/{ name = \"w\",     lsb = 0,  width = 12,/{ name = \"w\",     lsb = 0,  width = 11,/" \
	        $(CONTRACT_DEF) > $(CONTRACT_NEG)/contract.toml; \
	    if cmp -s $(CONTRACT_NEG)/contract.toml $(CONTRACT_DEF); then \
	        echo "the edit did not apply: $(CONTRACT_DEF) no longer has the E0.w line this test changes"; exit 1; fi; \
	    fail=0; \
	    if $(CONTRACT) --definition $(CONTRACT_NEG)/contract.toml --check $(CONTRACT_MD) 2> $(CONTRACT_NEG)/check.log; then \
	        echo "FAIL: the current check passed with a drifted definition"; fail=1; \
	    else sed "s/^/  caught: /" $(CONTRACT_NEG)/check.log; fi; \
	    if ALB_CONTRACT=$(CONTRACT_NEG)/contract.toml $(PYTHON) -m unittest compiler/tests/test_contract.py \
	        > $(CONTRACT_NEG)/oracles.log 2>&1; then \
	        echo "FAIL: the oracle tests passed against a drifted definition"; fail=1; \
	    else grep -m 4 "^FAIL:\|^AssertionError" $(CONTRACT_NEG)/oracles.log | sed "s/^/  caught by the oracle tests: /"; fi; \
	    $(CONTRACT) --definition $(CONTRACT_NEG)/contract.toml --root $(CONTRACT_NEG) > /dev/null && \
	    cp $(CTRL_RTL) $(CONTRACT_NEG)/rtl/ && \
	    if verilator --lint-only -Wall -y $(CONTRACT_NEG)/rtl --top-module albatross_controller \
	        $(CONTRACT_NEG)/rtl/albatross_controller.v > $(CONTRACT_NEG)/lint.log 2>&1; then \
	        echo "FAIL: the controller linted clean with the drifted include"; fail=1; \
	    else grep -m 2 "%Warning\|%Error" $(CONTRACT_NEG)/lint.log | sed "s/^/  caught by the lint: /"; fi; \
	    if [ $$fail = 0 ]; then echo "a drifted definition is caught by the check, the oracles and the lint"; fi; \
	    exit $$fail'

# Slot1 moved from offset 3 to 4 (into Buffer1) in a copy of the definition:
# make contract must refuse it (status 2) and name the byte and the rule.
test-contract-negative-four-slot:
	@tools/run_test.sh contract-negative-four-slot bash -c 'set -u; rm -rf $(CONTRACT_NEG)-fs; mkdir -p $(CONTRACT_NEG)-fs; \
	    sed "s/{ name = \"slot1\", offset = 3,/{ name = \"slot1\", offset = 4,/" \
	        $(CONTRACT_DEF) > $(CONTRACT_NEG)-fs/contract.toml; \
	    if cmp -s $(CONTRACT_NEG)-fs/contract.toml $(CONTRACT_DEF); then \
	        echo "the edit did not apply: $(CONTRACT_DEF) no longer has the slot1 line this test changes"; exit 1; fi; \
	    $(CONTRACT) --definition $(CONTRACT_NEG)-fs/contract.toml --root $(CONTRACT_NEG)-fs --check \
	        > $(CONTRACT_NEG)-fs/check.log 2>&1; rc=$$?; \
	    sed "s/^/  /" $(CONTRACT_NEG)-fs/check.log; \
	    if [ $$rc = 2 ] && grep -q "slot1 at offset 4 is outside the control word" $(CONTRACT_NEG)-fs/check.log; then \
	        echo "a bad four_slot section is refused, naming the byte"; exit 0; fi; \
	    echo "FAIL: expected status 2 and a message naming slot1 outside the control word, got status $$rc"; exit 1'
