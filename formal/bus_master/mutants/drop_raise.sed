# drop_raise: the bus master as it was before accesses were held: a pending
# access does not keep its owner (the owner rule ignores pend_q) and the bus
# fields are always the present owner's (never the held ones).  A requester
# that drops cyc in the clock in which another raises it hands the bus over
# with cyc and stb staying high while adr, we and sel change with no answer in
# between: a slave that had already performed the first access would ack it
# and the second one would be reported done without being performed.
# Must fail req_stable of formal/wb/fwb_master.v (bus_master.sby neg_drop_raise).
s/wire \[OWN_BITS-1:0\] owner = (pend_q || (busy_q \&\& r_cyc_i\[owner_q\])) ? owner_q : first;/wire [OWN_BITS-1:0] owner = (busy_q \&\& r_cyc_i[owner_q]) ? owner_q : first;/
s/wire \[FW-1:0\]       field = (HOLD_FIELDS != 0 \&\& pend_q) ? held_q : live;/wire [FW-1:0]       field = live;/
