# base_high: the due test also asks base < 2^rep (base's bits above rep must
# be 0), against the rule that only its low rep bits count: the --multirate
# image's entry of rep 2, base 5 never runs instead of running in the cycles
# n mod 4 = 1.  tb_sequencer_multirate must fail (make
# test-sequencer-multirate-negative-base_high).
s/            due_q    <= !MR || agree\[e6_rep\];/            due_q    <= !MR || (agree[e6_rep] \&\& (e6_base >> e6_rep) == 15'd0);/
