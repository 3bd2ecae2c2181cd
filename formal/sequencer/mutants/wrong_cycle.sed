# wrong_cycle: the minor-cycle count starts at 1 instead of 0 after start-up
# and after a mode switch: every entry runs one minor cycle early, in a cycle it
# is not due in.  Must fail go_given (formal/sequencer/sequencer.sby
# neg_wrong_cycle: entry 0, due in minor cycle 0, does not run there).
s/if (rst_i || !MR)  n_q <= {CB{1'b0}};/if (rst_i || !MR)  n_q <= {{(CB-1){1'b0}}, 1'b1};/
s/else if (clear_i)  n_q <= {CB{1'b0}};/else if (clear_i)  n_q <= {{(CB-1){1'b0}}, 1'b1};/
