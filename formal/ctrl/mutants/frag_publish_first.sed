# target: rtl/albatross_transfer_fsm.v
# frag_publish_first (tb/mutants/controller/frag_publish_first.sed): the
# first run of a value that may go over several runs publishes after its
# first word, so it publishes a buffer holding its first word only (the
# three edits keep the next-access logic in step).  Must fail
# dst_publish_complete (or frag_words_dst).
s/                else if (state_q == S_DST_WORD \&\& lastf) begin/                else if (state_q == S_DST_WORD \&\& (lastf || !cont_q)) begin/
s/: ((state_q == S_DST_WORD \&\& lastf) ||/: ((state_q == S_DST_WORD \&\& (lastf || !cont_q)) ||/
s/(adv \&\& state_q == S_DST_WORD \&\& !lastf))/(adv \&\& state_q == S_DST_WORD \&\& !(lastf || !cont_q)))/
