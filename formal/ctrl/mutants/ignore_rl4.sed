# target: rtl/albatross_transfer_pick.v
# ignore_rl4 (formal/export/mutants/ignore_rl4.sed on the datapath): the
# four-slot pair is picked from Actual, ignoring the reader's ReadLocked.
# Must fail dst_no_held_write.
s/    wire       pk_p     = r_valid ? !r_pair : r_zero ? 1'b1 : a_valid ? !a_pair : 1'b1;/    wire       pk_p     = a_valid ? !a_pair : 1'b1;/
