# formal/axil/tests.mk -- the SymbiYosys tests of formal/axil/axil.sby
# (tools/mk/formal_sby.mk says the fields: NAME:CORE:TASK:EXPECT, CORE:VARIANT:FILE).
FSBY_TESTS_SPEC += \
    axil-formal:axil:prove:pass \
    axil-formal-cover:axil:cover:pass \
    axil-formal-negative-drop_wstrb_lane:axil:neg_drop_wstrb_lane:wr_fields|atomicity_a|atomicity_b \
    axil-formal-negative-late_start:axil:neg_late_start:axil_a.s_r_wait|axil_a.s_b_wait \
    axil-formal-negative-ready_ignores_full:axil:neg_ready_ignores_full:wr_fields|axil_a.s_max_out \
    axil-formal-negative-rdata_unheld:axil:neg_rdata_unheld:axil_a.s_r_stable|rd_data
FSBY_MUTANTS += axil:drop_wstrb_lane:albatross_axil2native.v axil:late_start:albatross_axil2native.v \
                axil:ready_ignores_full:albatross_axil2native.v axil:rdata_unheld:albatross_axil2native.v
# the wrapper, its front-end and its core
FSBY_RTL_axil := rtl/albatross_dpram_axil.v rtl/albatross_axil2native.v rtl/albatross_dpram_core.v
