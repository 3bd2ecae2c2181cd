# new_unstored: every load of Actual marks the value New, so an Import that
# found ReadLocked = Actual (nothing stored) reports New.  Must fail new_exact
# (formal/import/import.sby neg_new_unstored).
s/^\( *\)act_q <= act_byte\[2:0\];/&\n\1new_q <= 1'b1;/
