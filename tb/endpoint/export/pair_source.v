// pair_source -- test-only RTL producer for tb/endpoint/export: publishes the
// pair test's values (soc/firmware/board.h: seq, mix(seq), mix(mix(seq)),
// seq ^ h1 ^ h2 ^ 0x5A5A5A5A) with seq = 1..VALUES through an
// albatross_export_endpoint, a new value as often as the endpoint takes one.
// stall_i (from the harness) holds it: no new value is offered and no word
// is valid while it is high, so Exports start and take their words in many
// phases.  Rules: publish_o is high in a clock where busy_i is low, stall_i
// is low and values remain; the value taken at that edge is seq_o + 1.  The
// words follow word_index_i (word_i = value[word_index_i]).
`default_nettype none

module pair_source #(
    parameter VALUES = 1000  // values to publish: seq 1..VALUES
) (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        stall_i,        // hold: offer nothing this clock
    input  wire        busy_i,         // the endpoint's busy_o
    output wire        publish_o,      // to the endpoint's publish_i
    output wire [31:0] word_o,
    output wire        word_valid_o,
    input  wire [15:0] word_index_i,
    output wire [31:0] seq_o,          // the value being (or last) published
    output wire        finished_o      // seq VALUES was taken
);

    localparam [31:0] SALT = 32'h5A5A5A5A;

    function [31:0] mix;               // pair_mix of board.h
        input [31:0] x0;
        reg   [31:0] x;
        begin
            x   = x0 ^ (x0 << 13);
            x   = x ^ (x >> 17);
            x   = x ^ (x << 5);
            mix = x + 32'h9E3779B9;
        end
    endfunction

    reg [31:0] seq_q;                  // the value taken last (0: none yet)
    wire       more = seq_q != VALUES;

    assign publish_o    = !busy_i && !stall_i && more && !rst_i;
    always @(posedge clk_i) begin
        if (rst_i) seq_q <= 32'd0;
        else if (publish_o) seq_q <= seq_q + 32'd1;
    end

    wire [31:0] h1 = mix(seq_q);
    wire [31:0] h2 = mix(h1);
    assign word_o       = word_index_i == 16'd0 ? seq_q : word_index_i == 16'd1 ? h1 :
                          word_index_i == 16'd2 ? h2 : (seq_q ^ h1 ^ h2 ^ SALT);
    assign word_valid_o = !stall_i;
    assign seq_o        = seq_q;
    assign finished_o   = !more;

endmodule

`default_nettype wire
