# idx_actual: the four-slot Import reads the buffer Actual named (the index
# taken from Actual, not from the slot byte after the ReadLocked store).
# Must fail fs_no_torn (formal/import/import.sby four_neg_idx_actual).
s/    wire \[2:0\] pick_b     = {1'b0, pair_a, slot_a} + 3'd1;/    wire [2:0] pick_b     = act_q;/
