# target: rtl/albatross_transfer_frag.v
# frag_wrong_word (tb/mutants/controller/frag_wrong_word.sed): a run that
# goes on resumes one word early.  Must fail frag_words_src (its source
# load is of word 0).
s/if (go_i \&\& cont) k_q <= st_prog_i;/if (go_i \&\& cont) k_q <= st_prog_i - 12'd1;/
