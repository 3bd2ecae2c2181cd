// pico_boards -- test top: NB boards, each a PicoRV32 core (or, where
// SERV_MASK selects it, a SERV core: soc/serv_core.v) with its own
// albatross_dpram, joined by albatross_bus and albatross_controller; the
// controller reaches the bus through a bus_fault_injector.
//
// Board c: core c (the memory map of tb/pico/pico_pair.v and soc/firmware/board.h:
// local RAM at 0, DPRAM window at 0x1000_0000, board registers at
// 0x2000_0000 with TOHOST and STAT 0..3) reaches port A of its own
// albatross_dpram through a pico_wb_adapter; port B hangs on albatross_bus,
// whose master is albatross_controller behind a bus_fault_injector
// (fi_kind_i / fi_dead_i as in tb/common/bus_fault_injector.v; 0 forwards every
// request unchanged; the bus's slave err inputs are tied low).  The harness
// sees each core's board events (ev_*: a store to EVENT, board_memmap.v),
// each core's completed DPRAM accesses (dp_*: port A, one clock per acked
// access), and the controller side of the injector (m_*), where a new request
// is m_stb_o in a clock after one without m_stb_o or with an answer.  Plusargs (simulation only): +fwC=FILE the
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
    parameter POLL       = 16,    // controller poll interval in sync mode
    parameter SERV_MASK  = 0      // NB bits: board c's core is SERV when bit c is set, else PicoRV32
) (
    input  wire              clk_i,
    input  wire              rst_i,      // synchronous, active high
    input  wire [NB-1:0]     stall_i,    // core c: hold its local-RAM access this cycle
    input  wire [1:0]        fi_kind_i,  // fault kind for the controller's next new request
    input  wire [NB-1:0]     fi_dead_i,  // board links that are down
    output wire [NB-1:0]     done_o,     // core c stored to TOHOST
    output wire [NB*32-1:0]  code_o,     // the last value it stored (exit code)
    output wire [NB*128-1:0] stat_o,     // core c: STAT k at [c*128 + k*32 +: 32]
    output wire [NB-1:0]     ev_valid_o, // core c stored to EVENT (one clock)
    output wire [NB*32-1:0]  ev_data_o,  // that value
    output wire [NB*32-1:0]  ev_arg_o,   // ARG at that time
    output wire [NB-1:0]     dp_ack_o,   // core c's DPRAM access acked this clock
    output wire [NB-1:0]     dp_we_o,    // ... and it is a write
    output wire [NB*ADDR_WIDTH-1:0] dp_adr_o, // its word address
    output wire [NB*4-1:0]   dp_sel_o,   // its byte lanes
    output wire [NB-1:0]     trap_o,     // core c trapped (PicoRV32 trap)
    output wire [NB-1:0]     bus_err_o,  // core c accessed an unmapped address
    output wire [31:0]       time_o,     // controller global time
    output wire              error_o,    // controller error
    output wire [15:0]       rom_errors_o,
    output wire              m_cyc_o,    // the controller's bus cycle (bus load figure)
    output wire              m_stb_o,    // its strobe (controller side of the injector)
    output wire              m_ack_o,    // the answer it gets: ack
    output wire              m_err_o     //                     err
);

    localparam BA       = 4 + ADDR_WIDTH;     // bus address {board[3:0], word}

    // controller <-> fault injector
    wire          m_cyc, m_stb, m_we, m_ack, m_err;
    wire [BA-1:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat, m_rdat;
    // fault injector <-> bus
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
        .NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS),
        .ROM_FILE(""), .TIMEOUT(TIMEOUT), .POLL(POLL)
    ) u_ctrl (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_we_o(m_we), .m_adr_o(m_adr), .m_sel_o(m_sel),
        .m_dat_o(m_wdat), .m_dat_i(m_rdat), .m_ack_i(m_ack), .m_err_i(m_err),
        .time_o(time_o), .error_o(error_o), .rom_errors_o(rom_errors_o)
    );

    bus_fault_injector #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_faults (
        .clk_i(clk_i), .rst_i(rst_i), .fi_kind_i(fi_kind_i), .fi_dead_i(fi_dead_i),
        .c_cyc_i(m_cyc), .c_stb_i(m_stb), .c_we_i(m_we), .c_adr_i(m_adr), .c_sel_i(m_sel),
        .c_dat_i(m_wdat), .c_dat_o(m_rdat), .c_ack_o(m_ack), .c_err_o(m_err),
        .b_cyc_o(i_cyc), .b_stb_o(i_stb), .b_we_o(i_we), .b_adr_o(i_adr), .b_sel_o(i_sel),
        .b_dat_o(i_wdat), .b_dat_i(i_rdat), .b_ack_i(i_ack), .b_err_i(i_err)
    );

    albatross_bus #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_bus (
        .m_cyc_i(i_cyc), .m_stb_i(i_stb), .m_we_i(i_we), .m_adr_i(i_adr), .m_sel_i(i_sel),
        .m_dat_i(i_wdat), .m_dat_o(i_rdat), .m_ack_o(i_ack), .m_err_o(i_err),
        .s_cyc_o(s_cyc), .s_stb_o(s_stb), .s_we_o(s_we), .s_adr_o(s_adr), .s_sel_o(s_sel),
        .s_dat_o(s_wdat), .s_dat_i(s_rdat), .s_ack_i(s_ack), .s_err_i({NB{1'b0}})
    );
    assign m_cyc_o = m_cyc;
    assign m_stb_o = m_stb;
    assign m_ack_o = m_ack;
    assign m_err_o = m_err;

    genvar c;
    generate
        for (c = 0; c < NB; c = c + 1) begin : g_board
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
            assign dp_ack_o[c]                           = a_cyc & a_stb & a_ack;
            assign dp_we_o[c]                            = a_we;
            assign dp_adr_o[c*ADDR_WIDTH +: ADDR_WIDTH]  = a_adr;
            assign dp_sel_o[c*4 +: 4]                    = a_sel;

            board_core #(.SERV((SERV_MASK >> c) & 1), .CORE(c), .ADDR_WIDTH(ADDR_WIDTH),
                         .RAM_WORDS(RAM_WORDS)) u_core (
                .clk_i    (clk_i),
                .rst_i    (rst_i),
                .stall_i  (stall_i[c]),
                .wb_cyc_o (a_cyc),
                .wb_stb_o (a_stb),
                .wb_we_o  (a_we),
                .wb_adr_o (a_adr),
                .wb_sel_o (a_sel),
                .wb_dat_o (a_wdat),
                .wb_dat_i (a_rdat),
                .wb_ack_i (a_ack),
                .done_o   (done_o[c]),
                .code_o   (code_o[c*32 +: 32]),
                .stat_o   (stat_o[c*128 +: 128]),
                .ev_valid_o(ev_valid_o[c]),
                .ev_data_o(ev_data_o[c*32 +: 32]),
                .ev_arg_o (ev_arg_o[c*32 +: 32]),
                .trap_o   (trap_o[c]),
                .bus_err_o(bus_err_o[c])
            );
`ifndef SYNTHESIS  // simulation only: +ram<c>=FILE is the start image of this board's DPRAM
            reg [8*256-1:0] img_file;
            integer         have_img;
            initial begin
                case (c)
                    0:       have_img = $value$plusargs("ram0=%s", img_file);
                    1:       have_img = $value$plusargs("ram1=%s", img_file);
                    2:       have_img = $value$plusargs("ram2=%s", img_file);
                    default: have_img = $value$plusargs("ram3=%s", img_file);
                endcase
                if (have_img != 0) $readmemh(img_file, u_ram.mem);
            end
`endif
        end
    endgenerate

endmodule

`default_nettype wire
