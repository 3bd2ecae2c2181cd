# formal/mode_switch/tests.mk -- the SymbiYosys tests of formal/mode_switch/mode_switch.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-mode_switch:mode_switch:prove:pass \
    formal-mode_switch-cover:mode_switch:cover:pass \
    formal-mode_switch-negative-early:mode_switch:neg_early:base_at_boundary
FSBY_MUTANTS += mode_switch:early
