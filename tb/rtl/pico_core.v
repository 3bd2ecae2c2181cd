// pico_core -- test fixture: one PicoRV32 core with its local program RAM,
// board registers and a Wishbone master to one port of an albatross_dpram.
//
// Memory map (address bits 31:28 select the region; firmware/board.h):
//   0x0xxx_xxxx  local RAM, RAM_WORDS words, performed at the edge after the
//                request (one-cycle access), loaded from +fw<CORE>=FILE
//   0x1xxx_xxxx  DPRAM window: wb_* through a pico_wb_adapter
//   0x2xxx_xxxx  board registers: +0 TOHOST (a store sets done_o and
//                code_o), +0x10..0x1c STAT 0..3 (stat_o); reads give 0
//   other        bus_err_o is set (sticky); the access completes, reads 0
// stall_i holds the local-RAM access (instruction fetches included) while
// high: a harness varies the core's speed with it, as an interrupt or a slow
// memory would; DPRAM accesses are never held.  Reset (synchronous, active
// high) clears control state, never the RAM.  PicoRV32 comes from PyPI
// (pythondata-cpu-picorv32): rv32i, counters on, no IRQ, no PCPI.
`default_nettype none

module pico_core #(
    parameter CORE       = 0,     // index: the firmware plusarg is +fw<CORE>=FILE (0..3)
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM port
    parameter RAM_WORDS  = 4096   // words of the local RAM (16 KiB)
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
    output wire                  trap_o,    // PicoRV32 trapped
    output wire                  bus_err_o  // an access to an unmapped address
);

    localparam RAM_BITS = $clog2(RAM_WORDS);  // word-address bits, local RAM

    wire        mem_valid, mem_instr, mem_ready, trap;
    wire [31:0] mem_addr, mem_wdata, mem_rdata;
    wire [3:0]  mem_wstrb;
    // PicoRV32 outputs this fixture does not use.
    wire        la_read, la_write, pcpi_valid;
    wire [31:0] la_addr, la_wdata, pcpi_insn, pcpi_rs1, pcpi_rs2, eoi;
    wire [3:0]  la_wstrb;
    wire [35:0] trace_data;
    wire        trace_valid;

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
                         trace_valid, trace_data, mem_addr[27:ADDR_WIDTH+2]};

    // Address decode: bits 31:28 pick the region.
    wire sel_ram  = mem_valid && mem_addr[31:28] == 4'h0;
    wire sel_dp   = mem_valid && mem_addr[31:28] == 4'h1;
    wire sel_regs = mem_valid && mem_addr[31:28] == 4'h2;
    wire sel_none = mem_valid && mem_addr[31:28] >  4'h2;

    // Local RAM: performed at the edge after the request, ready then.
    reg [31:0] ram [0:RAM_WORDS-1];
    reg [31:0] ram_rdata_q;
    reg        ram_ready_q;
    wire [RAM_BITS-1:0] ram_idx = mem_addr[RAM_BITS+1:2];
`ifndef SYNTHESIS  // simulation only: Yosys has no $value$plusargs
    reg [8*256-1:0] fw_file;
    integer         have_fw;
    initial begin
        case (CORE)
            0:       have_fw = $value$plusargs("fw0=%s", fw_file);
            1:       have_fw = $value$plusargs("fw1=%s", fw_file);
            2:       have_fw = $value$plusargs("fw2=%s", fw_file);
            default: have_fw = $value$plusargs("fw3=%s", fw_file);
        endcase
        if (have_fw != 0) $readmemh(fw_file, ram);
        else $display("pico_core: no +fw%0d=FILE given, core %0d has an empty RAM", CORE, CORE);
    end
`endif
    always @(posedge clk_i) begin
        ram_ready_q <= sel_ram & ~ram_ready_q & ~stall_i & ~rst_i;
        if (sel_ram & ~ram_ready_q & ~stall_i) begin
            ram_rdata_q <= ram[ram_idx];
            if (mem_wstrb[0]) ram[ram_idx][7:0]   <= mem_wdata[7:0];
            if (mem_wstrb[1]) ram[ram_idx][15:8]  <= mem_wdata[15:8];
            if (mem_wstrb[2]) ram[ram_idx][23:16] <= mem_wdata[23:16];
            if (mem_wstrb[3]) ram[ram_idx][31:24] <= mem_wdata[31:24];
        end
    end
    wire unused_ram_addr = &{1'b0, mem_addr[27:RAM_BITS+2]};

    // Board registers and unmapped addresses: one-cycle access.
    reg        regs_ready_q, done_q, err_q;
    reg [31:0] code_q;
    reg [31:0] stat_q [0:3];
    always @(posedge clk_i) begin
        if (rst_i) begin
            regs_ready_q <= 1'b0;
            done_q       <= 1'b0;
            err_q        <= 1'b0;
            code_q       <= 32'd0;
        end else begin
            regs_ready_q <= (sel_regs | sel_none) & ~regs_ready_q;
            if (sel_none) err_q <= 1'b1;
            if (sel_regs & ~regs_ready_q & (|mem_wstrb)) begin
                if (mem_addr[7:0] == 8'h00) begin
                    done_q <= 1'b1;
                    code_q <= mem_wdata;
                end
                if (mem_addr[7:4] == 4'h1) stat_q[mem_addr[3:2]] <= mem_wdata;
            end
        end
    end

    // DPRAM window through the adapter.
    wire        dp_ready;
    wire [31:0] dp_rdata;
    pico_wb_adapter #(.ADDR_WIDTH(ADDR_WIDTH)) u_adapter (
        .valid_i (sel_dp),
        .addr_i  (mem_addr[ADDR_WIDTH+1:0]),
        .wdata_i (mem_wdata),
        .wstrb_i (mem_wstrb),
        .ready_o (dp_ready),
        .rdata_o (dp_rdata),
        .wb_cyc_o(wb_cyc_o),
        .wb_stb_o(wb_stb_o),
        .wb_we_o (wb_we_o),
        .wb_adr_o(wb_adr_o),
        .wb_sel_o(wb_sel_o),
        .wb_dat_o(wb_dat_o),
        .wb_dat_i(wb_dat_i),
        .wb_ack_i(wb_ack_i)
    );

    assign mem_ready = ram_ready_q | regs_ready_q | dp_ready;
    assign mem_rdata = ram_ready_q ? ram_rdata_q : dp_ready ? dp_rdata : 32'd0;

    assign done_o    = done_q;
    assign code_o    = code_q;
    assign stat_o    = {stat_q[3], stat_q[2], stat_q[1], stat_q[0]};
    assign trap_o    = trap;
    assign bus_err_o = err_q;

endmodule

`default_nettype wire
