// albatross_dpram -- byte-arbitrated dual-ported RAM, Wishbone B4 classic on
// both ports (ALBATROSS, the paper, section 3.1; docs/rtl.md "albatross_dpram").
//
// A thin wrapper: the RAM, its arbitration and its timing are those of the
// native core albatross_dpram_core (whose header states the rules); this file
// only maps each Wishbone B4 classic slave port onto a native port
// (req = cyc & stb, sel = byte enables, ack and dat_o straight through), so
// every rule holds here unchanged, clock for clock:
//   * The array performs one access per clock; cycles alternate between the
//     ports (fixed time division, not a lock).  A request is performed at the
//     first rising edge in its port's own slot; ack is high for exactly the one
//     cycle after that edge.  Access time, stb to ack, is 1 or 2 cycles
//     whatever the other port does; each port may issue one access every 2
//     cycles.
//   * Byte atomicity: a read returns the complete old or the complete new
//     byte; two writes to one byte leave the complete later value.  Requests
//     presented in the same cycle take effect in slot order.
//   * Writes honour sel byte lanes (lane 0 = bits 7:0 = lowest byte address);
//     adr is a word address.  Reads return the whole word.  Reset clears the
//     slot and the acks, never the array.
`default_nettype none

module albatross_dpram #(
    parameter ADDR_WIDTH = 10, // word-address bits: 2**ADDR_WIDTH words of 32 bits
    parameter INIT_FILE  = ""  // $readmemh image loaded at configuration ("": none)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,     // synchronous, active high
    // port A: Wishbone B4 classic slave
    input  wire                  a_cyc_i,
    input  wire                  a_stb_i,
    input  wire                  a_we_i,
    input  wire [ADDR_WIDTH-1:0] a_adr_i,
    input  wire [3:0]            a_sel_i,
    input  wire [31:0]           a_dat_i,
    output wire [31:0]           a_dat_o,
    output wire                  a_ack_o,
    // port B: Wishbone B4 classic slave
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i,
    output wire [31:0]           b_dat_o,
    output wire                  b_ack_o
);

    albatross_dpram_core #(
        .ADDR_WIDTH(ADDR_WIDTH),
        .INIT_FILE (INIT_FILE)
    ) u_core (
        .clk_i(clk_i), .rst_i(rst_i),
        .a_req_i(a_cyc_i & a_stb_i), .a_we_i(a_we_i), .a_adr_i(a_adr_i), .a_be_i(a_sel_i),
        .a_wdata_i(a_dat_i), .a_rdata_o(a_dat_o), .a_ack_o(a_ack_o),
        .b_req_i(b_cyc_i & b_stb_i), .b_we_i(b_we_i), .b_adr_i(b_adr_i), .b_be_i(b_sel_i),
        .b_wdata_i(b_dat_i), .b_rdata_o(b_dat_o), .b_ack_o(b_ack_o)
    );

endmodule

`default_nettype wire
