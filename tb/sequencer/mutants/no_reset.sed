# no_reset: the minor-cycle count restarts at 0 only at start-up, not at a
# mode switch: the new mode's entries run in the minor cycles the old count
# gives.  tb_sequencer_multirate +modes must fail (make
# test-sequencer-multirate-negative-no_reset).
s/else if (clear_i)  n_q <= {CB{1'b0}};/else if (clear_i)  n_q <= n_q;/
