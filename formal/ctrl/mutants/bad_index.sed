# target: rtl/albatross_transfer_pick.v
# bad_index (tb/mutants/controller/bad_index.sed on the datapath): the pick can
# yield buffer 0.  Must fail dst_ctrl_store or dst_in_channel.
s/(a_pub != 2'd2 \&\& r_lock != 2'd2) ? 2'd2 : 2'd1;/(a_pub != 2'd2 \&\& r_lock != 2'd2) ? 2'd2 : 2'd0;/
