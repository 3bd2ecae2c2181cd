# err_no_stb: an absent board is answered with err on cyc alone (no stb): an
# answer without a request.  Must fail wb_m ans_in_req (formal/bus/bus.sby neg_err_no_stb).
s/assign m_err_o = |(s_err_i \& answer_q) | (req \& none);/assign m_err_o = |(s_err_i \& answer_q) | (m_cyc_i \& none);/
