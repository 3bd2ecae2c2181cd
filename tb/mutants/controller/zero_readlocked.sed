# target: rtl/albatross_transfer_access.v
# Controller mutant: the store of a destination's Actual also writes the
# ReadLocked lane, with 0 (never a valid buffer).  The consumer's driver then
# loops without a RAM access: no bound in simulated cycles can end the run, so
# tb_system's wall-clock hand-off watchdog must (test system-negative-watchdog).
s/                     dst_fin_i ? SEL_ACT :/                     dst_fin_i ? (SEL_ACT | SEL_RL) :/
