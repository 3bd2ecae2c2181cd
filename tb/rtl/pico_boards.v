// pico_boards -- test top: NB boards, each a PicoRV32 core with its own
// albatross_dpram, joined by albatross_bus and albatross_controller.
//
// Board c: core c (the memory map of tb/rtl/pico_pair.v and firmware/board.h:
// local RAM at 0, DPRAM window at 0x1000_0000, board registers at
// 0x2000_0000 with TOHOST and STAT 0..3) reaches port A of its own
// albatross_dpram through a pico_wb_adapter; port B hangs on albatross_bus,
// whose master is albatross_controller (no fault injector: the bus's slave
// err inputs are tied low).  Plusargs (simulation only): +fwC=FILE the
// program of core C, +ramC=FILE the start image of board C's DPRAM (the
// compiler's <board>_ram.hex), +rom=FILE the schedule ROM (read by the
// controller itself).  Board index c is the compiler's board index; NB is at
// most 4 (four plusarg names).  Core c uses the flattened outputs' bits
// [c*w +: w].  stall_i[c] holds core c's local-RAM accesses as in pico_pair.
`default_nettype none

module pico_boards #(
    parameter NB         = 4,     // boards, 1..4
    parameter ADDR_WIDTH = 10,    // word-address bits of each board DPRAM
    parameter RAM_WORDS  = 4096,  // words of each core's local RAM (16 KiB)
    parameter N_CHAN     = 16,    // controller channel ids
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in words
    parameter TIMEOUT    = 8,     // controller access timeout, clocks
    parameter POLL       = 16     // controller poll interval in sync mode
) (
    input  wire              clk_i,
    input  wire              rst_i,      // synchronous, active high
    input  wire [NB-1:0]     stall_i,    // core c: hold its local-RAM access this cycle
    output wire [NB-1:0]     done_o,     // core c stored to TOHOST
    output wire [NB*32-1:0]  code_o,     // the last value it stored (exit code)
    output wire [NB*128-1:0] stat_o,     // core c: STAT k at [c*128 + k*32 +: 32]
    output wire [NB-1:0]     trap_o,     // core c trapped (PicoRV32 trap)
    output wire [NB-1:0]     bus_err_o,  // core c accessed an unmapped address
    output wire [31:0]       time_o,     // controller global time
    output wire              error_o,    // controller error
    output wire [15:0]       rom_errors_o,
    output wire              m_cyc_o     // the controller's bus cycle (bus load figure)
);

    localparam RAM_BITS = $clog2(RAM_WORDS);  // word-address bits, local RAM
    localparam BA       = 4 + ADDR_WIDTH;     // bus address {board[3:0], word}

    // controller <-> bus
    wire          m_cyc, m_stb, m_we, m_ack, m_err;
    wire [BA-1:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat, m_rdat;
    // bus <-> port B of each RAM
    wire [NB-1:0]            s_cyc, s_stb, s_we, s_ack;
    wire [NB*ADDR_WIDTH-1:0] s_adr;
    wire [NB*4-1:0]          s_sel;
    wire [NB*32-1:0]         s_wdat, s_rdat;

    albatross_controller #(
        .NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS),
        .ROM_FILE(""), .TIMEOUT(TIMEOUT), .POLL(POLL)
    ) u_ctrl (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_we_o(m_we), .m_adr_o(m_adr), .m_sel_o(m_sel),
        .m_dat_o(m_wdat), .m_dat_i(m_rdat), .m_ack_i(m_ack), .m_err_i(m_err),
        .time_o(time_o), .error_o(error_o), .rom_errors_o(rom_errors_o)
    );

    albatross_bus #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_bus (
        .m_cyc_i(m_cyc), .m_stb_i(m_stb), .m_we_i(m_we), .m_adr_i(m_adr), .m_sel_i(m_sel),
        .m_dat_i(m_wdat), .m_dat_o(m_rdat), .m_ack_o(m_ack), .m_err_o(m_err),
        .s_cyc_o(s_cyc), .s_stb_o(s_stb), .s_we_o(s_we), .s_adr_o(s_adr), .s_sel_o(s_sel),
        .s_dat_o(s_wdat), .s_dat_i(s_rdat), .s_ack_i(s_ack), .s_err_i({NB{1'b0}})
    );
    assign m_cyc_o = m_cyc;

    genvar c;
    generate
        for (c = 0; c < NB; c = c + 1) begin : g_board
            wire        mem_valid, mem_instr, mem_ready, trap;
            wire [31:0] mem_addr, mem_wdata, mem_rdata;
            wire [3:0]  mem_wstrb;
            // PicoRV32 outputs this top does not use.
            wire        la_read, la_write, pcpi_valid;
            wire [31:0] la_addr, la_wdata, pcpi_insn, pcpi_rs1, pcpi_rs2, eoi;
            wire [3:0]  la_wstrb;
            wire [35:0] trace_data;
            wire        trace_valid;

            // The board's RAM: port A the core (adapter), port B the bus.
            wire                  a_cyc, a_stb, a_we, a_ack;
            wire [ADDR_WIDTH-1:0] a_adr;
            wire [3:0]            a_sel;
            wire [31:0]           a_wdat, a_rdat;
            albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH)) u_ram (
                .clk_i(clk_i), .rst_i(rst_i),
                .a_cyc_i(a_cyc), .a_stb_i(a_stb), .a_we_i(a_we), .a_adr_i(a_adr),
                .a_sel_i(a_sel), .a_dat_i(a_wdat), .a_dat_o(a_rdat), .a_ack_o(a_ack),
                .b_cyc_i(s_cyc[c]), .b_stb_i(s_stb[c]), .b_we_i(s_we[c]),
                .b_adr_i(s_adr[c*ADDR_WIDTH +: ADDR_WIDTH]), .b_sel_i(s_sel[c*4 +: 4]),
                .b_dat_i(s_wdat[c*32 +: 32]), .b_dat_o(s_rdat[c*32 +: 32]), .b_ack_o(s_ack[c])
            );

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
            reg [8*256-1:0] fw_file, img_file;
            integer         have_fw, have_img;
            initial begin
                case (c)
                    0: have_fw = $value$plusargs("fw0=%s", fw_file);
                    1: have_fw = $value$plusargs("fw1=%s", fw_file);
                    2: have_fw = $value$plusargs("fw2=%s", fw_file);
                    default: have_fw = $value$plusargs("fw3=%s", fw_file);
                endcase
                if (have_fw != 0) $readmemh(fw_file, ram);
                else $display("pico_boards: no +fw%0d=FILE given, core %0d has an empty RAM", c, c);
                case (c)
                    0: have_img = $value$plusargs("ram0=%s", img_file);
                    1: have_img = $value$plusargs("ram1=%s", img_file);
                    2: have_img = $value$plusargs("ram2=%s", img_file);
                    default: have_img = $value$plusargs("ram3=%s", img_file);
                endcase
                if (have_img != 0) $readmemh(img_file, u_ram.mem);
            end
`endif
            always @(posedge clk_i) begin
                ram_ready_q <= sel_ram & ~ram_ready_q & ~stall_i[c] & ~rst_i;
                if (sel_ram & ~ram_ready_q & ~stall_i[c]) begin
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
                .wb_cyc_o(a_cyc),
                .wb_stb_o(a_stb),
                .wb_we_o (a_we),
                .wb_adr_o(a_adr),
                .wb_sel_o(a_sel),
                .wb_dat_o(a_wdat),
                .wb_dat_i(a_rdat),
                .wb_ack_i(a_ack)
            );

            assign mem_ready = ram_ready_q | regs_ready_q | dp_ready;
            assign mem_rdata = ram_ready_q ? ram_rdata_q : dp_ready ? dp_rdata : 32'd0;

            assign done_o[c]              = done_q;
            assign code_o[c*32 +: 32]     = code_q;
            assign stat_o[c*128 +: 128]   = {stat_q[3], stat_q[2], stat_q[1], stat_q[0]};
            assign trap_o[c]              = trap;
            assign bus_err_o[c]           = err_q;
        end
    endgenerate

endmodule

`default_nettype wire
