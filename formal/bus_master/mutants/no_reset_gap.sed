# no_reset_gap: cyc is not held low in the clock after a reset clock, so a
# requester raising cyc then reaches the bus at once.  Must fail req_reset of
# formal/wb/fwb_master.v (bus_master.sby neg_no_reset_gap).
s/            gap_q     <= 1'b1;   \/\/ cyc stays low in the clock after reset/            gap_q     <= 1'b0;/
