# formal/bus/tests.mk -- the SymbiYosys tests of formal/bus/bus.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-bus:bus:prove:pass \
    formal-bus-cover:bus:cover:pass \
    formal-bus-negative-err_no_stb:bus:neg_err_no_stb:absent_late \
    formal-bus-negative-alias:bus:neg_alias:ack_selected \
    formal-bus-negative-sticky_answer:bus:neg_sticky_answer:route_answer
FSBY_MUTANTS += bus:err_no_stb bus:alias bus:sticky_answer
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-bus proves (make formal-slow).
FSBY_SLOW_SPEC += formal-bus-pdr:bus:prove_pdr:pass
