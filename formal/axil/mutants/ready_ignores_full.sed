# ready_ignores_full (rtl/albatross_axil2native.v): AWREADY always high, so an
# AW offered while one is held is handshaken and dropped (the write then goes to
# the earlier address).  Must fail wr_fields (the native write is not the
# accepted one) or axil_a s_max_out (formal/axil/axil.sby neg_ready_ignores_full).
s/assign s_axi_awready_o = ~aw_full_q;/assign s_axi_awready_o = 1'b1;/
