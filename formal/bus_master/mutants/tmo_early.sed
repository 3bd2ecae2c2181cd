# tmo_early: the timeout comes one clock early (in the (TIMEOUT-1)-th clock).
# Must fail err_tmo (bus_master.sby neg_tmo_early).
s/localparam integer        TMO_LAST_I = TIMEOUT - 1;/localparam integer        TMO_LAST_I = TIMEOUT - 2;/
