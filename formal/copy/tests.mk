# formal/copy/tests.mk -- the SymbiYosys tests of formal/copy/copy.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT:FILE).
# The harness composes the rtl files below; the mutants edit the Export engine
# (writes_locked its buffer pick, in albatross_export_dest.v).
FSBY_RTL_copy := rtl/albatross_import.v rtl/albatross_export.v rtl/albatross_export_dest.v rtl/albatross_bus_master.v
# This harness composes the Import and Export engines through the bus master
# as the controller did before its single transfer datapath: the controller's
# own top is proved by formal/ctrl (make test), so these run with make
# formal-slow, beside the engines' own proofs (formal/import, formal/export).
FSBY_SLOW_SPEC += \
    formal-copy:copy:prove:pass \
    formal-copy-cover:copy:cover:pass \
    formal-copy-negative-early_publish:copy:neg_early_publish:publish_complete \
    formal-copy-negative-writes_locked:copy:neg_writes_locked:no_write_read
FSBY_MUTANTS += copy:early_publish:albatross_export.v copy:writes_locked:albatross_export_dest.v
