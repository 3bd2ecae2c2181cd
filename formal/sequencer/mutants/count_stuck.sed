# count_stuck: the minor-cycle count does not wrap: it stays at 2^CB - 1.
# Must fail go_given (formal/sequencer/sequencer.sby neg_count_stuck: with
# CLUSTER_BITS 2, entry 0, due in minor cycle 0 of the second cluster, does
# not run there).
s/else if (step_i)   n_q <= n_q + 1'b1;/else if (step_i)   n_q <= \&n_q ? n_q : n_q + 1'b1;/
