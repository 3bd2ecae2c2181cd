# sticky_answer: the answering board is never forgotten (answer_q only gains
# boards), so after a request to one board and then to another, the read data
# are both boards' words ORed.  Must fail route_answer (formal/bus/bus.sby neg_sticky_answer).
s/always @(posedge clk_i) answer_q <= {req \& none \& ~absent_err, sel_b \& {NB{req}}};/always @(posedge clk_i) answer_q <= answer_q | {req \& none \& ~absent_err, sel_b \& {NB{req}}};/
