// serv_bridge -- board part: SERV's two Wishbone buses (ibus: fetch only,
// dbus: loads and stores) onto one PicoRV32-style native memory port
// (valid/addr/wdata/wstrb out, ready/rdata in), the port of board_memmap.
//
// Rules.  SERV never requests on both buses at once (it fetches, then
// executes); the bridge relies on that, as servant_arbiter does: the ibus has
// priority and the acknowledge goes to the bus that requested.  A fetch is a
// read (wstrb 0); a dbus store drives wstrb = sel, a dbus load wstrb = 0.
// SERV holds cyc until ack and drops it afterwards; the bridge additionally
// drops valid_o in the clock after ready_i (done_q), the PicoRV32 behaviour
// board_memmap relies on, so a request is never performed twice.
//
// Counters.  SERV has no cycle/instret CSRs (rdcycle would read another CSR,
// not trap), so the bridge answers two read-only board registers itself,
// one-cycle access like board_memmap's registers; stores to them are ignored:
//   0x2000_0080  CYCLE: clocks since reset
//   0x2000_0084  INSTRET: instructions fetched since reset (SERV fetches
//                each instruction exactly once: no compressed, no alignment)
// They are read by firmware built with -DBOARD_NO_COUNTERS (soc/firmware/board.h);
// on a board without them (board_memmap alone) the same reads give 0.
//
// FENCE.  SERV decodes FENCE and FENCE.I (opcode 0001111) as a data-bus read
// from an address made of the instruction's fields (0x8000_0070 for
// `fence rw,rw`), which board_memmap would flag as unmapped.  The bridge
// remembers whether the last fetched instruction was one (fence_q) and
// completes its dbus access itself, like a counter read: nothing goes out.
// A fence orders nothing on SERV (in order, one access at a time, no store
// buffer), so that is its whole effect.
// Reset (synchronous, active high) clears the counters, fence_q and done_q.
`default_nettype none

module serv_bridge (
    input  wire        clk_i,
    input  wire        rst_i,      // synchronous, active high
    // SERV instruction bus (Wishbone, read only)
    input  wire [31:0] ibus_adr_i,
    input  wire        ibus_cyc_i,
    output wire [31:0] ibus_rdt_o,
    output wire        ibus_ack_o,
    // SERV data bus (Wishbone)
    input  wire [31:0] dbus_adr_i,
    input  wire [31:0] dbus_dat_i,
    input  wire [3:0]  dbus_sel_i,
    input  wire        dbus_we_i,
    input  wire        dbus_cyc_i,
    output wire [31:0] dbus_rdt_o,
    output wire        dbus_ack_o,
    // native memory port (to board_memmap)
    output wire        valid_o,
    output wire [31:0] addr_o,
    output wire [31:0] wdata_o,
    output wire [3:0]  wstrb_o,    // 0: read
    input  wire        ready_i,
    input  wire [31:0] rdata_i
);

    reg        done_q;          // ready in the previous clock: hold valid low
    reg        fence_q;         // the last fetched instruction is a FENCE
    reg        local_ready_q;   // counter read or FENCE access: ready this clock
    reg [31:0] ctr_rdata_q, cycle_q, instret_q;

    wire [31:0] adr     = ibus_cyc_i ? ibus_adr_i : dbus_adr_i;
    wire        req     = (ibus_cyc_i | dbus_cyc_i) & ~done_q;
    // Answered here: 0x2000_0080..0x2000_0087 on the dbus (the counters), and
    // any dbus access of a FENCE.
    wire        local_sel = ~ibus_cyc_i & (fence_q | adr[31:3] == 29'h0400_0010);
    wire        ack       = ready_i | local_ready_q;

    always @(posedge clk_i) begin
        if (rst_i) begin
            done_q        <= 1'b0;
            fence_q       <= 1'b0;
            local_ready_q <= 1'b0;
            cycle_q       <= 32'd0;
            instret_q     <= 32'd0;
        end else begin
            done_q        <= ack;
            local_ready_q <= req & local_sel & ~local_ready_q;
            cycle_q       <= cycle_q + 32'd1;
            if (ack & ibus_cyc_i) begin
                instret_q <= instret_q + 32'd1;
                fence_q   <= rdata_i[6:0] == 7'b0001111;
            end
        end
    end
    // Read data is data, not control: never reset.
    always @(posedge clk_i)
        ctr_rdata_q <= adr[2] ? instret_q : cycle_q;

    assign valid_o    = req & ~local_sel;
    assign addr_o     = adr;
    assign wdata_o    = dbus_dat_i;
    assign wstrb_o    = (~ibus_cyc_i & dbus_we_i) ? dbus_sel_i : 4'h0;
    assign ibus_ack_o = ack & ibus_cyc_i;
    assign dbus_ack_o = ack & ~ibus_cyc_i;
    assign ibus_rdt_o = rdata_i;
    assign dbus_rdt_o = local_ready_q ? ctr_rdata_q : rdata_i;

endmodule

`default_nettype wire
