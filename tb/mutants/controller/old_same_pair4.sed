# target: rtl/albatross_transfer_pick.v
# Controller mutant: the four-slot source Import answers Old whenever the
# source's Actual names the pair of its ReadLocked copy L, whatever that
# pair's Slot byte says: a value the producer completed in the pair the
# controller holds (its Export began before the controller's ReadLocked
# store) is skipped, and withheld for good if the producer then stops.
# Caught by the system test's freshness check
# (test-system-negative-freshness-pair4) and by the controller-top proof's
# src_fresh (test-formal-ctrl-negative-old_same_pair4).
s/    wire       a_match  = four_i ? c_is_l : a_byte\[2:0\] == rl_i;/    wire       a_match  = four_i ? (rl_i != 3'd0 \&\& a_pair == (rl_i[2] | (rl_i[1] \& rl_i[0]))) : a_byte[2:0] == rl_i;/
