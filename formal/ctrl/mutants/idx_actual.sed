# target: rtl/albatross_transfer_fsm.v
# idx_actual (formal/import/mutants/idx_actual.sed on the datapath): the
# four-slot Import reads the buffer Actual named.  Must fail src_no_torn.
s/                S_SRC_SLOT: if (ack) rl_q <= pick_l;/                S_SRC_SLOT: if (ack) rl_q <= ald_q;/
