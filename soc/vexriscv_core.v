// vexriscv_core -- board part: one VexRiscv core (the LiteX standard
// variant VexRiscv.v of pythondata-cpu-vexriscv: rv32im, 5-stage pipeline,
// 4 KiB instruction cache and 4 KiB write-through data cache, 32-byte lines,
// Wishbone iBus and dBus) with a native memory port, the same ports as
// pico_core: board_core picks it per board with a generate-if (VEX = 1) and
// puts the board's memory map (board_memmap: local program RAM, board
// registers and a Wishbone master to one port of an albatross_dpram) behind it.
//
// What a cached core needs.  The data cache would hand the driver stale
// copies of the channel's control bytes and buffers (the other side writes
// the DPRAM behind the cache's back), so the DPRAM window must be uncached.
// The variant's I/O rule is fixed in its generated Verilog: an address with
// bit 31 set is I/O, never cached (checked: isIoAccess = physicalAddress[31]
// on both buses).  vexriscv_bridge therefore shows the DPRAM window at
// 0x9000_0000 and the board registers at 0xA000_0000 (board_memmap's 0x1 and
// 0x2 regions with bit 31 set); code and data stay cached at 0.  Firmware
// for this core is built with -DBOARD_DPRAM_BASE=0x90000000
// -DBOARD_REGS_BASE=0xA0000000 -DBOARD_NO_COUNTERS (soc/firmware/board.h);
// the driver itself is unchanged.  CACHED_ALIAS = 1 also lets the core reach
// the DPRAM and the registers through the cache at 0x1 and 0x2 (the negative
// test of tools/mk/vexriscv.mk); with 0 (the default) those addresses are
// unmapped.  The full map and the arbitration of the two buses:
// soc/vexriscv_bridge.v.
//
// Timing.  A cache hit costs no bus access; a miss refills a 32-byte line in
// 8 beats of 2 clocks each from the local RAM.  An uncached access (the
// DPRAM window, a register) is one bus request; the pipeline waits for it.
// Reset (synchronous, active high) clears control state; the caches
// invalidate themselves after reset.
// VexRiscv brings out no trap signal: a trap jumps to mtvec inside the core
// (the variant's mtvec is write-only and not initialised), so trap_o is 0;
// a run that traps ends on its harness's watchdog.
`default_nettype none

module vexriscv_core #(
    parameter CACHED_ALIAS = 0    // 1: the DPRAM and registers also reachable cached (vexriscv_bridge)
) (
    input  wire        clk_i,
    input  wire        rst_i,        // synchronous, active high
    // Native memory port to the board's memory map (board_core puts
    // board_memmap here): a request holds mem_valid_o and its address, data
    // and byte strobes (0: a read) until mem_ready_i, with mem_rdata_i valid then.
    output wire        mem_valid_o,
    output wire [31:0] mem_addr_o,
    output wire [31:0] mem_wdata_o,
    output wire [3:0]  mem_wstrb_o,
    input  wire        mem_ready_i,
    input  wire [31:0] mem_rdata_i,
    output wire        trap_o        // always 0: VexRiscv has no trap output
);

    // VexRiscv's buses.
    wire [29:0] ibus_adr, dbus_adr;
    wire [31:0] ibus_dat, dbus_dat, dbus_rdt, ibus_wdat;
    wire        ibus_cyc, ibus_stb, ibus_ack, ibus_we;
    wire        dbus_cyc, dbus_stb, dbus_ack, dbus_we;
    wire [3:0]  dbus_sel, ibus_sel;
    wire [2:0]  ibus_cti, dbus_cti;
    wire [1:0]  ibus_bte, dbus_bte;
    // Outputs this wrapper does not use: the iBus's write side, the burst
    // tags (each beat is its own request here: vexriscv_bridge).
    wire unused_core = &{1'b0, ibus_wdat, ibus_we, ibus_sel, ibus_cti, ibus_bte, dbus_cti, dbus_bte};

    VexRiscv u_cpu (
        .externalResetVector   (32'h0000_0000),
        .timerInterrupt        (1'b0),
        .softwareInterrupt     (1'b0),
        .externalInterruptArray(32'd0),
        .iBusWishbone_CYC      (ibus_cyc),
        .iBusWishbone_STB      (ibus_stb),
        .iBusWishbone_ACK      (ibus_ack),
        .iBusWishbone_WE       (ibus_we),
        .iBusWishbone_ADR      (ibus_adr),
        .iBusWishbone_DAT_MISO (ibus_dat),
        .iBusWishbone_DAT_MOSI (ibus_wdat),
        .iBusWishbone_SEL      (ibus_sel),
        .iBusWishbone_ERR      (1'b0),
        .iBusWishbone_CTI      (ibus_cti),
        .iBusWishbone_BTE      (ibus_bte),
        .dBusWishbone_CYC      (dbus_cyc),
        .dBusWishbone_STB      (dbus_stb),
        .dBusWishbone_ACK      (dbus_ack),
        .dBusWishbone_WE       (dbus_we),
        .dBusWishbone_ADR      (dbus_adr),
        .dBusWishbone_DAT_MISO (dbus_rdt),
        .dBusWishbone_DAT_MOSI (dbus_dat),
        .dBusWishbone_SEL      (dbus_sel),
        .dBusWishbone_ERR      (1'b0),
        .dBusWishbone_CTI      (dbus_cti),
        .dBusWishbone_BTE      (dbus_bte),
        .clk                   (clk_i),
        .reset                 (rst_i)
    );

    vexriscv_bridge #(.CACHED_ALIAS(CACHED_ALIAS)) u_bridge (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .ibus_adr_i(ibus_adr),
        .ibus_cyc_i(ibus_cyc),
        .ibus_stb_i(ibus_stb),
        .ibus_dat_o(ibus_dat),
        .ibus_ack_o(ibus_ack),
        .dbus_adr_i(dbus_adr),
        .dbus_dat_i(dbus_dat),
        .dbus_sel_i(dbus_sel),
        .dbus_we_i (dbus_we),
        .dbus_cyc_i(dbus_cyc),
        .dbus_stb_i(dbus_stb),
        .dbus_dat_o(dbus_rdt),
        .dbus_ack_o(dbus_ack),
        .valid_o   (mem_valid_o),
        .addr_o    (mem_addr_o),
        .wdata_o   (mem_wdata_o),
        .wstrb_o   (mem_wstrb_o),
        .ready_i   (mem_ready_i),
        .rdata_i   (mem_rdata_i)
    );

    assign trap_o = 1'b0;

endmodule

`default_nettype wire
