# target: rtl/albatross_transfer.v
# extra_access (formal/export/mutants/extra_access.sed on the datapath): the
# first destination's Actual is read back although its copy is known.  Must
# fail dst_readback_needed.
s/begin_access((st_known\[first_in\] || four_i) ? S_DST_RL : S_DST_ACT, first_in);/begin_access(four_i ? S_DST_RL : S_DST_ACT, first_in);/
