# target: rtl/albatross_transfer_frag.v
# Controller mutant: a fragment after the first resumes one word early (its
# word index from the progress minus one).  The controller bench's scenario
# frag must fail (test-controller-negative-frag_wrong_word: "frag whole:
# fragment 1 resumes at word 2").
s/if (go_i \&\& cont) k_q <= st_prog_i;/if (go_i \&\& cont) k_q <= st_prog_i - 12'd1;/
