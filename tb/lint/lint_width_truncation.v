// lint_width_truncation -- DELIBERATELY BAD Verilog, test fixture only: a
// 4-bit sum silently truncated to 2 bits.  The lint negative test asserts
// that tools/lint.sh rejects it (Verilator -Wall: WIDTH), proving lint
// warnings fail the build.  Not part of the RTL.
`default_nettype none

module lint_width_truncation (
    input  wire       clk_i,
    input  wire [3:0] a_i,
    output reg  [1:0] q_o
);
    always @(posedge clk_i) q_o <= a_i + 4'd1;
endmodule

`default_nettype wire
