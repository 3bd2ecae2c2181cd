// albatross_soc -- the synthesisable multi-board system for one FPGA: NB
// boards, each a PicoRV32 core (soc/pico_core.v with SMALL = 1: no
// counters, no traps) or, where SERV_MASK selects it, a SERV core
// (soc/serv_core.v; its program in local block RAM, board registers, a
// Wishbone master) on port A of its own
// albatross_dpram, the RAMs' port B joined by albatross_bus, whose master is
// albatross_controller running the schedule ROM.
//
// Clocks: with CPU_CDC 0, one clock (clk_i) and one synchronous reset
// (rst_i, active high) for everything; cpu_clk_i and cpu_rst_i are unused.
// With CPU_CDC 1 the cores run on their own clock, cpu_clk_i (reset
// cpu_rst_i), and each reaches port A of its DPRAM through albatross_wb_cdc;
// the DPRAMs, the bus and the controller stay on clk_i.  The communication
// controller is then independent of the processors' clock (seed 3.2, b-2):
// it never limits it.  The two clocks may be unrelated.  rst_i and cpu_rst_i
// must follow albatross_wb_cdc's reset rule (fpga/duo_system.v shows one way).
// A core's DPRAM access then takes up to 6 CPU + 7 RAM clocks instead of 1
// or 2 clocks (albatross_wb_cdc's bound with SYNC_STAGES 2).
//
// Images (the make flow, mk/fpga.mk, writes them): board c's program is
// <FW_PREFIX><c>.hex, the start image of its DPRAM <RAM_PREFIX><c>.hex (the
// compiler's <board>_ram.hex: every control byte Buffer1, so the firmware
// attaches at once), the controller's ROM ROM_FILE (the compiler's rom.hex).
// All three become block-RAM contents.  Status: done_o[c] when core c
// stored to TOHOST (its program ended), err_o[c] when that exit code is not
// 0 (a failed check), beat_o[c] = bit 0 of its STAT 0 (the firmware's
// heartbeat), trap_o[c] when it trapped; ctrl_err_o is the controller's
// error output (bad ROM header).  done_o, err_o, beat_o and trap_o are
// synchronous to the cores' clock, ctrl_err_o to clk_i.
`default_nettype none

module albatross_soc #(
    parameter NB         = 2,        // boards, 1..4 (a PicoRV32 each)
    parameter ADDR_WIDTH = 8,        // word-address bits of each DPRAM (8: 1 KiB)
    parameter RAM_WORDS  = 512,      // words of each core's program RAM (2 KiB: 4 iCE40 block RAMs)
    parameter N_CHAN     = 4,        // controller channel ids (the description's n_chan)
    parameter ROM_WORDS  = 256,      // schedule ROM depth in words
    parameter ROM_FILE   = "",       // schedule ROM image
    parameter FW_PREFIX  = "",       // board c's program: <FW_PREFIX><c>.hex ("": none)
    parameter RAM_PREFIX = "",       // board c's DPRAM image: <RAM_PREFIX><c>.hex ("": none)
    parameter TIMEOUT    = 8,        // controller access timeout, clocks
    parameter POLL       = 16,       // controller poll interval in sync mode
    parameter SERV_MASK  = 0,        // NB bits: board c's core is SERV when bit c is set, else PicoRV32
    parameter CPU_CDC    = 0         // 1: the cores on cpu_clk_i, through albatross_wb_cdc; 0: all on clk_i
) (
    input  wire          clk_i,      // RAMs, bus and controller (with CPU_CDC 0: everything)
    input  wire          rst_i,      // synchronous to clk_i, active high
    input  wire          cpu_clk_i,  // the cores' clock (CPU_CDC 1 only)
    input  wire          cpu_rst_i,  // synchronous to cpu_clk_i, active high (CPU_CDC 1 only)
    output wire [NB-1:0] done_o,     // core c ended its program
    output wire [NB-1:0] err_o,      // ... with a non-zero exit code
    output wire [NB-1:0] beat_o,     // core c's STAT 0 bit 0 (heartbeat)
    output wire [NB-1:0] trap_o,     // core c trapped
    output wire          ctrl_err_o  // controller error (bad ROM header)
);

    localparam BA = 4 + ADDR_WIDTH;  // bus address {board[3:0], word}

    wire          m_cyc, m_stb, m_we, m_ack, m_err;
    wire [BA-1:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat, m_rdat, time_now;
    wire [15:0]   rom_errors;
    wire [NB-1:0]            s_cyc, s_stb, s_we, s_ack;
    wire [NB*ADDR_WIDTH-1:0] s_adr;
    wire [NB*4-1:0]          s_sel;
    wire [NB*32-1:0]         s_wdat, s_rdat;
    wire unused_ctrl = &{1'b0, time_now, rom_errors};
    // The cores' clock and reset (a constant choice, no clock multiplexer).
    wire core_clk = (CPU_CDC != 0) ? cpu_clk_i : clk_i;
    wire core_rst = (CPU_CDC != 0) ? cpu_rst_i : rst_i;

    albatross_controller #(
        .NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS),
        .ROM_FILE(ROM_FILE), .TIMEOUT(TIMEOUT), .POLL(POLL)
    ) u_ctrl (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_we_o(m_we), .m_adr_o(m_adr), .m_sel_o(m_sel),
        .m_dat_o(m_wdat), .m_dat_i(m_rdat), .m_ack_i(m_ack), .m_err_i(m_err),
        .time_o(time_now), .error_o(ctrl_err_o), .rom_errors_o(rom_errors)
    );

    albatross_bus #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_bus (
        .m_cyc_i(m_cyc), .m_stb_i(m_stb), .m_we_i(m_we), .m_adr_i(m_adr), .m_sel_i(m_sel),
        .m_dat_i(m_wdat), .m_dat_o(m_rdat), .m_ack_o(m_ack), .m_err_o(m_err),
        .s_cyc_o(s_cyc), .s_stb_o(s_stb), .s_we_o(s_we), .s_adr_o(s_adr), .s_sel_o(s_sel),
        .s_dat_o(s_wdat), .s_dat_i(s_rdat), .s_ack_i(s_ack), .s_err_i({NB{1'b0}})
    );

    genvar c;
    generate
        for (c = 0; c < NB; c = c + 1) begin : g_board
            // "" (a zero) stays a zero at any width: no image.
            localparam FW_FILE  = (FW_PREFIX == "") ? "" : {FW_PREFIX, 8'd48 + c[7:0], ".hex"};
            localparam RAM_FILE = (RAM_PREFIX == "") ? "" : {RAM_PREFIX, 8'd48 + c[7:0], ".hex"};
            // Port A of the RAM (a_*) and the core's bus (c_*): the same
            // wires with CPU_CDC 0, the two sides of a bridge with CPU_CDC 1.
            wire                  a_cyc, a_stb, a_we, a_ack, c_cyc, c_stb, c_we, c_ack;
            wire [ADDR_WIDTH-1:0] a_adr, c_adr;
            wire [3:0]            a_sel, c_sel;
            wire [31:0]           a_wdat, a_rdat, c_wdat, c_rdat, code, ev_data, ev_arg;
            wire [127:0]          stat;
            wire                  ev_valid, bus_err;
            wire unused_board = &{1'b0, stat[127:1], ev_valid, ev_data, ev_arg, bus_err};

            albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH), .INIT_FILE(RAM_FILE)) u_ram (
                .clk_i(clk_i), .rst_i(rst_i),
                .a_cyc_i(a_cyc), .a_stb_i(a_stb), .a_we_i(a_we), .a_adr_i(a_adr),
                .a_sel_i(a_sel), .a_dat_i(a_wdat), .a_dat_o(a_rdat), .a_ack_o(a_ack),
                .b_cyc_i(s_cyc[c]), .b_stb_i(s_stb[c]), .b_we_i(s_we[c]),
                .b_adr_i(s_adr[c*ADDR_WIDTH +: ADDR_WIDTH]), .b_sel_i(s_sel[c*4 +: 4]),
                .b_dat_i(s_wdat[c*32 +: 32]), .b_dat_o(s_rdat[c*32 +: 32]), .b_ack_o(s_ack[c])
            );

            if (CPU_CDC != 0) begin : g_cdc
                albatross_wb_cdc #(.ADDR_WIDTH(ADDR_WIDTH)) u_cdc (
                    .s_clk_i(cpu_clk_i), .s_rst_i(cpu_rst_i), .m_clk_i(clk_i), .m_rst_i(rst_i),
                    .s_cyc_i(c_cyc), .s_stb_i(c_stb), .s_we_i(c_we), .s_adr_i(c_adr), .s_sel_i(c_sel),
                    .s_dat_i(c_wdat), .s_dat_o(c_rdat), .s_ack_o(c_ack),
                    .m_cyc_o(a_cyc), .m_stb_o(a_stb), .m_we_o(a_we), .m_adr_o(a_adr), .m_sel_o(a_sel),
                    .m_dat_o(a_wdat), .m_dat_i(a_rdat), .m_ack_i(a_ack)
                );
            end else begin : g_direct
                assign {a_cyc, a_stb, a_we, a_adr, a_sel, a_wdat} = {c_cyc, c_stb, c_we, c_adr, c_sel, c_wdat};
                assign {c_rdat, c_ack} = {a_rdat, a_ack};
            end

            board_core #(.SERV((SERV_MASK >> c) & 1), .CORE(c), .ADDR_WIDTH(ADDR_WIDTH),
                         .RAM_WORDS(RAM_WORDS), .FW_FILE(FW_FILE), .SMALL(1)) u_core (
                .clk_i     (core_clk),
                .rst_i     (core_rst),
                .stall_i   (1'b0),
                .wb_cyc_o  (c_cyc),
                .wb_stb_o  (c_stb),
                .wb_we_o   (c_we),
                .wb_adr_o  (c_adr),
                .wb_sel_o  (c_sel),
                .wb_dat_o  (c_wdat),
                .wb_dat_i  (c_rdat),
                .wb_ack_i  (c_ack),
                .done_o    (done_o[c]),
                .code_o    (code),
                .stat_o    (stat),
                .ev_valid_o(ev_valid),
                .ev_data_o (ev_data),
                .ev_arg_o  (ev_arg),
                .trap_o    (trap_o[c]),
                .bus_err_o (bus_err)
            );
            assign err_o[c]  = done_o[c] & (|code);
            assign beat_o[c] = stat[0];
        end
    endgenerate

endmodule

`default_nettype wire
