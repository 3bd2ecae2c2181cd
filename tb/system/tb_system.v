// tb_system -- multi-board test top: albatross_system (soc/albatross_system.v)
// with every board external, and bus_fault_injector closing its bus hook.
//
// Each board b is an albatross_dpram.  Its port A is the CPU port, exposed as
// cpu_*[b] (albatross_system's ext_* ports, EXT_MASK all ones); its port B
// hangs on albatross_bus.  bus_fault_injector sits between
// albatross_controller and the bus (BUS_HOOK 1).  Everything runs on clk_i:
// the harness drives the CPU ports, the fault inputs and the clock.  Rules:
//   * Flattened vectors: board b uses bits [b*w +: w] of a w-bit field.
//   * cpu_*[b] is albatross_dpram's port A itself: its timing (an ack 1 or 2
//     clocks after the request, one access per request while cyc & stb).
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
    input  wire                       clk_i,        // everything's clock
    input  wire                       rst_i,        // synchronous, active high
    // CPU side of every board's port A (Wishbone B4 classic slave)
    input  wire [NB-1:0]              cpu_cyc_i,    // cycle
    input  wire [NB-1:0]              cpu_stb_i,    // strobe
    input  wire [NB-1:0]              cpu_we_i,     // write enable
    input  wire [NB*ADDR_WIDTH-1:0]   cpu_adr_i,    // word address
    input  wire [NB*4-1:0]            cpu_sel_i,    // byte lanes
    input  wire [NB*32-1:0]           cpu_dat_i,    // write data
    output wire [NB*32-1:0]           cpu_dat_o,    // read data
    output wire [NB-1:0]              cpu_ack_o,    // acknowledge
    // fault injection (tb/common/bus_fault_injector.v)
    input  wire [1:0]                 fi_kind_i,    // fault kind for the controller's next new request
    input  wire [NB-1:0]              fi_dead_i,    // board links that are down
    output wire                       fi_new_o,     // a new controller request samples fi_kind_i now
    output wire                       fi_dead_o,    // ... and goes to a dead board
    // every RAM's port B as performed (valid while mon_ack_o[b])
    output wire [NB-1:0]              mon_ack_o,    // the RAM performed an access (previous clock)
    output wire [NB-1:0]              mon_we_o,     // ... a write
    output wire [NB*ADDR_WIDTH-1:0]   mon_adr_o,    // its word address
    output wire [NB*4-1:0]            mon_sel_o,    // its byte lanes
    output wire [NB*32-1:0]           mon_wdat_o,   // its write data
    output wire [NB*32-1:0]           mon_rdat_o,   // the read data
    // the controller's bus as it sees it
    output wire                       bus_cyc_o,    // cycle
    output wire                       bus_stb_o,    // strobe
    output wire                       bus_we_o,     // write enable
    output wire [ADDR_WIDTH+3:0]      bus_adr_o,    // {board[3:0], word}
    output wire [3:0]                 bus_sel_o,    // byte lanes
    output wire [31:0]                bus_wdat_o,   // write data
    output wire [31:0]                bus_rdat_o,   // the read data it samples with ack
    output wire                       bus_ack_o,    // the ack it samples (after the injector)
    output wire                       bus_err_o,    // the err it samples (after the injector)
    // controller status
    output wire [31:0]                time_o,       // global time
    output wire                       error_o,      // invalid ROM header
    output wire [15:0]                rom_errors_o, // invalid entries skipped (counter)
    output wire [3:0]                 mode_o,       // the controller's running schedule mode (a probe)
    output wire                       cycle_o       // one clock: a minor cycle starts (a probe)
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
    // Outputs of the system this top does not use: the cores' (there are
    // none) and port A's monitors (the harness drives port A itself).
    wire [NB-1:0]            done, trap, map_err, ev_valid, a_ack, a_we;
    wire [NB*32-1:0]         code, ev_data, ev_arg;
    wire [NB*128-1:0]        stat;
    wire [NB*ADDR_WIDTH-1:0] a_adr;
    wire [NB*4-1:0]          a_sel;
    wire unused = &{1'b0, done, trap, map_err, ev_valid, a_ack, a_we, code, ev_data, ev_arg,
                    stat, a_adr, a_sel};

    albatross_system #(
        .NB         (NB),
        .ADDR_WIDTH (ADDR_WIDTH),
        .N_CHAN     (N_CHAN),
        .ROM_WORDS  (ROM_WORDS),
        .ROM_FILE   (ROM_FILE),
        .TIMEOUT    (TIMEOUT),
        .POLL       (POLL),
        .EXT_MASK   ((1 << NB) - 1),   // every board's port A is cpu_*
        .BUS_HOOK   (1)                // the injector closes the controller's bus
    ) u_sys (
        .clk_i            (clk_i),
        .rst_i            (rst_i),
        .cpu_clk_i        (clk_i),
        .cpu_rst_i        (rst_i),
        .stall_i          ({NB{1'b0}}),
        .ext_cyc_i        (cpu_cyc_i),
        .ext_stb_i        (cpu_stb_i),
        .ext_we_i         (cpu_we_i),
        .ext_adr_i        (cpu_adr_i),
        .ext_sel_i        (cpu_sel_i),
        .ext_dat_i        (cpu_dat_i),
        .ext_dat_o        (cpu_dat_o),
        .ext_ack_o        (cpu_ack_o),
        .ctl_cyc_o        (c_cyc),
        .ctl_stb_o        (c_stb),
        .ctl_we_o         (c_we),
        .ctl_adr_o        (c_adr),
        .ctl_sel_o        (c_sel),
        .ctl_dat_o        (c_wdat),
        .ctl_dat_i        (c_rdat),
        .ctl_ack_i        (c_ack),
        .ctl_err_i        (c_err),
        .bus_cyc_i        (i_cyc),
        .bus_stb_i        (i_stb),
        .bus_we_i         (i_we),
        .bus_adr_i        (i_adr),
        .bus_sel_i        (i_sel),
        .bus_dat_i        (i_wdat),
        .bus_dat_o        (i_rdat),
        .bus_ack_o        (i_ack),
        .bus_err_o        (i_err),
        .done_o           (done),
        .code_o           (code),
        .stat_o           (stat),
        .ev_valid_o       (ev_valid),
        .ev_data_o        (ev_data),
        .ev_arg_o         (ev_arg),
        .trap_o           (trap),
        .map_err_o        (map_err),
        .mon_a_ack_o      (a_ack),
        .mon_a_we_o       (a_we),
        .mon_a_adr_o      (a_adr),
        .mon_a_sel_o      (a_sel),
        .mon_b_ack_o      (mon_ack_o),
        .mon_b_we_o       (mon_we_o),
        .mon_b_adr_o      (mon_adr_o),
        .mon_b_sel_o      (mon_sel_o),
        .mon_b_wdat_o     (mon_wdat_o),
        .mon_b_rdat_o     (mon_rdat_o),
        .ctl_time_o       (time_o),
        .ctl_error_o      (error_o),
        .ctl_rom_errors_o (rom_errors_o)
    );

    // The running mode, read inside the controller (simulation only: the IP
    // has no port for it); the harness times every switch with it.
`ifndef SYNTHESIS
    assign mode_o = u_sys.u_ctrl.mode;
    assign cycle_o = u_sys.u_ctrl.u_seq.cycle_o;   // the sequencer's port: the controller need not use it
`else
    assign mode_o = 4'd0;
    assign cycle_o = 1'b0;
`endif

    bus_fault_injector #(
        .NB         (NB),
        .ADDR_WIDTH (ADDR_WIDTH)
    ) u_fi (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .fi_kind_i (fi_kind_i),
        .fi_dead_i (fi_dead_i),
        .fi_new_o  (fi_new_o),
        .fi_dead_o (fi_dead_o),
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

    assign bus_cyc_o = c_cyc;
    assign bus_stb_o = c_stb;
    assign bus_we_o  = c_we;
    assign bus_adr_o = c_adr;
    assign bus_sel_o = c_sel;
    assign bus_wdat_o = c_wdat;
    assign bus_rdat_o = c_rdat;
    assign bus_ack_o = c_ack;
    assign bus_err_o = c_err;

endmodule

`default_nettype wire
