# old_by_actual: the four-slot Import decides Old by "Actual is L" (the mapping
# as first proposed) instead of "buf(pair(A), Slot_pair(A)) is L": a
# producer between its Slot and Actual stores then makes one value New twice.
# Must fail fs_new_exact (formal/import/import.sby four_neg_old_by_actual).
s/    wire       act_match  = four_q ? cur_b == rl_q : act_byte\[2:0\] == rl_q;/    wire       act_match  = act_byte[2:0] == rl_q;/
