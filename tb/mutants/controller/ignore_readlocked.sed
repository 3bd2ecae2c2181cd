# target: rtl/albatross_transfer_pick.v
# Controller mutant: the Export ignores the destination's ReadLocked and may
# write the buffer the consumer is reading (the paper, figure 4).
s/wire \[1:0\] r_lock   = r_valid ? r_byte\[1:0\] : 2'd0;/wire [1:0] r_lock   = 2'd0;/
