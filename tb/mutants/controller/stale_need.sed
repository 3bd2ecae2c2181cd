# target: rtl/albatross_controller.v
# Controller mutant: the state-RAM write-back regression that 7e46d73 fixed.  At
# a slot's end the abandoned count takes the transfer datapath's need (the
# destinations it served without those it published) even when no Export ran,
# so a COPY whose Import ended without choosing counts what the datapath holds
# (with the single datapath: every destination of the entry) instead of the
# channel's own stored need.  Caught by test_controller's cold scenario (a zero
# source Actual ends the Import with no choice; nothing may count as abandoned):
# make test-controller-negative-stale_need.
s/wire \[3:0\] need_end = tr_exp ? tr_aband : st_need;/wire [3:0] need_end = tr_aband;/
