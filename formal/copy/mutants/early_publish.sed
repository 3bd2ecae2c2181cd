# early_publish: the Export stores Actual after W-1 words, before the last word
# of the value (the mutant of tb/mutants/engines/export_early_publish.sed): a
# destination buffer is published incompletely written.  Must fail
# publish_complete (formal/copy/copy.sby neg_early_publish).
s/wire       last_word = take_k_q == words_q;/wire       last_word = take_k_q == words_q - 1'b1;/
