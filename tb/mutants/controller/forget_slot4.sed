# target: rtl/albatross_transfer_fsm.v
# Controller mutant: the four-slot Export's control-word load never
# recognises a landed Slot store whose Actual store was not made (the value
# complete, unpublished), and picks a buffer as for a new value: the next
# slot writes the same value into another buffer, completes and publishes it
# again, so its consumer may read it New twice.  Caught by the system test's
# duplicate-publication check (test-system-negative-four-slot-late-publish)
# and by the controller-top proof's dst_new_once
# (test-formal-ctrl-negative-forget_slot4).
s/    wire       complete = ack \&\& ctrl_ld \&\& t_done \&\& !t_act;/    wire       complete = 1'b0 \&\& ack \&\& ctrl_ld \&\& t_done \&\& !t_act;/
s/    wire       e_pick   = nrm \&\& ack \&\& ctrl_ld \&\& !t_done;/    wire       e_pick   = nrm \&\& ack \&\& ctrl_ld;/
