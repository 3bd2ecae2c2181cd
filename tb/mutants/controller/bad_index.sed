# target: rtl/albatross_export_dest.v
# Controller mutant: the Export's buffer choice can yield index 0, an invalid Actual.
s/(copy_d != BUFFER2 \&\& rl_lock != BUFFER2) ? BUFFER2 : BUFFER1;/(copy_d != BUFFER2 \&\& rl_lock != BUFFER2) ? BUFFER2 : 2'd0;/
