# formal/dpram/tests.mk -- the SymbiYosys tests of formal/dpram/dpram.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-dpram:dpram:prove:pass \
    formal-dpram-cover:dpram:cover:pass \
    formal-dpram-negative-priority_a:dpram:neg_priority_a:wb_b.props.ans_max_wait \
    formal-dpram-negative-no_arbitration:dpram:neg_no_arbitration:atomicity_a|atomicity_b \
    formal-dpram-negative-drop_ack:dpram:neg_drop_ack:wb_a.props.ans_max_wait
FSBY_MUTANTS += dpram:drop_ack:albatross_dpram_core.v
# the wrapper and its core (the mutant edits the core)
FSBY_RTL_dpram := rtl/albatross_dpram.v rtl/albatross_dpram_core.v
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-dpram proves (make formal-slow).
FSBY_SLOW_SPEC += formal-dpram-pdr:dpram:prove_pdr:pass
