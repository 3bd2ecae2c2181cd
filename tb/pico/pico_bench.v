// pico_bench -- bench top: one board core (board_core: a PicoRV32; SERV = 1: a
// SERV core; VEX = 1: a VexRiscv with caches, its window and registers uncached
// at 0x9/0xA000_0000; with the board memory map of soc/firmware/board.h) on
// port A of one albatross_dpram; port B is idle, so
// every DPRAM access takes its undisturbed time.  The firmware
// (tb/pico/firmware/bench.c, loaded from +fw0=FILE) measures cycles with rdcycle and
// reports each figure as a board EVENT (ARG = value, EVENT = key), which the
// harness (tb/pico/bench_pico.cpp) collects from ev_valid_o / ev_data_o /
// ev_arg_o.  Clock and reset (synchronous, active high) are shared.
`default_nettype none

module pico_bench #(
    parameter ADDR_WIDTH = 10,   // word-address bits of the DPRAM
    parameter RAM_WORDS  = 4096, // words of the core's local RAM (16 KiB)
    parameter SERV       = 0,    // 1: the core is SERV (soc/serv_core.v), 0: PicoRV32
    parameter VEX        = 0     // 1: the core is VexRiscv (soc/vexriscv_core.v), whatever SERV is
) (
    input  wire        clk_i,
    input  wire        rst_i,       // synchronous, active high
    output wire        done_o,      // the core stored to TOHOST
    output wire [31:0] code_o,      // the value it stored (exit code)
    output wire        ev_valid_o,  // a store to EVENT, this clock
    output wire [31:0] ev_data_o,   // its value (the key)
    output wire [31:0] ev_arg_o,    // ARG at that time (the figure)
    output wire        trap_o,      // PicoRV32 trapped
    output wire        bus_err_o    // an access to an unmapped address
);

    wire                  wb_cyc, wb_stb, wb_we, wb_ack;
    wire [ADDR_WIDTH-1:0] wb_adr;
    wire [3:0]            wb_sel;
    wire [31:0]           wb_wdat, wb_rdat, b_rdat;
    wire                  b_ack;
    wire [127:0]          stat;
    wire unused_bench = &{1'b0, b_rdat, b_ack, stat};

    albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH)) u_dpram (
        .clk_i  (clk_i),
        .rst_i  (rst_i),
        .a_cyc_i(wb_cyc), .a_stb_i(wb_stb), .a_we_i(wb_we), .a_adr_i(wb_adr),
        .a_sel_i(wb_sel), .a_dat_i(wb_wdat), .a_dat_o(wb_rdat), .a_ack_o(wb_ack),
        .b_cyc_i(1'b0), .b_stb_i(1'b0), .b_we_i(1'b0), .b_adr_i({ADDR_WIDTH{1'b0}}),
        .b_sel_i(4'h0), .b_dat_i(32'd0), .b_dat_o(b_rdat), .b_ack_o(b_ack)
    );

    board_core #(.SERV(SERV), .VEX(VEX), .CORE(0), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS)) u_core (
        .clk_i     (clk_i),
        .rst_i     (rst_i),
        .stall_i   (1'b0),
        .wb_cyc_o  (wb_cyc),
        .wb_stb_o  (wb_stb),
        .wb_we_o   (wb_we),
        .wb_adr_o  (wb_adr),
        .wb_sel_o  (wb_sel),
        .wb_dat_o  (wb_wdat),
        .wb_dat_i  (wb_rdat),
        .wb_ack_i  (wb_ack),
        .done_o    (done_o),
        .code_o    (code_o),
        .stat_o    (stat),
        .ev_valid_o(ev_valid_o),
        .ev_data_o (ev_data_o),
        .ev_arg_o  (ev_arg_o),
        .trap_o    (trap_o),
        .bus_err_o (bus_err_o)
    );

endmodule

`default_nettype wire
