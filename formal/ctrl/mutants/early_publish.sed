# target: rtl/albatross_transfer_frag.v
# early_publish (formal/export/mutants/early_publish.sed on the datapath): the
# taken_at store follows after W-1 value words, so Actual publishes a buffer
# one value word short.  Must fail dst_publish_complete.
s/    wire        lastf = k_q == words_i;/    wire        lastf = k_q == words_i - 12'd1;/
