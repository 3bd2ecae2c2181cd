# formal/import/tests.mk -- the SymbiYosys tests of formal/import/import.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-import:import:prove:pass \
    formal-import-push:import:prove_push:pass \
    formal-import-cover:import:cover:pass \
    formal-import-negative-store_actual:import:neg_store_actual:store_rl_only \
    formal-import-negative-skip_confirm:import:neg_skip_confirm:load_not_written \
    formal-import-negative-new_unstored:import:neg_new_unstored:new_exact \
    formal-import-four-pdr:import:four_pdr:pass \
    formal-import-four-pdr-push:import:four_pdr_push:pass \
    formal-import-four-cover:import:four_cover:pass \
    formal-import-four-negative-idx_actual:import:four_neg_idx_actual:fs_load_chosen|fs_no_torn \
    formal-import-four-negative-wrong_slot:import:four_neg_wrong_slot:fs_fresh|fs_load_chosen|fs_no_torn \
    formal-import-four-negative-old_by_actual:import:four_neg_old_by_actual:fs_new_exact|fs_load_chosen \
    formal-import-four-negative-loop4:import:four_neg_loop4:fs_store_rl|fs_wait_free
FSBY_MUTANTS += import:store_actual import:skip_confirm import:new_unstored import:idx_actual import:wrong_slot \
                import:old_by_actual import:loop4
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-import proves (make formal-slow).
FSBY_SLOW_SPEC += formal-import-pdr:import:prove_pdr:pass
