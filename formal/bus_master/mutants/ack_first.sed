# ack_first: ack goes to the lowest-indexed requester with cyc instead of the
# owner: when a lower-indexed requester waits behind the owner, it sees the
# owner's ack.  Must fail own_silent (bus_master.sby neg_ack_first).
s/assign r_ack_o   = {{(REQS-1){1'b0}}, ack} << owner;/assign r_ack_o   = {{(REQS-1){1'b0}}, ack} << first;/
