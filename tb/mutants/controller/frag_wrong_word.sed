# target: rtl/albatross_transfer_frag.v
# Controller mutant: a run that goes on with a value resumes one word early
# (its word index from the progress minus one: a word already stored to the
# destination).  The controller bench's scenario frag must fail
# (test-controller-negative-frag_wrong_word: "frag whole: run 1 goes on at
# the first word not yet stored to the destination").
s/if (go_i \&\& cont) k_q <= st_prog_i;/if (go_i \&\& cont) k_q <= st_prog_i - 12'd1;/
