# target: rtl/albatross_transfer_fsm.v
# import_no_readlocked (tb/mutants/engines/import_no_readlocked.sed on the
# datapath): the Import takes Actual into its copy without storing
# ReadLocked.  Must fail src_no_torn.
s/^\( *\)begin_access(S_SRC_RL, 2'd0);/\1rl_q <= a_byte[2:0]; begin_access(S_SRC_ACT, 2'd0);/
