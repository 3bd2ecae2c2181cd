# target: rtl/albatross_transfer.v
# wrong_lane (tb/mutants/controller/wrong_lane.sed on the datapath): the
# Actual store also writes its byte into the ReadLocked lane.  Must fail
# dst_ctrl_store.
s/                     (state_q == S_DST_ACT || state_q == S_DST_FIN) ? SEL_ACT :/                     (state_q == S_DST_ACT) ? SEL_ACT : (state_q == S_DST_FIN) ? (SEL_ACT | SEL_RL) :/
s/({29'd0, buf_d} << ACT_BIT)/{4{5'd0, buf_d}}/
