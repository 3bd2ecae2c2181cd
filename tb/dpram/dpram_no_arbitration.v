// dpram_no_arbitration -- DELIBERATELY BROKEN dual-ported RAM, test fixture only.
//
// Same ports and timing as rtl/albatross_dpram.v, but both ports access the
// array at every edge with no arbitration, as a true dual-port block RAM with
// independent ports would.  It models the undefined cross-port collision of
// real block RAM: a read of a byte that the other port writes at the same edge
// returns a torn byte (even bits old, odd bits new), and two writes to one byte
// at the same edge leave a mix of both.  The testbench's negative tests assert
// that the checkers catch the result.  Never use it in a design.
`default_nettype none

module dpram_no_arbitration #(
    parameter ADDR_WIDTH = 10  // word-address bits: 2**ADDR_WIDTH words of 32 bits
) (
    input  wire                  clk_i,
    input  wire                  rst_i,     // synchronous, active high
    input  wire                  a_cyc_i,
    input  wire                  a_stb_i,
    input  wire                  a_we_i,
    input  wire [ADDR_WIDTH-1:0] a_adr_i,
    input  wire [3:0]            a_sel_i,
    input  wire [31:0]           a_dat_i,
    output wire [31:0]           a_dat_o,
    output wire                  a_ack_o,
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i,
    output wire [31:0]           b_dat_o,
    output wire                  b_ack_o
);

    reg [31:0] mem [0:(1<<ADDR_WIDTH)-1];
    reg        a_ack_q;
    reg        b_ack_q;
    reg [31:0] a_rdata_q;
    reg [31:0] b_rdata_q;

    wire a_go = ~rst_i & a_cyc_i & a_stb_i & ~a_ack_q;
    wire b_go = ~rst_i & b_cyc_i & b_stb_i & ~b_ack_q;
    wire [3:0] a_wen = {4{a_go & a_we_i}} & a_sel_i;
    wire [3:0] b_wen = {4{b_go & b_we_i}} & b_sel_i;
    wire       same  = a_adr_i == b_adr_i;

    // Per byte lane: what the lane holds after this edge, and what a reader of
    // the lane sees when the other port writes it at the same edge.
    reg  [31:0] next_word;
    reg  [31:0] a_seen;
    reg  [31:0] b_seen;
    integer i;
    always @* begin
        next_word = mem[a_adr_i];
        a_seen    = mem[a_adr_i];
        b_seen    = mem[b_adr_i];
        for (i = 0; i < 4; i = i + 1) begin
            if (a_wen[i] && same && b_wen[i])
                next_word[8*i +: 8] = (a_dat_i[8*i +: 8] & 8'h55) | (b_dat_i[8*i +: 8] & 8'hAA);
            else if (a_wen[i])
                next_word[8*i +: 8] = a_dat_i[8*i +: 8];
            if (same && b_wen[i])
                a_seen[8*i +: 8] = (mem[a_adr_i][8*i +: 8] & 8'h55) | (b_dat_i[8*i +: 8] & 8'hAA);
            if (same && a_wen[i])
                b_seen[8*i +: 8] = (mem[b_adr_i][8*i +: 8] & 8'h55) | (a_dat_i[8*i +: 8] & 8'hAA);
        end
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            a_ack_q <= 1'b0;
            b_ack_q <= 1'b0;
        end else begin
            a_ack_q <= a_go;
            b_ack_q <= b_go;
        end
    end

    always @(posedge clk_i) begin
        if (|a_wen) mem[a_adr_i] <= next_word;
        if (|b_wen && !(same && |a_wen)) mem[b_adr_i] <= (mem[b_adr_i] & ~lanes(b_wen)) | (b_dat_i & lanes(b_wen));
        if (|b_wen && same && |a_wen) mem[b_adr_i] <= (next_word & ~lanes(b_wen & ~a_wen)) | (b_dat_i & lanes(b_wen & ~a_wen));
        a_rdata_q <= a_seen;
        b_rdata_q <= b_seen;
    end

    function [31:0] lanes(input [3:0] sel);
        lanes = {{8{sel[3]}}, {8{sel[2]}}, {8{sel[1]}}, {8{sel[0]}}};
    endfunction

    assign a_dat_o = a_rdata_q;
    assign b_dat_o = b_rdata_q;
    assign a_ack_o = a_ack_q;
    assign b_ack_o = b_ack_q;

endmodule

`default_nettype wire
