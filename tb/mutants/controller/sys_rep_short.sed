# target: rtl/albatross_minor_cycles.v
# Controller mutant: a repetition read one bit short: the due test compares
# rep - 1 low bits of the minor-cycle count with the base instead of rep, so an
# entry of repetition 2^rep (rep >= 1) runs in twice as many minor cycles as it
# is due in.  The system checker's due_cycle must catch it
# (test-system-negative-rep-short).
s/            due_q    <= !MR || agree\[e6_rep\];/            due_q    <= !MR || agree[e6_rep - {3'd0, e6_rep != 4'd0}];/
