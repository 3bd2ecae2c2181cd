# target: rtl/albatross_transfer_fsm.v
# old_same_pair3 (tb/mutants/controller/old_same_pair3.sed): the three-buffer source
# Import's first load answers Old whenever Actual lies in the pair of its copy
# (Buffer1 and Buffer2, or Buffer3), whatever the buffer; the confirming
# loads still compare the buffer.  Must fail src_fresh.
s/\.a_match_o(a_match)/.a_match_o(a_match_p)/
s/^    albatross_transfer_pick u_pick (/    wire       a_match_p;\n    assign a_match = a_match_p || (!four_i \&\& !new_q \&\& rl_q != 3'd0 \&\& (a_byte[2] | (a_byte[1] \& a_byte[0])) == (rl_q[2] | (rl_q[1] \& rl_q[0])));\n    albatross_transfer_pick u_pick (/
