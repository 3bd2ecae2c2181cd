# formal/wb_cdc/tests.mk -- the SymbiYosys tests of formal/wb_cdc/wb_cdc.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-wb_cdc-pdr:wb_cdc:prove_pdr:pass \
    formal-wb_cdc-cover:wb_cdc:cover:pass \
    formal-wb_cdc-negative-live_adr:wb_cdc:neg_live_adr:wb_m.req_stable \
    formal-wb_cdc-negative-early_ack:wb_cdc:neg_early_ack:ack_match
FSBY_SLOW_SPEC += formal-wb_cdc-pdr-full:wb_cdc:prove_pdr_full:pass
FSBY_MUTANTS += wb_cdc:live_adr wb_cdc:early_ack
