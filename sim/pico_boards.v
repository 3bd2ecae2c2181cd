// pico_boards -- test top of the robot simulation (sim/mobot_sim.cpp) and of
// its Icarus bench (sim/pico_boards_tb.v): albatross_system
// (soc/albatross_system.v) with NB soft-core boards, the controller's bus
// closed through a bus_fault_injector, and the DPRAM images from plusargs.
//
// Board c: core c (PicoRV32, or SERV where SERV_MASK selects it, or VexRiscv
// where VEX_MASK does: its window and registers at 0x9/0xA000_0000; the memory
// map of soc/board_memmap.v and soc/firmware/board.h: local RAM at 0, DPRAM
// window at 0x1000_0000, board registers at 0x2000_0000 with TOHOST and
// STAT 0..3) reaches port A of its own albatross_dpram; port B hangs on
// albatross_bus, whose master is albatross_controller behind a
// bus_fault_injector (fi_kind_i / fi_dead_i as in
// tb/common/bus_fault_injector.v; 0 forwards every request unchanged).  The
// harness sees each core's board events (ev_*: a store to EVENT), each core's
// completed DPRAM accesses (dp_*: port A, one clock per acked access), and
// the controller side of the injector (m_*), and fi_new_o, high in the first
// clock of each new controller request (the clock fi_kind_i is sampled).  Everything runs on
// clk_i.  Plusargs (simulation only): +fwC=FILE the program of core C
// (board_memmap), +ramC=FILE the start image of board C's DPRAM (the
// compiler's <board>_ram.hex; read here), +rom=FILE the schedule ROM (read by
// the controller itself).  Board index c is the compiler's board index; NB is
// at most 4 (four plusarg names).  Core c uses the flattened outputs' bits
// [c*w +: w].  stall_i[c] holds core c's local-RAM accesses for a clock.
// ADDR_WIDTH 12 (16 KiB per DPRAM) serves every robot description: an image
// of a smaller RAM (ram_bytes 4096) fills the low words; the harness reads
// aw_o and refuses a plan whose ram_bytes exceeds the DPRAM.
// Local timers (simulation only, by hierarchical reference into each board's
// board_memmap; 0 under SYNTHESIS): timer_rd_o[c] is high in the clock a read
// of board c's TIMER register completes, timer_o the value it returns; the
// board's clock drift is its board_memmap's +drift<c>=PPM plusarg.
// +mute_board=B +mute_word=W (simulation only; a negative test's fault): the
// injector treats every controller store to word W of board B as a request
// to a dead link (kind 2: never performed, never answered, fi_dead_o high),
// so a destination whose control word is there is never published.
`default_nettype none

module pico_boards #(
    parameter NB         = 4,     // boards, 1..4
    parameter ADDR_WIDTH = 12,    // word-address bits of each board DPRAM (12: 16 KiB, room for the slow channels)
    parameter RAM_WORDS  = 4096,  // words of each core's local RAM (16 KiB)
    parameter N_CHAN     = 16,    // controller channel ids
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in words
    parameter TIMEOUT    = 8,     // controller access timeout, clocks
    parameter POLL       = 16,    // controller poll interval in sync mode
    parameter SERV_MASK  = 0,     // NB bits: board c's core is SERV when bit c is set, else PicoRV32
    parameter VEX_MASK   = 0      // NB bits: board c's core is VexRiscv when bit c is set (before SERV_MASK)
) (
    input  wire              clk_i,      // everything's clock
    input  wire              rst_i,      // synchronous, active high
    input  wire [NB-1:0]     stall_i,    // core c: hold its local-RAM access this cycle
    input  wire [1:0]        fi_kind_i,  // fault kind for the controller's next new request
    input  wire [NB-1:0]     fi_dead_i,  // board links that are down
    output wire              fi_new_o,   // a new controller request samples fi_kind_i in this clock
    output wire              fi_dead_o,  // ... and goes to a dead board
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
    output wire              error_o,    // controller error (invalid ROM header)
    output wire [15:0]       rom_errors_o, // invalid ROM entries skipped (counter)
    output wire              m_cyc_o,    // the controller's bus cycle (bus load figure)
    output wire              m_stb_o,    // its strobe (controller side of the injector)
    output wire              m_ack_o,    // the answer it gets: ack
    output wire              m_err_o,    //                     err
    output wire [NB-1:0]     timer_rd_o, // core c's read of its TIMER completes this clock (simulation only)
    output wire [NB*32-1:0]  timer_o,    // core c's local timer, the value such a read returns
    output wire [3:0]        mode_o,     // the controller's running schedule mode (simulation only: a probe)
    output wire [7:0]        aw_o        // ADDR_WIDTH, for the harness to check a plan's RAM against (a constant)
);

    localparam BA = 4 + ADDR_WIDTH;  // bus address {board[3:0], word}
    localparam [7:0] AW8 = ADDR_WIDTH;
    assign aw_o = AW8;

    // controller <-> fault injector
    wire          m_we;
    wire [BA-1:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat, m_rdat;
    // fault injector <-> bus
    wire          i_cyc, i_stb, i_we, i_ack, i_err;
    wire [BA-1:0] i_adr;
    wire [3:0]    i_sel;
    wire [31:0]   i_wdat, i_rdat;
    // Outputs of the system this top does not use: the external ports (there
    // are none) and port B's monitors.
    wire [NB*32-1:0]         ext_rdat, b_wdat, b_rdat;
    wire [NB-1:0]            ext_ack, b_ack, b_we;
    wire [NB*ADDR_WIDTH-1:0] b_adr;
    wire [NB*4-1:0]          b_sel;
    wire unused = &{1'b0, ext_rdat, ext_ack, b_ack, b_we, b_adr, b_sel, b_wdat, b_rdat};

    albatross_system #(
        .NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS),
        .TIMEOUT(TIMEOUT), .POLL(POLL), .SERV_MASK(SERV_MASK), .VEX_MASK(VEX_MASK),
        .BUS_HOOK(1)  // the fault injector closes the controller's bus
    ) u_sys (
        .clk_i(clk_i), .rst_i(rst_i), .cpu_clk_i(clk_i), .cpu_rst_i(rst_i), .stall_i(stall_i),
        .ext_cyc_i({NB{1'b0}}), .ext_stb_i({NB{1'b0}}), .ext_we_i({NB{1'b0}}),
        .ext_adr_i({NB*ADDR_WIDTH{1'b0}}), .ext_sel_i({NB*4{1'b0}}), .ext_dat_i({NB*32{1'b0}}),
        .ext_dat_o(ext_rdat), .ext_ack_o(ext_ack),
        .ctl_cyc_o(m_cyc_o), .ctl_stb_o(m_stb_o), .ctl_we_o(m_we), .ctl_adr_o(m_adr), .ctl_sel_o(m_sel),
        .ctl_dat_o(m_wdat), .ctl_dat_i(m_rdat), .ctl_ack_i(m_ack_o), .ctl_err_i(m_err_o),
        .bus_cyc_i(i_cyc), .bus_stb_i(i_stb), .bus_we_i(i_we), .bus_adr_i(i_adr), .bus_sel_i(i_sel),
        .bus_dat_i(i_wdat), .bus_dat_o(i_rdat), .bus_ack_o(i_ack), .bus_err_o(i_err),
        .done_o(done_o), .code_o(code_o), .stat_o(stat_o), .ev_valid_o(ev_valid_o),
        .ev_data_o(ev_data_o), .ev_arg_o(ev_arg_o), .trap_o(trap_o), .map_err_o(bus_err_o),
        .mon_a_ack_o(dp_ack_o), .mon_a_we_o(dp_we_o), .mon_a_adr_o(dp_adr_o), .mon_a_sel_o(dp_sel_o),
        .mon_b_ack_o(b_ack), .mon_b_we_o(b_we), .mon_b_adr_o(b_adr), .mon_b_sel_o(b_sel),
        .mon_b_wdat_o(b_wdat), .mon_b_rdat_o(b_rdat),
        .ctl_time_o(time_o), .ctl_error_o(error_o), .ctl_rom_errors_o(rom_errors_o)
    );

    // The running mode, read inside the controller: the harness judges every
    // age against the bounds of the mode in force (no port of the IP for it).
`ifndef SYNTHESIS
    assign mode_o = u_sys.u_ctrl.mode;
