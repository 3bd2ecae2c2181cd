// board_core -- the soft core of one board: a PicoRV32 (pico_core), a
// SERV (serv_core, SERV = 1) or a VexRiscv with caches (vexriscv_core,
// VEX = 1; it wins over SERV), each with the same native memory port, and
// the board's memory map behind it (board_memmap, one instance for every
// kind of core: local program RAM, board registers, the Wishbone master to
// the DPRAM port; VexRiscv sees it through vexriscv_bridge, with the DPRAM
// window and registers uncached at 0x9000_0000 / 0xA000_0000).  stall_i
// holds the core's local-RAM accesses (instruction fetches and refills
// included); DPRAM accesses are never held.  Reset (synchronous, active
// high) clears control state, never the RAM.  albatross_system (the
// system of the FPGA tops, the robot simulation and the system test) and
// tb/pico/pico_pair instantiate this once per board; the timing and rules
// are those of the chosen core.
`default_nettype none

module board_core #(
    parameter SERV       = 0,     // 0: PicoRV32, 1: SERV
    parameter VEX        = 0,     // 1: VexRiscv (soc/vexriscv_core.v), whatever SERV is
    // Read only in the VexRiscv branch below: unused (UNUSEDPARAM) when VEX = 0.
    /* verilator lint_off UNUSEDPARAM */
    parameter CACHED_ALIAS = 0,   // VexRiscv only: 1 also maps the DPRAM window cached (a negative test)
    /* verilator lint_on UNUSEDPARAM */
    parameter CORE       = 0,     // index: the firmware plusarg is +fw<CORE>=FILE (0..3)
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM port
    parameter RAM_WORDS  = 4096,  // words of the local RAM (16 KiB)
    parameter FW_FILE    = "",    // program image at configuration ("": +fw<CORE>=FILE in simulation)
    parameter SMALL      = 0      // PicoRV32 only: 1 drops the counters and traps (pico_core)
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
    output wire                  trap_o,    // the core trapped (PicoRV32; SERV, VexRiscv: 0)
    output wire                  bus_err_o  // an access to an unmapped address
);

    // The chosen core's native memory port, to the memory map.
    wire        mem_valid, mem_ready;
    wire [31:0] mem_addr, mem_wdata, mem_rdata;
    wire [3:0]  mem_wstrb;

    generate
        if (VEX != 0) begin : g_vex
            vexriscv_core #(.CACHED_ALIAS(CACHED_ALIAS)) u_core (
                .clk_i(clk_i), .rst_i(rst_i),
                .mem_valid_o(mem_valid), .mem_addr_o(mem_addr), .mem_wdata_o(mem_wdata), .mem_wstrb_o(mem_wstrb),
                .mem_ready_i(mem_ready), .mem_rdata_i(mem_rdata), .trap_o(trap_o)
            );
        end else if (SERV == 0) begin : g_pico
            pico_core #(.SMALL(SMALL)) u_core (
                .clk_i(clk_i), .rst_i(rst_i),
                .mem_valid_o(mem_valid), .mem_addr_o(mem_addr), .mem_wdata_o(mem_wdata), .mem_wstrb_o(mem_wstrb),
                .mem_ready_i(mem_ready), .mem_rdata_i(mem_rdata), .trap_o(trap_o)
            );
        end else begin : g_serv
            serv_core u_core (
                .clk_i(clk_i), .rst_i(rst_i),
                .mem_valid_o(mem_valid), .mem_addr_o(mem_addr), .mem_wdata_o(mem_wdata), .mem_wstrb_o(mem_wstrb),
                .mem_ready_i(mem_ready), .mem_rdata_i(mem_rdata), .trap_o(trap_o)
            );
        end
    endgenerate

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

endmodule

`default_nettype wire
