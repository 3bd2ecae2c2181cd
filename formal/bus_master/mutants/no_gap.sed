# no_gap: a failure does not drop cyc for the next clock (the retry follows at
# once, so the slave cannot tell it from the failed access).
# Must fail fail_gap (formal/bus_master/bus_master.sby neg_no_gap).
s/            gap_q   <= fail;/            gap_q   <= 1'b0;/
