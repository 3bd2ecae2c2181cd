# same_slot4: the four-slot Export writes the slot of pair p completed last
# (s = Slot_p instead of 1 - Slot_p), the buffer a consumer may be reading.
# Must fail fs_no_write_read (export.sby four_neg_same_slot4).
s/    wire       pick_s    = !(pick_p ? dat_i\[SLOT1_BIT\] : dat_i\[SLOT0_BIT\]);/    wire       pick_s    = pick_p ? dat_i[SLOT1_BIT] : dat_i[SLOT0_BIT];/
