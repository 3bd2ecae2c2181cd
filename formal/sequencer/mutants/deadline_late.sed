# deadline_late: may_access_o compares the current clock rather than the next
# one with the deadline (c <= D - MARGIN instead of c + 1 <= D - MARGIN), so it
# stays high one clock too long and the last access may end after D.
# Must fail deadline (formal/sequencer/sequencer.sby neg_deadline_late).
s/assign may_access_o = (state_q == ST_TRANSFER || go_now) \&\& next_rel_q <= end_q - MARGIN_T;/assign may_access_o = (state_q == ST_TRANSFER || go_now) \&\& next_rel_q - 1'b1 <= end_q - MARGIN_T;/
