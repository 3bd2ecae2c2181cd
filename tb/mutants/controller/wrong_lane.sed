# target: rtl/albatross_export.v
# Controller mutant: the store of a destination's Actual also writes its byte
# into the ReadLocked lane, a byte only the consumer may write.
s/assign wb_sel_o     = state_q == S_LOAD_ACTUAL || state_q == S_STORE_ACTUAL ? SEL_ACT :/assign wb_sel_o     = state_q == S_LOAD_ACTUAL ? SEL_ACT : state_q == S_STORE_ACTUAL ? (SEL_ACT | SEL_RL) :/
s/^                          ({29'd0, buf_d} << ACT_BIT);/                          {4{5'd0, buf_d}};/
