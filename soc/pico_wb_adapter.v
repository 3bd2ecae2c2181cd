// pico_wb_adapter -- PicoRV32 native memory interface to a Wishbone B4
// classic master port, for one port of albatross_dpram.
//
// Purely combinational.  The caller decodes the address: valid_i is the
// core's mem_valid for accesses that belong to this port.  cyc = stb = valid_i,
// held until ack; the core drops mem_valid in the cycle after mem_ready, so
// every request is performed exactly once.  mem_wstrb != 0 is a write whose
// byte lanes are the Wishbone sel (lane 0 = bits 7:0 = lowest address); a
// read selects all four lanes.  addr_i is the byte address within the window:
// bits 1:0 are dropped, the word address goes out on wb_adr_o.
`default_nettype none

module pico_wb_adapter #(
    parameter ADDR_WIDTH = 10  // word-address bits of the Wishbone slave
) (
    // PicoRV32 side
    input  wire                  valid_i,   // mem_valid, already decoded
    input  wire [ADDR_WIDTH+1:0] addr_i,    // byte address in the window
    input  wire [31:0]           wdata_i,
    input  wire [3:0]            wstrb_i,
    output wire                  ready_o,
    output wire [31:0]           rdata_o,
    // Wishbone master side
    output wire                  wb_cyc_o,
    output wire                  wb_stb_o,
    output wire                  wb_we_o,
    output wire [ADDR_WIDTH-1:0] wb_adr_o,
    output wire [3:0]            wb_sel_o,
    output wire [31:0]           wb_dat_o,
    input  wire [31:0]           wb_dat_i,
    input  wire                  wb_ack_i
);

    assign wb_cyc_o = valid_i;
    assign wb_stb_o = valid_i;
    assign wb_we_o  = |wstrb_i;
    assign wb_adr_o = addr_i[ADDR_WIDTH+1:2];
    assign wb_sel_o = (|wstrb_i) ? wstrb_i : 4'hf;
    assign wb_dat_o = wdata_i;
    assign ready_o  = wb_ack_i;
    assign rdata_o  = wb_dat_i;

    // Byte offset within the word: carried by the byte lanes instead.
    wire unused_byte_offset = &{1'b0, addr_i[1:0]};

endmodule
