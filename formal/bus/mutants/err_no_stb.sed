# err_no_stb: an absent board is remembered on cyc alone (no stb), so a
# request that follows a clock of cyc without stb is answered with err in its
# first clock, an answer to a clock that was no request.  Must fail
# absent_late (formal/bus/bus.sby neg_err_no_stb).
s/always @(posedge clk_i) answer_q <= {req \& none \& ~absent_err, sel_b/always @(posedge clk_i) answer_q <= {m_cyc_i \& none \& ~absent_err, sel_b/
