# early_publish: Actual is stored after W-1 words, before the last word of the
# value (as tb/mutants/engines/export_early_publish.sed): a buffer is published
# incompletely written.  Must fail complete_publish (formal/export/export.sby).
s/wire       last_word = take_k_q == words_q;/wire       last_word = take_k_q == words_q - 1'b1;/
