# target: rtl/albatross_export.v
# Controller mutant: the store of a destination's Actual also writes the
# ReadLocked lane, with 0 (never a valid buffer).  The consumer's driver then
# loops without a RAM access: no bound in simulated cycles can end the run, so
# tb_system's wall-clock hand-off watchdog must (test system-negative-watchdog).
s/assign wb_sel_o     = state_q == S_LOAD_ACTUAL || state_q == S_STORE_ACTUAL ? SEL_ACT :/assign wb_sel_o     = state_q == S_LOAD_ACTUAL ? SEL_ACT : state_q == S_STORE_ACTUAL ? (SEL_ACT | SEL_RL) :/
