# target: rtl/albatross_transfer_access.v
# Controller mutant: the store of a destination's Actual writes 7, a value
# no buffer has: the consumer's Import finds the control bytes corrupt.
s/({32{dst_fin_i}} \& ({29'd0, buf_i} << ACT_BIT));/({32{dst_fin_i}} \& (32'd7 << ACT_BIT));/
