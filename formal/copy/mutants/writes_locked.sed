# writes_locked: the Export's buffer choice ignores the ReadLocked it just loaded
# (figure 4 without CopyOfReadLocked; the mutant of
# tb/mutants/engines/export_writes_locked.sed), so it may write the buffer a
# destination's consumer is reading.  Must fail no_write_read
# (formal/copy/copy.sby neg_writes_locked).
s/wire \[1:0\] rl_lock   = rl_valid ? rl_byte\[1:0\] : 2'd0;/wire [1:0] rl_lock   = 2'd0;/
