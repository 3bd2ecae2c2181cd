// board_reset -- reset for an FPGA board top: a synchronous, active-high
// reset that is held for 2**POR_BITS clocks after configuration (power-on)
// and while the board's reset button is pressed.  The button (active low,
// asynchronous) passes through a two-flop synchroniser; release is
// synchronous to clk_i.  The registers start from their configuration
// values (FPGA flip-flops load them), the one place in the design where
// state is not reset by rst.
`default_nettype none

module board_reset #(
    parameter POR_BITS = 4   // power-on reset lasts 2**POR_BITS clocks
) (
    input  wire clk_i,
    input  wire btn_n_i,     // reset button, active low, asynchronous
    output wire rst_o        // synchronous reset, active high
);

    reg [1:0]          sync_q = 2'b00;  // button synchroniser (1 = released)
    reg [POR_BITS-1:0] por_q  = {POR_BITS{1'b0}};
    reg                rst_q  = 1'b1;

    always @(posedge clk_i) begin
        sync_q <= {sync_q[0], btn_n_i};
        if (!sync_q[1]) por_q <= {POR_BITS{1'b0}};
        else if (!(&por_q)) por_q <= por_q + 1'b1;
        rst_q <= !(&por_q);
    end

    assign rst_o = rst_q;

endmodule

`default_nettype wire
