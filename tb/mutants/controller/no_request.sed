# target: rtl/albatross_transfer_fsm.v
# Controller mutant: the transfer never offers a REQUEST entry's value as a
# mode request (mode_req_o stays low), so no mode switch ever happens.
# Scenario modes must fail (test-controller-negative-no_request).
s/assign mode_req_o      = nrm \&\& ack \&\& state_q == S_SRC_WORD \&\& request_i \&\& !early_q;/assign mode_req_o      = 1'b0;/
