# wrong_slot: the four-slot Import reads the other slot of the announced pair
# (the one the producer may be writing).
# Must fail fs_no_torn (formal/import/import.sby four_neg_wrong_slot).
s/    wire       slot_a     = pair_a ? wb_dat_i\[SLOT1_BIT\] : wb_dat_i\[SLOT0_BIT\];/    wire       slot_a     = !(pair_a ? wb_dat_i[SLOT1_BIT] : wb_dat_i[SLOT0_BIT]);/
