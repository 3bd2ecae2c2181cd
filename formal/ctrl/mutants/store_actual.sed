# target: rtl/albatross_transfer.v
# store_actual (formal/import/mutants/store_actual.sed on the datapath): the
# Import stores its copy into the source's Actual byte and lane.  Must fail
# src_store_rl.
s/                     (state_q == S_SRC_RL) ? SEL_RL :/                     (state_q == S_SRC_RL) ? SEL_ACT :/
s/({29'd0, ald_q} << RL_BIT)/({29'd0, ald_q} << ACT_BIT)/
