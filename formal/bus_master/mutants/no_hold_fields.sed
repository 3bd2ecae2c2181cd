# no_hold_fields: the bus fields are always the owner's present ones, never the
# held ones: an owner that changes its address, we, sel or data in the middle
# of an access changes the slave's request.  Must fail req_stable of
# formal/wb/fwb_master.v (bus_master.sby neg_no_hold_fields).
s/wire \[FW-1:0\]       field = pend_q ? held_q : live;/wire [FW-1:0]       field = live;/
