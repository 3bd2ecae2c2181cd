# target: rtl/albatross_transfer_fsm.v
# frag_publish_first (tb/mutants/controller/frag_publish_first.sed): a
# fragmented value's first fragment is taken for its last, so the first slot
# publishes a buffer holding its first word only.  Must fail frag_words_dst
# (a taken_at store in a slot that is not the last) or dst_publish_complete.
s/                        if (lastf) begin/                        if (lastf || !cont_q) begin/
