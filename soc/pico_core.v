// pico_core -- board part: one PicoRV32 core with its native memory port
// (PicoRV32's own mem_* interface) on the ports; board_core puts the board's
// memory map (board_memmap: local program RAM, board registers and a
// Wishbone master to one port of an albatross_dpram; the map is described
// there and in soc/firmware/board.h) behind it.  Timing: PicoRV32's; a
// request waits for mem_ready_i.  Reset (synchronous, active high) clears
// control state.
// PicoRV32 comes from PyPI (pythondata-cpu-picorv32): rv32i, counters on,
// no IRQ, no PCPI; SMALL = 1 drops the counters (the firmware must not read
// them) and the misalign/illegal-instruction traps, for FPGA tops whose
// firmware needs neither.
`default_nettype none

module pico_core #(
    parameter SMALL      = 0      // 1: a smaller PicoRV32 (no counters, no misalign/illegal-instruction traps)
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
    output wire        trap_o        // PicoRV32 trapped
);

    wire        mem_instr, trap;
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
        .mem_valid   (mem_valid_o),
        .mem_instr   (mem_instr),
        .mem_ready   (mem_ready_i),
        .mem_addr    (mem_addr_o),
        .mem_wdata   (mem_wdata_o),
        .mem_wstrb   (mem_wstrb_o),
        .mem_rdata   (mem_rdata_i),
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

    assign trap_o = trap;

endmodule

`default_nettype wire
