# target: rtl/albatross_transfer_fsm.v
# Controller mutant, the three-buffer analogue of old_same_pair4: the
# three-buffer source Import's first load answers Old whenever the source's
# Actual lies in the pair of its copy (pair(x) = (x - 1) >> 1: Buffer1 and
# Buffer2 one pair, Buffer3 the other), whatever the buffer; its confirming
# loads, after a ReadLocked store, still compare the buffer.  A value the
# producer published in the other buffer of that pair (two Exports between
# takes) is skipped, and withheld for good if the producer then stops.
# Caught by the system test's freshness check
# (test-system-negative-freshness-pair3) and by the controller-top proof's
# src_fresh (test-formal-ctrl-negative-old_same_pair3).
s/\.a_match_o(a_match)/.a_match_o(a_match_p)/
s/^    albatross_transfer_pick u_pick (/    wire       a_match_p;\n    assign a_match = a_match_p || (!four_i \&\& !new_q \&\& rl_q != 3'd0 \&\& (a_byte[2] | (a_byte[1] \& a_byte[0])) == (rl_q[2] | (rl_q[1] \& rl_q[0])));\n    albatross_transfer_pick u_pick (/
