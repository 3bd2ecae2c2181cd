# target: rtl/albatross_transfer_fsm.v
# Controller mutant: a value's first run (a run that does not go on with a
# value) takes its first word for the value's last: after word 0's stores the
# publication begins (taken_at and the destination's Actual stored before the
# value is whole).  The edit is on the state machine's alias of lastf_i, the
# one place lastf enters it (the next-word choice, want, is tested before the
# publication branch, so an edit of that branch alone changes nothing).  The
# controller bench's scenario frag must fail
# (test-controller-negative-frag_publish_first: "frag whole: run 0 publishes
# nothing").
s/    wire       cont = cont_i, lastf = lastf_i, mid = mid_i;/    wire       cont = cont_i, lastf = lastf_i || !cont_q, mid = mid_i;/
