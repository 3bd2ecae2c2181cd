# target: rtl/albatross_transfer_pick.v
# Controller mutant, the three-buffer analogue of old_same_pair4: the
# three-buffer source Import answers Old whenever the source's Actual lies in
# the pair of its copy (pair(x) = (x - 1) >> 1: Buffer1 and Buffer2 one pair,
# Buffer3 the other), whatever the buffer: a value the producer published in
# the other buffer of that pair (two Exports between takes) is skipped, and
# withheld for good if the producer then stops.  Caught by the system test's
# freshness check (test-system-negative-freshness-pair3) and by the
# controller-top proof's src_fresh (test-formal-ctrl-negative-old_same_pair3).
s/    wire       a_match  = four_i ? c_is_l : a_byte\[2:0\] == rl_i;/    wire       a_match  = four_i ? c_is_l : (rl_i != 3'd0 \&\& a_pair == (rl_i[2] | (rl_i[1] \& rl_i[0])));/
