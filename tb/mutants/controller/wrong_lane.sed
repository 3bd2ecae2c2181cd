# target: rtl/albatross_transfer.v
# Controller mutant: the store of a destination's Actual also writes its byte
# into the ReadLocked lane, a byte only the consumer may write.
s/(state_q == S_DST_ACT || state_q == S_DST_FIN) ? SEL_ACT :/(state_q == S_DST_ACT) ? SEL_ACT : (state_q == S_DST_FIN) ? (SEL_ACT | SEL_RL) :/
s/({32{state_q == S_DST_FIN}} \& ({29'd0, buf_d} << ACT_BIT));/({32{state_q == S_DST_FIN}} \& {4{5'd0, buf_d}});/
