# target: rtl/albatross_transfer_pick.v
# old_same_pair4 (tb/mutants/controller/old_same_pair4.sed): the four-slot source
# Import answers Old whenever Actual lies in the pair of its copy L, whatever
# the Slot byte says: a value completed in that pair is skipped.  Must fail
# src_fresh.
s/    wire       a_match  = four_i ? c_is_l : a_byte\[2:0\] == rl_i;/    wire       a_match  = four_i ? (rl_i != 3'd0 \&\& a_pair == (rl_i[2] | (rl_i[1] \& rl_i[0]))) : a_byte[2:0] == rl_i;/
