# target: rtl/albatross_controller.v
# Controller mutant: taken_at is recorded at the end of each COPY slot
# (time_o when the slot ends) instead of in the clock a New value is chosen,
# at the final source Actual load.  Every delivery carries a time that still
# lies near the transfer: only the system checker's exactness check
# (taken_at) sees it.
s/assign wr_tkn = !ready_q || tr_new;/assign wr_tkn = !ready_q || (slot_end \&\& tr_imp);/
