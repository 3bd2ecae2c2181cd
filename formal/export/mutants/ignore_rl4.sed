# ignore_rl4: the four-slot Export ignores the consumer's ReadLocked and picks
# its pair from Actual (the producer ignoring the reader's byte).
# Must fail fs_other_pair or fs_no_write_read (export.sby four_neg_ignore_rl4).
s/    wire       pick_p    = rl_valid ? !rl_pair : act_valid ? !act_pair : 1'b1;/    wire       pick_p    = act_valid ? !act_pair : 1'b1;/
