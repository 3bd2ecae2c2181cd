# target: rtl/albatross_transfer_access.v
# Controller mutant: the store of a destination's Actual also writes its byte
# into the ReadLocked lane, a byte only the consumer may write.
s/                     dst_fin_i ? SEL_ACT :/                     dst_fin_i ? (SEL_ACT | SEL_RL) :/
s/({32{dst_fin_i}} \& ({29'd0, buf_i} << ACT_BIT));/({32{dst_fin_i}} \& {4{5'd0, buf_i}});/
