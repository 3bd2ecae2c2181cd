// pico_core -- board part: one PicoRV32 core on the memory map of a
// board (board_memmap: local program RAM, board registers and a
// Wishbone master to one port of an albatross_dpram; the map is described
// there and in soc/firmware/board.h).  stall_i holds the core's local-RAM
// accesses (instruction fetches included); DPRAM accesses are never held.
// Reset (synchronous, active high) clears control state, never the RAM.
// PicoRV32 comes from PyPI (pythondata-cpu-picorv32): rv32i, counters on,
// no IRQ, no PCPI; SMALL = 1 drops the counters (the firmware must not read
// them) and the misalign/illegal-instruction traps, for FPGA tops whose
// firmware needs neither.
`default_nettype none

module pico_core #(
    parameter CORE       = 0,     // index: the firmware plusarg is +fw<CORE>=FILE (0..3)
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM port
    parameter RAM_WORDS  = 4096,  // words of the local RAM (16 KiB)
    parameter FW_FILE    = "",    // program image at configuration (board_memmap)
    parameter SMALL      = 0      // 1: a smaller PicoRV32 (no counters, no misalign/illegal-instruction traps)
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
    output wire                  trap_o,    // PicoRV32 trapped
    output wire                  bus_err_o  // an access to an unmapped address
);

    wire        mem_valid, mem_instr, mem_ready, trap;
    wire [31:0] mem_addr, mem_wdata, mem_rdata;
    wire [3:0]  mem_wstrb;
    // PicoRV32 outputs this core wrapper does not use.
    wire        la_read, la_write, pcpi_valid;
    wire [31:0] la_addr, la_wdata, pcpi_insn, pcpi_rs1, pcpi_rs2, eoi;
    wire [3:0]  la_wstrb;
    wire [35:0] trace_data;
    wire        trace_valid;

    picorv32 #(
        .ENABLE_COUNTERS  (SMALL ? 0 : 1),
        .CATCH_MISALIGN   (SMALL ? 0 : 1),
        .CATCH_ILLINSN    (SMALL ? 0 : 1),
        .ENABLE_COUNTERS64(0),
        .ENABLE_MUL       (0),
        .ENABLE_FAST_MUL  (0),
        .ENABLE_DIV       (0),
        .ENABLE_IRQ       (0),
        .COMPRESSED_ISA   (0),
        .ENABLE_PCPI      (0),
        .PROGADDR_RESET   (32'h0000_0000)
    ) u_cpu (
        .clk         (clk_i),
        .resetn      (~rst_i),
        .trap        (trap),
        .mem_valid   (mem_valid),
        .mem_instr   (mem_instr),
        .mem_ready   (mem_ready),
        .mem_addr    (mem_addr),
        .mem_wdata   (mem_wdata),
        .mem_wstrb   (mem_wstrb),
        .mem_rdata   (mem_rdata),
        .mem_la_read (la_read),
        .mem_la_write(la_write),
        .mem_la_addr (la_addr),
        .mem_la_wdata(la_wdata),
        .mem_la_wstrb(la_wstrb),
        .pcpi_valid  (pcpi_valid),
        .pcpi_insn   (pcpi_insn),
        .pcpi_rs1    (pcpi_rs1),
        .pcpi_rs2    (pcpi_rs2),
        .pcpi_wr     (1'b0),
        .pcpi_rd     (32'd0),
        .pcpi_wait   (1'b0),
        .pcpi_ready  (1'b0),
        .irq         (32'd0),
        .eoi         (eoi),
        .trace_valid (trace_valid),
        .trace_data  (trace_data)
    );
    wire unused_core = &{1'b0, mem_instr, la_read, la_write, la_addr, la_wdata,
                         la_wstrb, pcpi_valid, pcpi_insn, pcpi_rs1, pcpi_rs2, eoi,
                         trace_valid, trace_data};

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
    assign trap_o = trap;

endmodule

`default_nettype wire
