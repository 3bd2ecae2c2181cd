# target: rtl/albatross_transfer_pick.v
# writes_locked (formal/export/mutants/writes_locked.sed, tb/mutants/engines/
# export_writes_locked.sed, tb/mutants/controller/ignore_readlocked.sed on the
# datapath): the pick ignores the ReadLocked just loaded.  Must fail
# dst_no_held_write.
s/    wire \[1:0\] r_lock   = r_valid ? r_byte\[1:0\] : 2'd0;/    wire [1:0] r_lock   = 2'd0;/
