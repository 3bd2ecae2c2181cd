# target: rtl/albatross_transfer.v
# new_unstored (formal/import/mutants/new_unstored.sed on the datapath): every
# load of Actual marks the value New.  Must fail dst_new_once.
s/^\( *\)ald_q <= a_byte\[2:0\];/&\n\1new_q <= 1'b1;/
