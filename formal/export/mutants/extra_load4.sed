# extra_load4: the four-slot Export reads Actual back first when its copy is
# unknown, as the three-buffer kind does (one access more than W + 4).
# Must fail fs_count or fs_ctrl_lanes (export.sby four_neg_extra_load4).
s/else begin_access(known_in || four_i ? S_LOAD_RL : S_LOAD_ACTUAL, first_in);/else begin_access(known_in ? S_LOAD_RL : S_LOAD_ACTUAL, first_in);/
