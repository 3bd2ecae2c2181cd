# Import engine mutant: phase 1 takes Actual into its copy without storing
# ReadLocked (the producer never learns which buffer is being read).  Caught
# by: mutual_exclusion.
s/state_q <= may_access_i ? S_STORE_RL : S_IDLE;/state_q <= may_access_i ? S_LOAD_ACTUAL : S_IDLE; rl_q <= act_byte[1:0]; rl_known_q <= 1'b1; we_q <= 1'b0; sel_q <= SEL_ACT;/
