# target: rtl/albatross_transfer_fsm.v
# skip_confirm (formal/import/mutants/skip_confirm.sed on the datapath): the
# three-buffer Import chooses in the ack clock of its ReadLocked store,
# without the confirming load of Actual.  Must fail src_no_torn.
s/    wire       choose   = ack \&\& ((state_q == S_SRC_ACT \&\& a_valid \&\& a_match) || state_q == S_SRC_SLOT);/    wire       choose   = ack \&\& ((state_q == S_SRC_ACT \&\& a_valid \&\& a_match) || state_q == S_SRC_SLOT || (state_q == S_SRC_RL \&\& !four_i));/
