# late_start (rtl/albatross_axil2native.v): a request starts only once the
# native port is idle, not at the ack edge of the access before it: one clock
# lost, and the other port's slot then costs a second one.  Functionally right,
# but it breaks the response bound: must fail axil_a s_r_wait or s_b_wait
# (formal/axil/axil.sby neg_late_start).
s/wire n_free = ~req_q | n_ack_i; /wire n_free = ~req_q; /
