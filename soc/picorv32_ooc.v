// picorv32_ooc -- a PicoRV32 configured as soc/pico_core.v configures it
// (rv32i, cycle/instret counters, no multiply, divide, IRQ, PCPI or
// compressed instructions), with only its memory port on the ports: the
// design tools/fpga_report.py measures "one PicoRV32" with, so that its
// size and Fmax compare with the controller's on the same family.
`default_nettype none

module picorv32_ooc (
    input  wire        clk_i,
    input  wire        rst_i,        // synchronous, active high
    output wire        mem_valid_o,
    output wire        mem_instr_o,
    input  wire        mem_ready_i,
    output wire [31:0] mem_addr_o,
    output wire [31:0] mem_wdata_o,
    output wire [3:0]  mem_wstrb_o,
    input  wire [31:0] mem_rdata_i,
    output wire        trap_o
);

    // Outputs of PicoRV32 that this measurement leaves unconnected.
    wire        la_read, la_write, pcpi_valid, trace_valid;
    wire [31:0] la_addr, la_wdata, pcpi_insn, pcpi_rs1, pcpi_rs2, eoi;
    wire [3:0]  la_wstrb;
    wire [35:0] trace_data;
    wire unused = &{1'b0, la_read, la_write, la_addr, la_wdata, la_wstrb, pcpi_valid, pcpi_insn,
                    pcpi_rs1, pcpi_rs2, eoi, trace_valid, trace_data};

    picorv32 #(
        .ENABLE_COUNTERS  (1),
        .ENABLE_COUNTERS64(0),
        .ENABLE_MUL       (0),
        .ENABLE_FAST_MUL  (0),
        .ENABLE_DIV       (0),
        .ENABLE_IRQ       (0),
        .COMPRESSED_ISA   (0),
        .ENABLE_PCPI      (0),
        .PROGADDR_RESET   (32'h0000_0000)
    ) u_cpu (
        .clk(clk_i), .resetn(~rst_i), .trap(trap_o),
        .mem_valid(mem_valid_o), .mem_instr(mem_instr_o), .mem_ready(mem_ready_i),
        .mem_addr(mem_addr_o), .mem_wdata(mem_wdata_o), .mem_wstrb(mem_wstrb_o), .mem_rdata(mem_rdata_i),
        .mem_la_read(la_read), .mem_la_write(la_write), .mem_la_addr(la_addr),
        .mem_la_wdata(la_wdata), .mem_la_wstrb(la_wstrb),
        .pcpi_valid(pcpi_valid), .pcpi_insn(pcpi_insn), .pcpi_rs1(pcpi_rs1), .pcpi_rs2(pcpi_rs2),
        .pcpi_wr(1'b0), .pcpi_rd(32'd0), .pcpi_wait(1'b0), .pcpi_ready(1'b0),
        .irq(32'd0), .eoi(eoi), .trace_valid(trace_valid), .trace_data(trace_data)
    );

endmodule

`default_nettype wire
