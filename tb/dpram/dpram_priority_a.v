// dpram_priority_a -- DELIBERATELY BROKEN dual-ported RAM, test fixture only.
//
// Same ports as rtl/albatross_dpram.v, but arbitrated like a lock: port A
// always wins, and after each of its accesses it keeps the array for two more
// cycles (as a port holding a semaphore would).  Port B is served only when
// A neither requests nor holds the array, so a busy port A blocks port B for
// an unbounded time.  Byte atomicity holds; the fixed access time does not.
// The testbench's negative test asserts that the access-time checker
// catches it.  Never use it in a design.
`default_nettype none

module dpram_priority_a #(
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
    reg [1:0]  hold_q;    // cycles port A still keeps the array
    reg        a_ack_q;
    reg        b_ack_q;
    reg [31:0] rdata_q;

    wire a_go = ~rst_i & a_cyc_i & a_stb_i & ~a_ack_q;
    wire b_go = ~rst_i & ~a_go & (hold_q == 2'd0) & b_cyc_i & b_stb_i & ~b_ack_q;

    wire [ADDR_WIDTH-1:0] adr   = a_go ? a_adr_i : b_adr_i;
    wire [31:0]           wdata = a_go ? a_dat_i : b_dat_i;
    wire [3:0]            wen   = a_go ? ({4{a_we_i}} & a_sel_i) : ({4{b_go & b_we_i}} & b_sel_i);

    always @(posedge clk_i) begin
        if (rst_i) begin
            hold_q  <= 2'd0;
            a_ack_q <= 1'b0;
            b_ack_q <= 1'b0;
        end else begin
            hold_q  <= a_go ? 2'd2 : (hold_q != 2'd0 ? hold_q - 2'd1 : 2'd0);
            a_ack_q <= a_go;
            b_ack_q <= b_go;
        end
    end

    always @(posedge clk_i) begin
        if (wen[0]) mem[adr][7:0]   <= wdata[7:0];
        if (wen[1]) mem[adr][15:8]  <= wdata[15:8];
        if (wen[2]) mem[adr][23:16] <= wdata[23:16];
        if (wen[3]) mem[adr][31:24] <= wdata[31:24];
        rdata_q <= mem[adr];
    end

    assign a_dat_o = rdata_q;
    assign b_dat_o = rdata_q;
    assign a_ack_o = a_ack_q;
    assign b_ack_o = b_ack_q;

endmodule

`default_nettype wire
