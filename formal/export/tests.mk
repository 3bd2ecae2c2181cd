# formal/export/tests.mk -- the SymbiYosys tests of formal/export/export.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT).
FSBY_TESTS_SPEC += \
    formal-export:export:prove:pass \
    formal-export-t0:export:prove_t0:pass \
    formal-export-cover:export:cover:pass \
    formal-export-cover-t0:export:cover_t0:pass \
    formal-export-negative-early_publish:export:neg_early_publish:complete_publish \
    formal-export-negative-writes_locked:export:neg_writes_locked:no_locked_write \
    formal-export-negative-ignore_actual:export:neg_ignore_actual:no_actual_write \
    formal-export-negative-extra_access:export:neg_extra_access:exact_accesses \
    formal-export-negative-drop_total:export:neg_drop_total:retry_same|complete_export \
    formal-export-four-pdr:export:four_pdr:pass \
    formal-export-four-cover:export:four_cover:pass \
    formal-export-four-negative-ignore_rl4:export:four_neg_ignore_rl4:fs_other_pair|fs_pick|fs_no_write_read \
    formal-export-four-negative-same_slot4:export:four_neg_same_slot4:fs_pick|fs_slot_store|fs_no_write_read \
    formal-export-four-negative-actual_first4:export:four_neg_actual_first4:fs_actual_store \
    formal-export-four-negative-early_slot4:export:four_neg_early_slot4:fs_slot_store|fs_actual_store|fs_count \
    formal-export-four-negative-extra_load4:export:four_neg_extra_load4:fs_count|fs_ctrl_lanes
# The buffer pick is in albatross_export_dest.v: its mutants edit that file.
FSBY_MUTANTS += export:early_publish export:writes_locked:albatross_export_dest.v \
                export:ignore_actual:albatross_export_dest.v export:extra_access export:drop_total \
                export:ignore_rl4:albatross_export_dest.v export:same_slot4:albatross_export_dest.v \
                export:actual_first4 export:early_slot4 export:extra_load4
FSBY_RTL_export := rtl/albatross_export.v rtl/albatross_export_dest.v
# The same properties by abc pdr, without the k-induction's white-box probes:
# a second, independent proof of what formal-export proves (make formal-slow).
FSBY_SLOW_SPEC += formal-export-pdr:export:prove_pdr:pass
