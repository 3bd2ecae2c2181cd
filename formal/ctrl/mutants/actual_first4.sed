# target: rtl/albatross_transfer_fsm.v
# actual_first4 (formal/export/mutants/actual_first4.sed on the datapath): the
# four-slot Export stores Actual before the Slot byte.  Must fail
# dst_slot_first.  The last edit keeps req (an access begins in this clock:
# the deadline's cut-off) in step with the moved Slot store.
s/else if (state_q == S_DST_TKN) begin_access(four_i ? S_DST_SLOT : S_DST_FIN, first_d);/else if (state_q == S_DST_TKN) begin_access(S_DST_FIN, first_d);/
s/else if (state_q == S_DST_SLOT) begin_access(S_DST_FIN, first_d);/else if (state_q == S_DST_SLOT) finish;/
s/else if (state_q == S_DST_FIN) finish;/else if (state_q == S_DST_FIN) begin if (four_i) begin_access(S_DST_SLOT, first_d); else finish; end/
s/|| state_q == S_DST_TKN || state_q == S_DST_SLOT));/|| state_q == S_DST_TKN || state_q == S_DST_SLOT || (state_q == S_DST_FIN \&\& four_i)));/
