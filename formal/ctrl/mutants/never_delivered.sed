# target: rtl/albatross_transfer_fsm.v
# never_delivered (tb/mutants/controller/never_delivered.sed on the datapath):
# a published destination stays in need.  Must fail dst_new_once.
s/    assign need_o      = (mid ? need_q : serve_q) \& ~pub_q;/    assign need_o      = (mid ? need_q : serve_q);/
