# target: rtl/albatross_transfer.v
# extra_load4 (formal/export/mutants/extra_load4.sed on the datapath): the
# four-slot Export reads Actual back first when its copy is unknown, as the
# three-buffer kind does.  Must fail dst_one_load.
s/begin_access((st_known\[first_in\] || four_i) ? S_DST_RL : S_DST_ACT, first_in);/begin_access(st_known[first_in] ? S_DST_RL : S_DST_ACT, first_in);/
s/((known_q\[next_d\] || four_i) ? S_DST_RL : S_DST_ACT)/(known_q[next_d] ? S_DST_RL : S_DST_ACT)/
