# target: rtl/albatross_transfer_fsm.v
# early_slot4 (formal/export/mutants/early_slot4.sed on the datapath): the
# four-slot Slot byte is stored right after the last value word, before
# taken_at.  Must fail dst_slot_complete.
s/lastf) begin_access(S_DST_TKN, first_d);/lastf) begin_access(four_i ? S_DST_SLOT : S_DST_TKN, first_d);/
s/else if (state_q == S_DST_TKN) begin_access(four_i ? S_DST_SLOT : S_DST_FIN, first_d);/else if (state_q == S_DST_TKN) begin_access(S_DST_FIN, first_d);/
s/else if (state_q == S_DST_SLOT) begin_access(S_DST_FIN, first_d);/else if (state_q == S_DST_SLOT) begin_access(S_DST_TKN, first_d);/
