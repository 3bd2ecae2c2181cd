# target: rtl/albatross_transfer_pick.v
# wrong_slot (formal/import/mutants/wrong_slot.sed on the datapath): the
# four-slot Import reads the other slot of the announced pair.  Must fail
# src_no_torn.
s/    wire \[2:0\] pick_l   = {1'b0, p_ald, p_ald ? dat_i\[S1_BIT\] : dat_i\[S0_BIT\]} + 3'd1;/    wire [2:0] pick_l   = {1'b0, p_ald, !(p_ald ? dat_i[S1_BIT] : dat_i[S0_BIT])} + 3'd1;/
