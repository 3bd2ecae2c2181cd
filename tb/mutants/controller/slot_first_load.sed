# target: rtl/albatross_transfer_fsm.v
# Controller mutant: the four-slot source Import takes the Slot byte of the
# announced pair from its first control-word load (kept in the word
# register, unused until the Export) instead of the load after its
# ReadLocked store, so a value the producer completes between the two loads
# is not the one taken: an older one is, stamped with the second load's
# time.  The controller bench's scenario race4 must fail
# (test-controller-negative-slot_first_load); the system test's taken_at
# exactness sees it too.
s/    always @(posedge clk_i) if (take_en) word_q <= copy_i ? dat_i : status_i;/    always @(posedge clk_i) if (take_en) word_q <= copy_i ? dat_i : status_i; else if (ack \&\& state_q == S_SRC_ACT) word_q <= dat_i;/
s/                S_SRC_SLOT: if (ack) rl_q <= pick_l;/                S_SRC_SLOT: if (ack) rl_q <= four_i ? {1'b0, ald_q[2] | (ald_q[1] \& ald_q[0]), (ald_q[2] | (ald_q[1] \& ald_q[0])) ? word_q[24] : word_q[16]} + 3'd1 : pick_l;/
