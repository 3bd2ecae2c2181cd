# target: rtl/albatross_transfer_access.v
# wrong_lane (tb/mutants/controller/wrong_lane.sed on the datapath): the
# Actual store also writes its byte into the ReadLocked lane.  Must fail
# dst_ctrl_store.
s/                     dst_fin_i ? SEL_ACT :/                     dst_fin_i ? (SEL_ACT | SEL_RL) :/
s/({32{dst_fin_i}} \& ({29'd0, buf_i} << ACT_BIT));/({32{dst_fin_i}} \& {4{5'd0, buf_i}});/
