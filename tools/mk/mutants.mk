# tools/mk/mutants.mk -- the mutants' edits still land.
# Every negative test plants its fault with a sed script (tb/mutants/,
# formal/*/mutants/, sim/mutants/, ...).  A script of several edits can go
# stale one edit at a time when the file it edits is reworded, and then
# plants less than its name says.  tools/mutant_audit.py runs each edit alone
# and requires every one to change the script's file.
#   make test-mutants-audit            every edit of every mutant lands
#   make test-mutants-audit-negative   the audit names a stale edit of a
#                                      multi-edit script and of a '# target:' one

.PHONY: test-mutants-audit test-mutants-audit-negative
TESTS += mutants-audit mutants-audit-negative
test-mutants-audit:
	@tools/run_test.sh mutants-audit python3 tools/mutant_audit.py

test-mutants-audit-negative:
	@tools/run_test.sh mutants-audit-negative tools/mutant_audit_negative.sh
