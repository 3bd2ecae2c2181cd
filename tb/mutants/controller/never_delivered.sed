# target: rtl/albatross_transfer_fsm.v
# Controller mutant: a published destination is never marked delivered, so
# every redundant slot publishes the same value again.
s/assign need_o      = (mid ? need_q : serve_q) \& ~pub_q;/assign need_o      = mid ? need_q : serve_q;/
