# target: rtl/albatross_controller.v
# Controller mutant: a published destination is never marked delivered, so
# every redundant slot publishes the same value again.
s/st_d\[38:35\] = need_q \& ~exp_published;/st_d[38:35] = need_q;/
