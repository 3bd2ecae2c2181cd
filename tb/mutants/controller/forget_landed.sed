# target: rtl/albatross_export_dest.v
# Controller mutant: the read-back of a destination's Actual after a failed
# store never recognises a store that landed (performed, answered with err or
# not at all): the value is written and published there again.
s/assign landed_o = read_act_i \&\&/assign landed_o = 1'b0 \&\& read_act_i \&\&/
