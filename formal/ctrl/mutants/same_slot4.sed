# target: rtl/albatross_transfer_pick.v
# same_slot4 (formal/export/mutants/same_slot4.sed on the datapath): the
# four-slot Export writes the slot of its pair completed last.  Must fail
# dst_no_held_write.
s/    wire       pk_s     = !(pk_p ? dat_i\[S1_BIT\] : dat_i\[S0_BIT\]);/    wire       pk_s     = (pk_p ? dat_i[S1_BIT] : dat_i[S0_BIT]);/
