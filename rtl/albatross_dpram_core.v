// albatross_dpram_core -- byte-arbitrated dual-ported RAM, native ports
// (ALBATROSS, the paper, section 3.1; docs/rtl.md "albatross_dpram_core").
//
// The bus-independent heart of the DPRAM, the PicoRV32 way: this core has a
// simple request/acknowledge port per side; the bus front-ends are thin
// wrappers around it (albatross_dpram: Wishbone B4 classic on both ports;
// albatross_dpram_axil: AXI4-Lite on port A).  Two ports, A and B, share one
// single-ported memory array.  Arbitration is a fixed time division, not a lock:
//   * Native port protocol (each side): the requester raises req_i with we_i,
//     adr_i (word address), be_i (byte enables, lane 0 = bits 7:0 = lowest
//     byte address) and wdata_i, and holds all of them stable until ack_o.
//     ack_o is high for exactly one clock; rdata_o holds the read word in that
//     clock.  req_i may stay high in the ack clock for a next access (it is
//     not taken in that clock) or drop; it must not drop before its ack.
//   * The array performs exactly one access per clock.  Cycles alternate
//     between the ports: slot_q == 0 belongs to port A, slot_q == 1 to B.
//   * A request is performed at the first rising edge that falls in the
//     port's own slot; ack is high for exactly the one cycle after that edge,
//     with the read data.  Access time, req to ack, is 1 or 2 cycles whatever
//     the other port does (the fixed access bound): neither port ever waits
//     for the other, and each may issue one access every 2 cycles.
//   * Byte atomicity: every byte is only ever touched by one whole access of
//     one port at a time, so a read returns the complete old or the complete
//     new byte, and two writes to one byte leave the complete later value.
//     Requests presented in the same cycle take effect in slot order.
//   * Writes honour the byte enables; reads return the whole word.
//   * The array is a plain single-port RAM with byte enables, so it infers
//     block RAM on every FPGA family (iCE40 SB_RAM40_4K, ECP5 DP16KD, Xilinx
//     RAMB) and never relies on a RAM primitive's cross-port collision
//     behaviour.  Reset clears the slot and the acks, never the array.
`default_nettype none

module albatross_dpram_core #(
    parameter ADDR_WIDTH = 10, // word-address bits: 2**ADDR_WIDTH words of 32 bits
    parameter INIT_FILE  = ""  // $readmemh image loaded at configuration ("": none)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,       // synchronous, active high
    // port A: native request/acknowledge
    input  wire                  a_req_i,
    input  wire                  a_we_i,
    input  wire [ADDR_WIDTH-1:0] a_adr_i,
    input  wire [3:0]            a_be_i,
    input  wire [31:0]           a_wdata_i,
    output wire [31:0]           a_rdata_o,
    output wire                  a_ack_o,
    // port B: native request/acknowledge
    input  wire                  b_req_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_be_i,
    input  wire [31:0]           b_wdata_i,
    output wire [31:0]           b_rdata_o,
    output wire                  b_ack_o
);

    reg [31:0] mem [0:(1<<ADDR_WIDTH)-1];
    initial if (INIT_FILE != "") $readmemh(INIT_FILE, mem);  // block-RAM contents, no reset
    reg        slot_q;   // whose cycle this is: 0 = port A, 1 = port B
    reg        a_ack_q;
    reg        b_ack_q;
    reg [31:0] rdata_q;

    // A port goes when it requests in its own slot (never on its ack cycle).
    wire a_go = ~rst_i & ~slot_q & a_req_i & ~a_ack_q;
    wire b_go = ~rst_i &  slot_q & b_req_i & ~b_ack_q;

    // The one access of this cycle: the slot owner's.
    wire [ADDR_WIDTH-1:0] adr   = slot_q ? b_adr_i : a_adr_i;
    wire [31:0]           wdata = slot_q ? b_wdata_i : a_wdata_i;
    wire [3:0]            wen   = slot_q ? ({4{b_go & b_we_i}} & b_be_i)
                                         : ({4{a_go & a_we_i}} & a_be_i);

    always @(posedge clk_i) begin
        if (rst_i) begin
            slot_q  <= 1'b0;
            a_ack_q <= 1'b0;
            b_ack_q <= 1'b0;
        end else begin
            slot_q  <= ~slot_q;
            a_ack_q <= a_go;
            b_ack_q <= b_go;
        end
    end

    // Memory array: one read/write port with byte enables, never reset.  It
    // reads only when it does not write, so no RAM primitive ever sees a
    // read and a write of one address at one edge (no read-first emulation).
    always @(posedge clk_i) begin
        if (wen[0]) mem[adr][7:0]   <= wdata[7:0];
        if (wen[1]) mem[adr][15:8]  <= wdata[15:8];
        if (wen[2]) mem[adr][23:16] <= wdata[23:16];
        if (wen[3]) mem[adr][31:24] <= wdata[31:24];
        if (~|wen) rdata_q <= mem[adr];
    end

    // Read data is valid while the port's ack is high after a read (after a
    // write ack it holds the last read).
    assign a_rdata_o = rdata_q;
    assign b_rdata_o = rdata_q;
    assign a_ack_o   = a_ack_q;
    assign b_ack_o   = b_ack_q;

endmodule

`default_nettype wire