`else
    assign mode_o = 4'd0;
`endif

    // The links the injector sees as dead: fi_dead_i, and (simulation only)
    // the muted word's board while the controller requests a store to it.
    wire [NB-1:0] dead;
`ifndef SYNTHESIS
    integer  mute_board, mute_word;
    initial begin
        if (!$value$plusargs("mute_board=%d", mute_board)) mute_board = -1;
        if (!$value$plusargs("mute_word=%d", mute_word)) mute_word = -1;
        if ((mute_board >= 0 || mute_word >= 0) &&
            (mute_board < 0 || mute_board >= NB || mute_word < 0 || mute_word >= (1 << ADDR_WIDTH)))
            $display("pico_boards: +mute_board=%0d +mute_word=%0d name no word of a board RAM (boards 0..%0d, words 0..%0d): no store is muted",
                     mute_board, mute_word, NB - 1, (1 << ADDR_WIDTH) - 1);
    end
    wire          mute_on  = mute_board >= 0 && mute_board < NB && mute_word >= 0 && mute_word < (1 << ADDR_WIDTH);
    wire [BA-1:0] mute_adr = {mute_board[3:0], mute_word[ADDR_WIDTH-1:0]};
    wire          mute_hit = mute_on && m_we && m_adr == mute_adr;
    genvar        mb;
    generate
        for (mb = 0; mb < NB; mb = mb + 1) begin : g_mute
            assign dead[mb] = fi_dead_i[mb] || (mute_hit && mute_board == mb);
        end
    endgenerate
`else
    assign dead = fi_dead_i;
