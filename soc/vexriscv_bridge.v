// vexriscv_bridge -- board part: VexRiscv's two Wishbone buses (iBus: the
// instruction cache's line refills, dBus: the data cache's refills, its
// write-through stores and the uncached I/O accesses) onto one
// PicoRV32-style native memory port (valid/addr/wdata/wstrb out,
// ready/rdata in), the port of board_memmap, with the address map of a
// cached core.
//
// Address map (what the core sees -> board_memmap's map, soc/firmware/board.h).
// VexRiscv's LiteX variants (VexRiscv.v of pythondata-cpu-vexriscv,
// StaticMemoryTranslatorPlugin ioRange = _.msb) treat every address with bit
// 31 set as I/O: never cached, every load and store goes out on the bus as
// one access, in program order.  Bit 31 clear is cacheable (the data cache is
// write-through without write-allocate: a store always goes out, a load that
// hits is answered from the cache and never reaches the bus).  The bridge
// drops bit 31, so each board_memmap region appears twice:
//   0x0xxx_xxxx  local RAM, cached (code, data, stack)
//   0x8xxx_xxxx  local RAM, uncached alias
//   0x9xxx_xxxx  DPRAM window, uncached: where the driver's channels live
//   0xAxxx_xxxx  board registers, uncached (TOHOST, STAT, EVENT, TIMER, and
//                the counters below)
//   0x1xxx_xxxx, 0x2xxx_xxxx  the cached aliases of the DPRAM window and the
//                registers: only with CACHED_ALIAS = 1 (a test of what goes
//                wrong when the window is cached); with CACHED_ALIAS = 0 they
//                are unmapped, so a program built for the wrong window fails
//                at once with bus_err_o instead of reading stale values
//   other        unmapped (board_memmap sets bus_err_o, the access completes)
//
// Arbitration.  The port serves one bus at a time.  A bus that owns the port
// keeps it while its cyc stays high (a refill burst of 8 beats is never
// split); otherwise the dBus goes first.  The handover costs no clock.  Each
// beat is one native request: VexRiscv moves to its next beat (or drops cyc)
// in the clock after ack, and board_memmap never performs a request twice
// (its ready clock blocks it), so a request is performed exactly once.
//
// Counters.  The small CSR set of the LiteX variant has no cycle/instret
// CSRs, so the bridge answers two read-only board registers itself
// (one-cycle access, stores ignored), as serv_bridge does for SERV:
//   0x2000_0080  CYCLE: clocks since reset (core address 0xA000_0080)
//   0x2000_0084  INSTRET: reads 0 (VexRiscv brings out no retire signal)
// Firmware reads them when built with -DBOARD_NO_COUNTERS.
// Reset (synchronous, active high) clears the grant and the counter.
`default_nettype none

module vexriscv_bridge #(
    parameter CACHED_ALIAS = 0  // 1: 0x1/0x2xxx_xxxx reach the DPRAM and registers through the cache
) (
    input  wire        clk_i,
    input  wire        rst_i,      // synchronous, active high
    // VexRiscv iBus (Wishbone, reads; word address)
    input  wire [29:0] ibus_adr_i,
    input  wire        ibus_cyc_i,
    input  wire        ibus_stb_i,
    output wire [31:0] ibus_dat_o,
    output wire        ibus_ack_o,
    // VexRiscv dBus (Wishbone; word address)
    input  wire [29:0] dbus_adr_i,
    input  wire [31:0] dbus_dat_i,
    input  wire [3:0]  dbus_sel_i,
    input  wire        dbus_we_i,
    input  wire        dbus_cyc_i,
    input  wire        dbus_stb_i,
    output wire [31:0] dbus_dat_o,
    output wire        dbus_ack_o,
    // native memory port (to board_memmap)
    output wire        valid_o,
    output wire [31:0] addr_o,
    output wire [31:0] wdata_o,
    output wire [3:0]  wstrb_o,    // 0: read
    input  wire        ready_i,
    input  wire [31:0] rdata_i
);

    reg        own_i_q, own_d_q;    // the bus that owned the port last clock
    reg        local_ready_q;       // counter read answered this clock
    reg [31:0] cycle_q, ctr_rdata_q;

    // Owner: the last owner while its cyc stays high, else the dBus first.
    wire keep_i = own_i_q & ibus_cyc_i;
    wire keep_d = own_d_q & dbus_cyc_i;
    wire sel_d  = keep_d | (~keep_i & dbus_cyc_i);
    wire sel_i  = ~sel_d & ibus_cyc_i;

    wire [31:0] adr = sel_d ? {dbus_adr_i, 2'b00} : {ibus_adr_i, 2'b00};
    wire        req = sel_d ? dbus_stb_i : sel_i & ibus_stb_i;
    wire        we  = sel_d & dbus_we_i;
    // Bit 31 (I/O) dropped; a cached alias of the DPRAM or the registers is
    // sent to an unmapped region unless CACHED_ALIAS.
    wire        io        = adr[31];
    wire        alias_bad = ~io && adr[30:28] != 3'd0 && !(CACHED_ALIAS != 0 && adr[30:28] <= 3'd2);
    wire [31:0] map_adr   = alias_bad ? {4'hF, adr[27:0]} : {1'b0, adr[30:0]};
    // CYCLE / INSTRET: board_memmap 0x2000_0080..0x2000_0087.
    wire        local_sel = map_adr[31:3] == 29'h0400_0010;
    wire        ack       = ready_i | local_ready_q;

    always @(posedge clk_i) begin
        if (rst_i) begin
            own_i_q       <= 1'b0;
            own_d_q       <= 1'b0;
            local_ready_q <= 1'b0;
            cycle_q       <= 32'd0;
        end else begin
            own_i_q       <= sel_i;
            own_d_q       <= sel_d;
            local_ready_q <= req & local_sel & ~local_ready_q;
            cycle_q       <= cycle_q + 32'd1;
        end
    end
    // Read data is data, not control: never reset.
    always @(posedge clk_i)
        ctr_rdata_q <= map_adr[2] ? 32'd0 : cycle_q;

    assign valid_o    = req & ~local_sel;
    assign addr_o     = map_adr;
    assign wdata_o    = dbus_dat_i;
    assign wstrb_o    = we ? dbus_sel_i : 4'h0;
    assign ibus_ack_o = ack & sel_i;
    assign dbus_ack_o = ack & sel_d;
    assign ibus_dat_o = rdata_i;
    assign dbus_dat_o = local_ready_q ? ctr_rdata_q : rdata_i;

endmodule

`default_nettype wire
