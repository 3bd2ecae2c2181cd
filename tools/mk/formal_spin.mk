# tools/mk/formal_spin.mk -- SPIN model check of the three-buffer protocol
# (formal/spin/albatross.pml, run by formal/spin/check.py).
#   make test-formal-spin       every property: mutual exclusion, definite results,
#                               actuality, New/Old, retries; writer wait-free and
#                               lock-free hold; the reader's Import is NOT wait-free
#                               (Spin must find the starvation cycle).
#                               Report: build/reports/formal_spin.json
#   make test-formal-spin-negative-<variant>
#                               a broken variant (the driver mutants of tb/mutants/driver/)
#                               must violate mutual exclusion and definite results.
# Builds (spin -a, gcc pan.c) go to build/formal/spin/.

SPIN_DIR      := $(BUILD)/formal/spin
SPIN_CHECK    := formal/spin/check.py
# variant:-D switch of the model
SPIN_NEGATIVE := while-as-if:WHILE_AS_IF ignore-readlocked:IGNORE_READLOCKED

SPIN_TESTS    := formal-spin $(foreach v,$(SPIN_NEGATIVE),formal-spin-negative-$(call neg_field,$(v),1))
TESTS         += $(SPIN_TESTS)
FORMAL_TESTS  += $(SPIN_TESTS)

.PHONY: $(addprefix test-,$(SPIN_TESTS))

test-formal-spin:
	@tools/run_test.sh formal-spin $(PYTHON) $(SPIN_CHECK) --out $(SPIN_DIR) \
	    --json $(REPORTS)/formal_spin.json

define SPIN_NEG_RULE
test-formal-spin-negative-$(call neg_field,$(1),1):
	@tools/run_test.sh formal-spin-negative-$(call neg_field,$(1),1) $(PYTHON) $(SPIN_CHECK) \
	    --variant $(call neg_field,$(1),2) --must-fail mutex,definite \
	    --out $(SPIN_DIR)/negative --json $(REPORTS)/formal_spin_negative_$(call neg_field,$(1),1).json
endef
$(foreach v,$(SPIN_NEGATIVE),$(eval $(call SPIN_NEG_RULE,$(v))))
