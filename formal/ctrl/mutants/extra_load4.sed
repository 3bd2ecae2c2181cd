# target: rtl/albatross_transfer_fsm.v
# extra_load4 (formal/export/mutants/extra_load4.sed on the datapath): the
# four-slot Export loads a destination's control word a second time (as a
# read-back would; the flag borrows that destination's corrupt bit).  Must
# fail dst_one_load.
s/                else if (has_next) begin_access(state_q == S_DST_PUB ? S_DST_CTRL : state_q, next_d);/                else if (ctrl_ld \&\& four_i \&\& !cor_q[d_q]) begin cor_q <= cor_q | d_bit; begin_access(S_DST_CTRL, d_q); end\n                else if (has_next) begin_access(state_q == S_DST_PUB ? S_DST_CTRL : state_q, next_d);/
