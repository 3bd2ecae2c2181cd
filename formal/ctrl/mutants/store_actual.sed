# target: rtl/albatross_transfer_access.v
# store_actual (formal/import/mutants/store_actual.sed on the datapath): the
# Import stores its copy into the source's Actual byte and lane.  Must fail
# src_store_rl.
s/                     src_rl_i ? SEL_RL :/                     src_rl_i ? SEL_ACT :/
s/({32{src_rl_i}} \& ({29'd0, ald_i} << RL_BIT))/({32{src_rl_i}} \& ({29'd0, ald_i} << ACT_BIT))/
