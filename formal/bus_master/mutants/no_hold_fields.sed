# no_hold_fields: the bus fields are always the owner's present ones, never the
# held ones: an owner that changes its address, we, sel or data in the middle
# of an access changes the slave's request (HOLD_FIELDS 1, the defaults; with
# HOLD_FIELDS 0 this is the rule).  Must fail req_stable of
# formal/wb/fwb_master.v (bus_master.sby neg_no_hold_fields).
s/wire \[FW-1:0\]       field = (HOLD_FIELDS != 0 \&\& pend_q) ? held_q : live;/wire [FW-1:0]       field = live;/
