# writes_locked: the buffer choice ignores the ReadLocked just loaded (figure 4
# without CopyOfReadLocked; as tb/mutants/engines/export_writes_locked.sed), so
# the engine may write the buffer the consumer reads.  Must fail no_locked_write.
s/wire \[1:0\] rl_lock   = rl_valid ? rl_byte\[1:0\] : 2'd0;/wire [1:0] rl_lock   = 2'd0;/
