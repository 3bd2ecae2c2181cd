# target: rtl/albatross_transfer_fsm.v
# Controller mutant: the control-word load after a failed Actual store never
# recognises a store that landed (performed, answered with err or not at
# all): the value is written and published there again.
s/wire       landed   = ack \&\&/wire       landed   = 1'b0 \&\& ack \&\&/
