# extra_access: the first destination's Actual is read back even when its copy
# is known: one access more than ND * (W + TAKEN_AT + 2) + unknown copies.
# Must fail exact_accesses.
s/else begin_access(known_in || four_i ? S_LOAD_RL : S_LOAD_ACTUAL, first_in);/else begin_access(S_LOAD_ACTUAL, first_in);/
