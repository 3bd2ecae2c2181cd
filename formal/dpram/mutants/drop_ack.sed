# drop_ack (rtl/albatross_dpram_core.v): port A never acks a write (its request waits forever).
# Must fail wb_a ans_max_wait (formal/dpram/dpram.sby neg_drop_ack).
s/a_ack_q <= a_go;/a_ack_q <= a_go \& ~a_we_i;/
