# drop_wstrb_lane (rtl/albatross_axil2native.v): WSTRB lane 0 never reaches the
# RAM (byte 0 of every AXI write is lost).  Must fail wr_fields
# (formal/axil/axil.sby neg_drop_wstrb_lane); tools/mk/axil.mk also runs the
# cocotb test against it (axil-cocotb-negative-drop_wstrb_lane).
s/assign n_be_o    = req_we_q ? w_strb_q : 4'h0;/assign n_be_o    = req_we_q ? {w_strb_q[3:1], 1'b0} : 4'h0;/
