# Export engine mutant: the buffer choice ignores the ReadLocked just loaded,
# so the engine may write the buffer the consumer is reading (figure 4
# without CopyOfReadLocked).  Caught by: mutual_exclusion.
s/wire \[1:0\] rl_lock   = rl_valid ? rl_byte\[1:0\] : 2'd0;/wire [1:0] rl_lock   = 2'd0;/
