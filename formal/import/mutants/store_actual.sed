# store_actual: the Import stores its copy into Actual (lane and byte of Actual)
# instead of ReadLocked: the consumer writes the producer's control byte.
# Must fail store_rl_only (formal/import/import.sby neg_store_actual).
s/    wire \[3:0\] sel        = (phase2 || four_q) \&\& !we ? 4'hF : we ? SEL_RL : SEL_ACT;/    wire [3:0] sel        = (phase2 || four_q) \&\& !we ? 4'hF : SEL_ACT;/
s/assign wb_dat_o     = {29'd0, act_q} << RL_BIT;/assign wb_dat_o     = {29'd0, act_q} << ACT_BIT;/
