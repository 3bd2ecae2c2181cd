# target: rtl/albatross_transfer_fsm.v
# forget_landed (tb/mutants/controller/forget_landed.sed on the datapath): the
# control-word load never recognises a landed Actual store.  Must fail dst_new_once.
s/    wire       landed   = ack \&\&/    wire       landed   = 1'b0 \&\& ack \&\&/
