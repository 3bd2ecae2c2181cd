# deadline_late: the deadline check allows one clock more than it should: the
# clock before decides that an access put on the bus one clock later than it
# may still ends before D (rel + 1 <= D - MARGIN instead of rel + 1 < D -
# MARGIN, rel that clock's), so may_access_o stays high one clock too long and
# the last access may end after D.
# Must fail deadline (formal/sequencer/sequencer.sby neg_deadline_late).
# (edits rtl/albatross_slot_timing.v, where the deadline check lives)
s/wire \[TB:0\]   df = {1'b0, next_rel_q\[TB-1:0\]} - {1'b0, dm};/wire [TB:0]   df = {1'b0, next_rel_q[TB-1:0]} - {1'b0, dm} - 1'b1;/
