// tb_system -- multi-board test top: NB boards, the system bus, the controller.
//
// Each board b is an albatross_dpram.  Its port A is the CPU port, exposed as
// cpu_*[b]; its port B hangs on albatross_bus.  bus_fault_injector sits between
// albatross_controller and the bus.  Everything runs on clk_i: the harness
// drives the CPU ports, the fault inputs and the clock.  Rules:
//   * Flattened vectors: board b uses bits [b*w +: w] of a w-bit field.
//   * BOARD_BITS is fixed at 4: a bus address is always {board[3:0], word}.
//   * mon_*[b] is board b's port B as the RAM sees it, wired straight through.
//     mon_ack_o[b] is high in the clock after the RAM performed a port-B
//     access.  In that clock mon_we/adr/sel/wdat still carry the request
//     (neither the controller nor the injector has dropped it yet), and
//     mon_rdat carries the read data.
//   * bus_* is the controller's own master port (after the injector as it sees
//     ack and err): a request, and the answer the controller samples.
`default_nettype none

module tb_system #(
    parameter NB         = 4,     // boards
    parameter ADDR_WIDTH = 10,    // word-address bits of each board RAM
    parameter N_CHAN     = 16,    // controller channel ids
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in words
    parameter ROM_FILE   = "",    // $readmemh image of the schedule ROM
    parameter TIMEOUT    = 8,     // controller access timeout, clocks
    parameter POLL       = 16     // controller poll interval in sync mode, clocks
) (
    input  wire                       clk_i,
    input  wire                       rst_i,
    // CPU side of every board's port A
    input  wire [NB-1:0]              cpu_cyc_i,
    input  wire [NB-1:0]              cpu_stb_i,
    input  wire [NB-1:0]              cpu_we_i,
    input  wire [NB*ADDR_WIDTH-1:0]   cpu_adr_i,
    input  wire [NB*4-1:0]            cpu_sel_i,
    input  wire [NB*32-1:0]           cpu_dat_i,
    output wire [NB*32-1:0]           cpu_dat_o,
    output wire [NB-1:0]              cpu_ack_o,
    // fault injection
    input  wire [1:0]                 fi_kind_i,
    input  wire [NB-1:0]              fi_dead_i,
    // every RAM's port B as performed (valid while mon_ack_o[b])
    output wire [NB-1:0]              mon_ack_o,
    output wire [NB-1:0]              mon_we_o,
    output wire [NB*ADDR_WIDTH-1:0]   mon_adr_o,
    output wire [NB*4-1:0]            mon_sel_o,
    output wire [NB*32-1:0]           mon_wdat_o,
    output wire [NB*32-1:0]           mon_rdat_o,
    // the controller's bus as it sees it
    output wire                       bus_cyc_o,
    output wire                       bus_stb_o,
    output wire                       bus_we_o,
    output wire [ADDR_WIDTH+3:0]      bus_adr_o,   // {board[3:0], word}
    output wire                       bus_ack_o,
    output wire                       bus_err_o,
    // controller status
    output wire [31:0]                time_o,
    output wire                       error_o,
    output wire [15:0]                rom_errors_o
);

    localparam BOARD_BITS = 4;   // board field of a bus address
    localparam BA         = BOARD_BITS + ADDR_WIDTH;

    // controller <-> injector
    wire          c_cyc, c_stb, c_we, c_ack, c_err;
    wire [BA-1:0] c_adr;
    wire [3:0]    c_sel;
    wire [31:0]   c_wdat, c_rdat;
    // injector <-> bus
    wire          i_cyc, i_stb, i_we, i_ack, i_err;
    wire [BA-1:0] i_adr;
    wire [3:0]    i_sel;
    wire [31:0]   i_wdat, i_rdat;
    // bus <-> port B of each RAM
    wire [NB-1:0]            s_cyc, s_stb, s_we, s_ack;
    wire [NB*ADDR_WIDTH-1:0] s_adr;
    wire [NB*4-1:0]          s_sel;
    wire [NB*32-1:0]         s_wdat, s_rdat;

    albatross_controller #(
        .NB         (NB),
        .ADDR_WIDTH (ADDR_WIDTH),
        .N_CHAN     (N_CHAN),
        .ROM_WORDS  (ROM_WORDS),
        .ROM_FILE   (ROM_FILE),
        .TIMEOUT    (TIMEOUT),
        .POLL       (POLL)
    ) u_ctrl (
        .clk_i        (clk_i),
        .rst_i        (rst_i),
        .m_cyc_o      (c_cyc),
        .m_stb_o      (c_stb),
        .m_we_o       (c_we),
        .m_adr_o      (c_adr),
        .m_sel_o      (c_sel),
        .m_dat_o      (c_wdat),
        .m_dat_i      (c_rdat),
        .m_ack_i      (c_ack),
        .m_err_i      (c_err),
        .time_o       (time_o),
        .error_o      (error_o),
        .rom_errors_o (rom_errors_o)
    );

    bus_fault_injector #(
        .NB         (NB),
        .ADDR_WIDTH (ADDR_WIDTH)
    ) u_fi (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .fi_kind_i (fi_kind_i),
        .fi_dead_i (fi_dead_i),
        .c_cyc_i   (c_cyc),
        .c_stb_i   (c_stb),
        .c_we_i    (c_we),
        .c_adr_i   (c_adr),
        .c_sel_i   (c_sel),
        .c_dat_i   (c_wdat),
        .c_dat_o   (c_rdat),
        .c_ack_o   (c_ack),
        .c_err_o   (c_err),
        .b_cyc_o   (i_cyc),
        .b_stb_o   (i_stb),
        .b_we_o    (i_we),
        .b_adr_o   (i_adr),
        .b_sel_o   (i_sel),
        .b_dat_o   (i_wdat),
        .b_dat_i   (i_rdat),
        .b_ack_i   (i_ack),
        .b_err_i   (i_err)
    );

    albatross_bus #(
        .NB         (NB),
        .ADDR_WIDTH (ADDR_WIDTH)
    ) u_bus (
        .m_cyc_i (i_cyc),
        .m_stb_i (i_stb),
        .m_we_i  (i_we),
        .m_adr_i (i_adr),
        .m_sel_i (i_sel),
        .m_dat_i (i_wdat),
        .m_dat_o (i_rdat),
        .m_ack_o (i_ack),
        .m_err_o (i_err),
        .s_cyc_o (s_cyc),
        .s_stb_o (s_stb),
        .s_we_o  (s_we),
        .s_adr_o (s_adr),
        .s_sel_o (s_sel),
        .s_dat_o (s_wdat),
        .s_dat_i (s_rdat),
        .s_ack_i (s_ack),
        .s_err_i ({NB{1'b0}})          // the RAMs have no err output
    );

    genvar b;
    generate
        for (b = 0; b < NB; b = b + 1) begin : g_board
            albatross_dpram #(
                .ADDR_WIDTH (ADDR_WIDTH)
            ) u_ram (
                .clk_i   (clk_i),
                .rst_i   (rst_i),
                .a_cyc_i (cpu_cyc_i[b]),
                .a_stb_i (cpu_stb_i[b]),
                .a_we_i  (cpu_we_i[b]),
                .a_adr_i (cpu_adr_i[b*ADDR_WIDTH +: ADDR_WIDTH]),
                .a_sel_i (cpu_sel_i[b*4 +: 4]),
                .a_dat_i (cpu_dat_i[b*32 +: 32]),
                .a_dat_o (cpu_dat_o[b*32 +: 32]),
                .a_ack_o (cpu_ack_o[b]),
                .b_cyc_i (s_cyc[b]),
                .b_stb_i (s_stb[b]),
                .b_we_i  (s_we[b]),
                .b_adr_i (s_adr[b*ADDR_WIDTH +: ADDR_WIDTH]),
                .b_sel_i (s_sel[b*4 +: 4]),
                .b_dat_i (s_wdat[b*32 +: 32]),
                .b_dat_o (s_rdat[b*32 +: 32]),
                .b_ack_o (s_ack[b])
            );
        end
    endgenerate

    assign mon_ack_o  = s_ack;
    assign mon_we_o   = s_we;
    assign mon_adr_o  = s_adr;
    assign mon_sel_o  = s_sel;
    assign mon_wdat_o = s_wdat;
    assign mon_rdat_o = s_rdat;

    assign bus_cyc_o = c_cyc;
    assign bus_stb_o = c_stb;
    assign bus_we_o  = c_we;
    assign bus_adr_o = c_adr;
    assign bus_ack_o = c_ack;
    assign bus_err_o = c_err;

endmodule

`default_nettype wire
