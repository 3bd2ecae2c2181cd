# rdata_unheld (rtl/albatross_axil2native.v): the read register follows the
# RAM every clock, so RDATA changes while RVALID waits for RREADY.  Must fail
# axil_a s_r_stable or rd_data (formal/axil/axil.sby neg_rdata_unheld).
s/if (done \& ~req_we_q) rdata_q <= n_rdata_i;/rdata_q <= n_rdata_i;/
