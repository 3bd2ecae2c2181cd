// serv_core -- board part: one SERV core (bit-serial RISC-V, rv32i) on the
// memory map of a board (board_memmap: local program RAM, board
// registers and a Wishbone master to one port of an albatross_dpram; the map
// is described there and in soc/firmware/board.h).  The same parameters and ports
// as pico_core, so a top picks either core per board with a generate-if.
//
// SERV (serv_rf_top: the core with its register file in a small RAM) has a
// Wishbone instruction bus and data bus; serv_bridge puts them onto
// board_memmap's native port and adds two read-only counter registers (CYCLE
// 0x2000_0080, INSTRET 0x2000_0084) that stand in for the cycle/instret CSRs
// SERV does not have.  Timing: SERV needs 32 or more clocks per instruction
// (bit-serial), plus the fetch (two clocks from the local RAM) and, for a
// load or store, the data access.  stall_i holds the core's local-RAM
// accesses (instruction fetches included); DPRAM accesses are never held.
// Reset (synchronous, active high) clears control state, never the RAM.
// SERV comes from PyPI (pythondata-cpu-serv): rv32i, WITH_CSR=1 (the machine
// CSRs, for traps), no compressed, no MDU, no timer interrupt.  It has no
// trap output: a trap (misaligned access, ecall) jumps to mtvec inside the
// core, so trap_o is tied to 0.
`default_nettype none

module serv_core #(
    parameter CORE       = 0,     // index: the firmware plusarg is +fw<CORE>=FILE (0..3)
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM port
    parameter RAM_WORDS  = 4096,  // words of the local RAM (16 KiB)
    parameter FW_FILE    = ""     // program image at configuration (board_memmap)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,     // synchronous, active high
    input  wire                  stall_i,   // hold the local-RAM access this cycle
    // Wishbone B4 classic master to a DPRAM port
    output wire                  wb_cyc_o,
    output wire                  wb_stb_o,
    output wire                  wb_we_o,
    output wire [ADDR_WIDTH-1:0] wb_adr_o,
    output wire [3:0]            wb_sel_o,
    output wire [31:0]           wb_dat_o,
    input  wire [31:0]           wb_dat_i,
    input  wire                  wb_ack_i,
    // board status
    output wire                  done_o,    // the core stored to TOHOST
    output wire [31:0]           code_o,    // the last value it stored (exit code)
    output wire [127:0]          stat_o,    // STAT k at [k*32 +: 32]
    output wire                  ev_valid_o,// a store to EVENT, this clock
    output wire [31:0]           ev_data_o, // its value
    output wire [31:0]           ev_arg_o,  // ARG at that time
    output wire                  trap_o,    // always 0: SERV has no trap output
    output wire                  bus_err_o  // an access to an unmapped address
);

    // SERV's buses.
    wire [31:0] ibus_adr, ibus_rdt, dbus_adr, dbus_dat, dbus_rdt;
    wire        ibus_cyc, ibus_ack, dbus_we, dbus_cyc, dbus_ack;
    wire [3:0]  dbus_sel;
    // The native port to the memory map.
    wire        mem_valid, mem_ready;
    wire [31:0] mem_addr, mem_wdata, mem_rdata;
    wire [3:0]  mem_wstrb;
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
        .valid_o   (mem_valid),
        .addr_o    (mem_addr),
        .wdata_o   (mem_wdata),
        .wstrb_o   (mem_wstrb),
        .ready_i   (mem_ready),
        .rdata_i   (mem_rdata)
    );

    board_memmap #(.CORE(CORE), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS), .FW_FILE(FW_FILE)) u_map (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .stall_i   (stall_i),
        .valid_i   (mem_valid),
        .addr_i    (mem_addr),
        .wdata_i   (mem_wdata),
        .wstrb_i   (mem_wstrb),
        .ready_o   (mem_ready),
        .rdata_o   (mem_rdata),
        .wb_cyc_o  (wb_cyc_o),
        .wb_stb_o  (wb_stb_o),
        .wb_we_o   (wb_we_o),
        .wb_adr_o  (wb_adr_o),
        .wb_sel_o  (wb_sel_o),
        .wb_dat_o  (wb_dat_o),
        .wb_dat_i  (wb_dat_i),
        .wb_ack_i  (wb_ack_i),
        .done_o    (done_o),
        .code_o    (code_o),
        .stat_o    (stat_o),
        .ev_valid_o(ev_valid_o),
        .ev_data_o (ev_data_o),
        .ev_arg_o  (ev_arg_o),
        .bus_err_o (bus_err_o)
    );
    assign trap_o = 1'b0;

endmodule

`default_nettype wire
