# formal/export/tests.mk -- the SymbiYosys tests of formal/export/export.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-export:export:prove:pass \
    formal-export-t0:export:prove_t0:pass \
    formal-export-pdr:export:prove_pdr:pass \
    formal-export-cover:export:cover:pass \
    formal-export-cover-t0:export:cover_t0:pass \
    formal-export-negative-early_publish:export:neg_early_publish:complete_publish \
    formal-export-negative-writes_locked:export:neg_writes_locked:no_locked_write \
    formal-export-negative-ignore_actual:export:neg_ignore_actual:no_actual_write \
    formal-export-negative-extra_access:export:neg_extra_access:exact_accesses
FSBY_MUTANTS += export:early_publish export:writes_locked export:ignore_actual export:extra_access
