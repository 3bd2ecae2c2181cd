# tmo_late: the timeout comes one clock late (in the (TIMEOUT+1)-th clock of an
# access without an answer).  Must fail err_tmo (bus_master.sby neg_tmo_late).
s/localparam integer        TMO_LAST_I = TIMEOUT - 1;/localparam integer        TMO_LAST_I = TIMEOUT;/
