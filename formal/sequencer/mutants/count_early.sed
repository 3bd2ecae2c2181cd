# count_early: the minor-cycle count wraps one cycle early (after 2^CB - 2,
# not 2^CB - 1): from the first wrap on, entries run in the wrong minor cycles.
# Must fail go_time (formal/sequencer/sequencer.sby neg_count_early: with
# CLUSTER_BITS 2, entry 0, due in the even minor cycles, runs in cycle 3).
s/else if (step_i)   n_q <= n_q + 1'b1;/else if (step_i)   n_q <= (n_q == {{(CB-1){1'b1}}, 1'b0}) ? {CB{1'b0}} : n_q + 1'b1;/
