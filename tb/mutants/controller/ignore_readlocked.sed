# Controller mutant: the Export ignores the destination's ReadLocked and may
# write the buffer the consumer is reading (seed figure 4).
s/wire \[1:0\]    pick_v = pick(act_cur, vidx(r_byte) ? r_byte\[1:0\] : 2'd0);/wire [1:0]    pick_v = pick(act_cur, 2'd0);/
