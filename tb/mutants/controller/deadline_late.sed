# target: rtl/albatross_slot_timing.v
# Controller mutant (formal/sequencer/mutants/deadline_late.sed on the
# controller): the deadline check allows one clock more than it should, so
# an access may begin in D - TIMEOUT - 1 and, timing out, end at the
# deadline D.  The controller bench's scenario deadline must fail
# (test-controller-negative-deadline_late): its slots of 16 lengths put a
# retry of a dead source on every phase of the rule.
s/wire \[TB:0\]   df = {1'b0, next_rel_q\[TB-1:0\]} - {1'b0, dm};/wire [TB:0]   df = {1'b0, next_rel_q[TB-1:0]} - {1'b0, dm} - 1'b1;/
