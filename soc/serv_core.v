// serv_core -- board part: one SERV core (bit-serial RISC-V, rv32i) with a
// native memory port, the same ports as pico_core: board_core picks one core
// per board with a generate-if and puts the board's memory map
// (board_memmap; soc/firmware/board.h) behind it.
//
// SERV (serv_rf_top: the core with its register file in a small RAM) has a
// Wishbone instruction bus and data bus; serv_bridge puts them onto
// board_memmap's native port and adds two read-only counter registers (CYCLE
// 0x2000_0080, INSTRET 0x2000_0084) that stand in for the cycle/instret CSRs
// SERV does not have.  Timing: SERV needs 32 or more clocks per instruction
// (bit-serial), plus the fetch (two clocks from the local RAM) and, for a
// load or store, the data access.  Reset (synchronous, active high) clears
// control state.
// SERV comes from PyPI (pythondata-cpu-serv): rv32i, WITH_CSR=1 (the machine
// CSRs, for traps), no compressed, no MDU, no timer interrupt.  It has no
// trap output: a trap (misaligned access, ecall) jumps to mtvec inside the
// core, so trap_o is tied to 0.
`default_nettype none

module serv_core (
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
    output wire        trap_o        // always 0: SERV has no trap output
);

    // SERV's buses.
    wire [31:0] ibus_adr, ibus_rdt, dbus_adr, dbus_dat, dbus_rdt;
    wire        ibus_cyc, ibus_ack, dbus_we, dbus_cyc, dbus_ack;
    wire [3:0]  dbus_sel;
    // SERV outputs this core wrapper does not use (extension and MDU interface).
    wire [31:0] ext_rs1, ext_rs2;
    wire [2:0]  ext_funct3;
    wire        mdu_valid;

    serv_rf_top #(
        .RESET_PC      (32'h0000_0000),
        .COMPRESSED    (1'b0),
        .MDU           (1'b0),
        .PRE_REGISTER  (1),
        .RESET_STRATEGY("MINI"),
        .WITH_CSR      (1)
    ) u_cpu (
        .clk         (clk_i),
        .i_rst       (rst_i),
        .i_timer_irq (1'b0),
        .o_ibus_adr  (ibus_adr),
        .o_ibus_cyc  (ibus_cyc),
        .i_ibus_rdt  (ibus_rdt),
        .i_ibus_ack  (ibus_ack),
        .o_dbus_adr  (dbus_adr),
        .o_dbus_dat  (dbus_dat),
        .o_dbus_sel  (dbus_sel),
        .o_dbus_we   (dbus_we),
        .o_dbus_cyc  (dbus_cyc),
        .i_dbus_rdt  (dbus_rdt),
        .i_dbus_ack  (dbus_ack),
        .o_ext_rs1   (ext_rs1),
        .o_ext_rs2   (ext_rs2),
        .o_ext_funct3(ext_funct3),
        .i_ext_rd    (32'd0),
        .i_ext_ready (1'b0),
        .o_mdu_valid (mdu_valid)
    );
    wire unused_core = &{1'b0, ext_rs1, ext_rs2, ext_funct3, mdu_valid};

    serv_bridge u_bridge (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .ibus_adr_i(ibus_adr),
        .ibus_cyc_i(ibus_cyc),
        .ibus_rdt_o(ibus_rdt),
        .ibus_ack_o(ibus_ack),
        .dbus_adr_i(dbus_adr),
        .dbus_dat_i(dbus_dat),
        .dbus_sel_i(dbus_sel),
        .dbus_we_i (dbus_we),
        .dbus_cyc_i(dbus_cyc),
        .dbus_rdt_o(dbus_rdt),
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
