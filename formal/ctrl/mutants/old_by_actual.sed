# target: rtl/albatross_transfer_pick.v
# old_by_actual (formal/import/mutants/old_by_actual.sed on the datapath): the
# four-slot Import decides Old by "Actual is L".  Must fail dst_new_once.
s/    wire       a_match  = four_i ? c_is_l : a_byte\[2:0\] == rl_i;/    wire       a_match  = a_byte[2:0] == rl_i;/
