// beat_divider -- a heartbeat a person can see on a fast board.  The output
// changes once every 2**LOG2 changes of the input (LOG2 = 0: every change,
// one clock late).  The input is a board's heartbeat bit from the same clock
// domain; the firmware flips it every 256 Exports or New Imports, which is a
// visible blink at 12 MHz but a glow at 25 or 100 MHz.  Reset (synchronous,
// active high) clears the count.
`default_nettype none

module beat_divider #(
    parameter LOG2 = 5   // the output changes every 2**LOG2 input changes, 0..15
) (
    input  wire clk_i,
    input  wire rst_i,   // synchronous, active high
    input  wire beat_i,  // heartbeat bit
    output wire beat_o   // divided heartbeat
);

    reg          prev_q;  // beat_i a clock ago
    reg [LOG2:0] cnt_q;   // changes of beat_i seen

    always @(posedge clk_i) begin
        if (rst_i) begin
            prev_q <= 1'b0;
            cnt_q  <= {(LOG2 + 1){1'b0}};
        end else begin
            prev_q <= beat_i;
            if (beat_i != prev_q) cnt_q <= cnt_q + {{LOG2{1'b0}}, 1'b1};
        end
    end

    assign beat_o = cnt_q[LOG2];

endmodule

`default_nettype wire
