# target: rtl/albatross_transfer_pick.v
# ignore_actual (formal/export/mutants/ignore_actual.sed on the datapath): the
# pick ignores the destination's Actual.  Must fail dst_no_actual_write.
s/    wire \[1:0\] pick3    = (a_pub != 2'd3 \&\& r_lock != 2'd3) ? 2'd3 : (a_pub != 2'd2 \&\& r_lock != 2'd2) ? 2'd2 : 2'd1;/    wire [1:0] pick3    = (r_lock != 2'd3) ? 2'd3 : (r_lock != 2'd2) ? 2'd2 : 2'd1;/
