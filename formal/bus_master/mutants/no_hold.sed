# no_hold: no ownership: the lowest-indexed requester with cyc always takes the
# bus, even from an owner in the middle of its access.  Must fail own_fields
# (bus_master.sby neg_no_hold).
s/wire \[OWN_BITS-1:0\] owner = (pend_q || (busy_q \&\& r_cyc_i\[owner_q\])) ? owner_q : first;/wire [OWN_BITS-1:0] owner = first;/
