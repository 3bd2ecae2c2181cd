# actual_first4: the four-slot Export stores Actual before the slot byte.
# Must fail fs_actual_store (export.sby four_neg_actual_first4).
s/    wire \[2:0\] after_data = four_q ? S_STORE_SLOT : S_STORE_ACTUAL;/    wire [2:0] after_data = S_STORE_ACTUAL;/
s/^\( *\)else if (state_q == S_STORE_SLOT) begin_access(S_STORE_ACTUAL, first_d);/\1else if (state_q == S_STORE_ACTUAL \&\& four_q) begin_access(S_STORE_SLOT, first_d);\n\1else if (state_q == S_STORE_SLOT) begin stb_q <= 1'b0; state_q <= S_IDLE; done_q <= 1'b1; end/
