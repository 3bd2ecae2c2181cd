# target: rtl/albatross_transfer_fsm.v
# Controller mutant (formal only): after the last value word, the Export stores
# Actual instead of the taken_at word, publishing a buffer one word short.
s/begin_access(S_DST_TKN, first_d);/begin_access(S_DST_FIN, first_d);/
