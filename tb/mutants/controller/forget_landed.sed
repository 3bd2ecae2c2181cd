# target: rtl/albatross_transfer.v
# Controller mutant: the read-back of a destination's Actual after a failed
# store never recognises a store that landed (performed, answered with err or
# not at all): the value is written and published there again.
s/wire       landed   = read_act \&\&/wire       landed   = 1'b0 \&\& read_act \&\&/
