# formal/import/tests.mk -- the SymbiYosys tests of formal/import/import.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-import:import:prove:pass \
    formal-import-push:import:prove_push:pass \
    formal-import-pdr:import:prove_pdr:pass \
    formal-import-cover:import:cover:pass \
    formal-import-negative-store_actual:import:neg_store_actual:store_rl_only \
    formal-import-negative-skip_confirm:import:neg_skip_confirm:load_not_written \
    formal-import-negative-new_unstored:import:neg_new_unstored:new_exact
FSBY_MUTANTS += import:store_actual import:skip_confirm import:new_unstored