`endif

    bus_fault_injector #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_faults (
        .clk_i(clk_i), .rst_i(rst_i), .fi_kind_i(fi_kind_i), .fi_dead_i(dead),
        .fi_new_o(fi_new_o), .fi_dead_o(fi_dead_o),
        .c_cyc_i(m_cyc_o), .c_stb_i(m_stb_o), .c_we_i(m_we), .c_adr_i(m_adr), .c_sel_i(m_sel),
        .c_dat_i(m_wdat), .c_dat_o(m_rdat), .c_ack_o(m_ack_o), .c_err_o(m_err_o),
        .b_cyc_o(i_cyc), .b_stb_o(i_stb), .b_we_o(i_we), .b_adr_o(i_adr), .b_sel_o(i_sel),
        .b_dat_o(i_wdat), .b_dat_i(i_rdat), .b_ack_i(i_ack), .b_err_i(i_err)
    );

`ifndef SYNTHESIS  // simulation only: each board's local timer, read where board_memmap keeps it
    genvar t;
    generate
        for (t = 0; t < NB; t = t + 1) begin : g_timer
            assign timer_rd_o[t]         = u_sys.g_board[t].g_core.u_core.u_map.timer_read;
            assign timer_o[t*32 +: 32]   = u_sys.g_board[t].g_core.u_core.u_map.timer_q;
        end
    endgenerate
`else
    assign timer_rd_o = {NB{1'b0}};
    assign timer_o    = {NB*32{1'b0}};
`endif

`ifndef SYNTHESIS  // simulation only: +ram<c>=FILE is the start image of board c's DPRAM
    genvar c;
    generate
        for (c = 0; c < NB; c = c + 1) begin : g_image
            reg [8*256-1:0] img_file;
            integer         have_img;
            initial begin
                case (c)
                    0:       have_img = $value$plusargs("ram0=%s", img_file);
                    1:       have_img = $value$plusargs("ram1=%s", img_file);
                    2:       have_img = $value$plusargs("ram2=%s", img_file);
                    default: have_img = $value$plusargs("ram3=%s", img_file);
                endcase
                if (have_img != 0) $readmemh(img_file, u_sys.g_board[c].u_ram.u_core.mem);
            end
        end
    endgenerate
`endif

endmodule

`default_nettype wire
