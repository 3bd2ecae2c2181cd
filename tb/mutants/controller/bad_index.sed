# target: rtl/albatross_transfer_pick.v
# Controller mutant: the Export's buffer choice can yield index 0, an invalid Actual.
s/(a_pub != 2'd2 \&\& r_lock != 2'd2) ? 2'd2 : 2'd1;/(a_pub != 2'd2 \&\& r_lock != 2'd2) ? 2'd2 : 2'd0;/
