# target: rtl/albatross_transfer_fsm.v
# publish_early (formal/rtl/mutants/publish_early.sed on the datapath): after
# the last value word, Actual is stored instead of taken_at.  Must fail
# dst_publish_complete.
s/begin_access(S_DST_TKN, first_d);/begin_access(S_DST_FIN, first_d);/
