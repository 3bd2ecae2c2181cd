# target: rtl/albatross_transfer_fsm.v
# new_unstored (formal/import/mutants/new_unstored.sed on the datapath): every
# load of Actual marks the value New, so a value chosen at that load (Old:
# Actual is the one read last) is published as New again.  Must fail
# dst_new_once.  (Setting new_q at the load, as the Import engine's mutant
# does, is not a fault here: the datapath decides New or Old in the clock of
# the load, from new_q before it, and abc pdr proves dst_new_once with it.)
s/    wire \[3:0\] need_now = (new_q ? 4'hF : st_need_i) & active_i;/    wire [3:0] need_now = ((new_q || state_q == S_SRC_ACT) ? 4'hF : st_need_i) \& active_i;/
s/    assign new_o       = nrm && choose && new_q;/    assign new_o       = nrm \&\& choose \&\& (new_q || state_q == S_SRC_ACT);/
