# formal/bus_master/tests.mk -- the SymbiYosys tests of formal/bus_master/bus_master.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-bus_master:bus_master:prove:pass \
    formal-bus_master-pdr-reqs2:bus_master:prove_pdr_reqs2:pass \
    formal-bus_master-cover:bus_master:cover:pass \
    formal-bus_master-negative-no_gap:bus_master:neg_no_gap:fail_gap \
    formal-bus_master-negative-tmo_early:bus_master:neg_tmo_early:err_tmo \
    formal-bus_master-negative-ack_first:bus_master:neg_ack_first:own_silent \
    formal-bus_master-negative-board_first:bus_master:neg_board_first:adr_owner \
    formal-bus_master-negative-no_hold:bus_master:neg_no_hold:own_fields \
    formal-bus_master-negative-no_abort:bus_master:neg_no_abort:pass_now \
    formal-bus_master-negative-no_hold_fields:bus_master:neg_no_hold_fields:req_stable \
    formal-bus_master-negative-no_reset_gap:bus_master:neg_no_reset_gap:req_reset
# A second mutant of a property that a negative above already breaks runs
# with make test-slow.
FSBY_SLOW_SPEC += \
    formal-bus_master-negative-tmo_late:bus_master:neg_tmo_late:err_tmo \
    formal-bus_master-negative-drop_raise:bus_master:neg_drop_raise:req_stable
FSBY_MUTANTS += bus_master:no_gap bus_master:tmo_late bus_master:tmo_early \
                bus_master:ack_first bus_master:board_first bus_master:no_hold \
                bus_master:drop_raise bus_master:no_abort bus_master:no_hold_fields \
                bus_master:no_reset_gap
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-bus_master proves (make formal-slow).
FSBY_SLOW_SPEC += formal-bus_master-pdr:bus_master:prove_pdr:pass
