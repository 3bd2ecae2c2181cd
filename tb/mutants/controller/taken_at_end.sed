# target: rtl/albatross_controller.v
# Controller mutant: a New value's taken_at is recorded at the end of its
# transfer (time_o when the slot ends) instead of at the final source Actual
# load.  The first delivery still carries the right time (the Export sampled
# it at its start); every later delivery of that value (a redundant slot, after
# a failed or dropped destination) carries the end-of-transfer time, which
# still lies between the producer's publication and the destination's: only
# the system checker's exactness check (taken_at) sees it.
s/st_d\[31:0\]  = taken_q;/st_d[31:0]  = new_q ? time_o : taken_q;/
