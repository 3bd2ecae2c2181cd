# Import engine mutant: phase 1 takes Actual into its copy without storing
# ReadLocked (the producer never learns which buffer is being read).  Caught
# by: mutual_exclusion.
s/^\( *\)nst = S_STORE_RL;/\1nst = S_LOAD_ACTUAL;/
s/^\( *\)else if (!act_match) new_q <= 1'b1;/\1else if (!act_match) begin new_q <= 1'b1; rl_q <= act_byte[1:0]; end/
