# no_abort: a pending access does not keep its owner (the owner rule ignores
# pend_q) although its fields are still held: when the owner drops cyc and
# another requester raises it in the same clock, cyc stays high and the new
# requester is answered for the old owner's access.  Must fail pass_now
# (bus_master.sby neg_no_abort).
s/wire \[OWN_BITS-1:0\] owner = (pend_q || (busy_q \&\& r_cyc_i\[owner_q\])) ? owner_q : first;/wire [OWN_BITS-1:0] owner = (busy_q \&\& r_cyc_i[owner_q]) ? owner_q : first;/
