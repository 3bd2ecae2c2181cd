# live_adr: the RAM-side address changes mid-request (its lowest bit flips in
# the clock in which the RAM acks).
# Must fail wb_m req_stable (formal/wb_cdc/wb_cdc.sby neg_live_adr).
s/assign m_adr_o = m_adr_q;/assign m_adr_o = m_adr_q ^ {{(ADDR_WIDTH-1){1'b0}}, m_ack_i};/
