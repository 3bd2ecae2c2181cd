# tools/mk/formal_spin.mk -- SPIN model checks of the three-buffer protocol
# (formal/spin/albatross.pml) and of the four-slot channel (formal/spin/four_slot.pml),
# both run by formal/spin/check.py.
#   make test-formal-spin       every property: mutual exclusion, definite results,
#                               actuality, New/Old, retries, each also from a zeroed
#                               RAM (cold_*: each side's init at any point); writer wait-free and
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

SPIN_TESTS    := formal-spin $(foreach v,$(SPIN_NEGATIVE),formal-spin-negative-$(call neg_field,$(v),1)) \
                 formal-spin-negative-cold-read-zero
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

# The cold start (-DCOLD_START, checked as cold_* by test-formal-spin): an
# Import that reads Buffer1 while Actual is still 0, as if the RAM image had
# set it, meets alb_producer_init writing Buffer1.
test-formal-spin-negative-cold-read-zero:
	@tools/run_test.sh formal-spin-negative-cold-read-zero $(PYTHON) $(SPIN_CHECK) \
	    --variant COLD_READ_ZERO --must-fail cold_mutex,cold_definite \
	    --out $(SPIN_DIR)/negative --json $(REPORTS)/formal_spin_negative_cold_read_zero.json

# --- the four-slot channel: formal/spin/four_slot.pml -----------
#   make test-formal-spin-four-slot
#                               every property of the four-slot channel: mutual
#                               exclusion, definite results, actuality, New/Old,
#                               the access bound (1 + W / 3 + W per Import), also
#                               with W = 1, L = 1 at init, consumer crashes and
#                               from a zeroed RAM (cold_*);
#                               reader_wait_free, writer_wait_free and lock_free
#                               all HOLD.  Report: build/reports/formal_spin_four_slot.json
#                               (actuality and cold_actuality at W = 1 here; at
#                               W = 2, crash_newold and ctrl_newold: below, make test-slow)
#   make test-formal-spin-four-slot-deep
#                               those four rows (build/reports/formal_spin_four_slot_deep.json)
#   make test-formal-spin-four-slot-negative-<variant>
#                               a broken variant must violate the checks named
#                               in its third field (breadth-first: a shortest
#                               counterexample; its steps in .../trail.txt)
SPIN_FS_DIR      := $(SPIN_DIR)/four_slot
# variant:-D switch:checks that must fail
SPIN_FS_NEGATIVE := wrong-order:WRONG_ORDER:mutex,definite \
                    index-from-actual:INDEX_FROM_ACTUAL:mutex,definite \
                    ignore-readlocked:IGNORE_READLOCKED:mutex,definite \
                    rl-as-last:RL_AS_LAST:actuality,actuality_w1 \
                    slot-after-actual:SLOT_AFTER_ACTUAL:definite,actuality,newold \
                    new-if-a-ne-l:NEW_IF_A_NE_L:newold \
                    reread:REREAD:bound,reader_wait_free \
                    cold-pair-of-actual:COLD_PAIR_OF_ACTUAL:cold_newold

SPIN_FS_TESTS    := formal-spin-four-slot \
                    $(foreach v,$(SPIN_FS_NEGATIVE),formal-spin-four-slot-negative-$(call neg_field,$(v),1))
TESTS            += $(SPIN_FS_TESTS)
FORMAL_TESTS     += $(SPIN_FS_TESTS)

.PHONY: $(addprefix test-,$(SPIN_FS_TESTS))

test-formal-spin-four-slot:
	@tools/run_test.sh formal-spin-four-slot $(PYTHON) $(SPIN_CHECK) --model four_slot --skip $(SPIN_FS_DEEP) \
	    --out $(SPIN_FS_DIR) --json $(REPORTS)/formal_spin_four_slot.json
# New/Old with consumer crashes and with the controller's Import rule: the two
# longest searches (about 45 s together), run with make test-slow.  make test
# keeps the other crash_* and ctrl_* rows, and New/Old itself.
SPIN_FS_DEEP := crash_newold,ctrl_newold,actuality,cold_actuality
SLOW_TESTS   += formal-spin-four-slot-deep
.PHONY: test-formal-spin-four-slot-deep formal-slow
formal-slow: test-formal-spin-four-slot-deep
test-formal-spin-four-slot-deep:
	@tools/run_test.sh formal-spin-four-slot-deep $(PYTHON) $(SPIN_CHECK) --model four_slot --only $(SPIN_FS_DEEP) \
	    --out $(SPIN_FS_DIR)/deep --json $(REPORTS)/formal_spin_four_slot_deep.json

define SPIN_FS_NEG_RULE
test-formal-spin-four-slot-negative-$(call neg_field,$(1),1):
	@tools/run_test.sh formal-spin-four-slot-negative-$(call neg_field,$(1),1) $(PYTHON) \
	    $(SPIN_CHECK) --model four_slot --variant $(call neg_field,$(1),2) \
	    --must-fail $(call neg_field,$(1),3) --out $(SPIN_FS_DIR)/negative \
	    --json $(REPORTS)/formal_spin_four_slot_negative_$(call neg_field,$(1),1).json
endef
$(foreach v,$(SPIN_FS_NEGATIVE),$(eval $(call SPIN_FS_NEG_RULE,$(v))))
