# target: rtl/albatross_transfer_frag.v
# frag_progress_early: the progress of a value that goes on counts a word
# when it is taken (its source load), not when its stores to every
# destination have ended: a run cut off between a word's stores saves a
# progress past a word some destination lacks.  Must fail frag_prog (the
# next run would go on from W) or dst_publish_complete (a buffer published
# without that word).
s/else if (wend_i \&\& !lastf) kdone_q <= k_q;/else if (take_i) kdone_q <= k_q + 12'd1;/
