# target: rtl/albatross_transfer_frag.v
# Controller mutant: a run cut off in its publication (after the value's last
# word, before any Slot or Actual store) ends the value instead of going on
# from word W - 1: the next run Imports afresh and stores from word 0, and
# with a slot too short for the value and its publication together the runs
# repeat without end.  The controller bench's scenario fragedge must fail
# (test-controller-negative-frag_pub_cut: "frag edge ...: expected the value
# published once").
s/    wire        mid   = FR \&\& safe_i/    wire        mid   = FR \&\& !lastf \&\& safe_i/
