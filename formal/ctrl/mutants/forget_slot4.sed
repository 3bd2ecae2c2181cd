# target: rtl/albatross_transfer_fsm.v
# forget_slot4 (tb/mutants/controller/forget_slot4.sed on the datapath): the
# four-slot control-word load never recognises a landed Slot store whose
# Actual store was not made, and picks a buffer as for a new value: the next
# slot completes the same value a second time.  Must fail dst_new_once.
s/    wire       complete = ack \&\& ctrl_ld \&\& t_done \&\& !t_act;/    wire       complete = 1'b0 \&\& ack \&\& ctrl_ld \&\& t_done \&\& !t_act;/
s/    wire       e_pick   = nrm \&\& ack \&\& ctrl_ld \&\& !t_done;/    wire       e_pick   = nrm \&\& ack \&\& ctrl_ld;/
