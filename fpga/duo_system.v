// duo_system -- the FPGA demonstration as every board top uses it: the
// system of fpga/duo.toml (soc/albatross_system.v: two soft-core boards,
// 'sensor' = board 0 and 'actuator' = board 1, with the sizes the compiler's
// images are made for; the controller drives the bus directly), its reset (board_reset: power-on and the reset button) and the
// heartbeats divided for the eye (beat_divider).  A top adds only its pins
// and LED mapping.
//
// Clocks: with CPU_CDC 0 everything runs on clk_i (cpu_clk_i unused).  With
// CPU_CDC 1 the two cores run on cpu_clk_i and reach their DPRAMs through
// albatross_wb_cdc, while the DPRAMs, the bus and the controller stay on
// clk_i (albatross_system).  The cores' reset is then the clk_i reset passed
// through a second board_reset on cpu_clk_i: it is taken on a cpu_clk_i edge
// at most 6 cpu_clk_i clocks after the clk_i reset rises (synchroniser, a
// possibly metastable first capture, the hold counter's clear, its register)
// and falls 2**4 + 3 cpu_clk_i clocks after it falls.  The clk_i reset lasts
// 15 clk_i clocks at least, so albatross_wb_cdc's reset rule (each side's
// reset is taken by the other side before it ends) holds whenever cpu_clk_i
// runs at 0.4 times clk_i's frequency or faster.  A top that derives its
// clocks from a PLL holds btn_n_i low until the PLL locks.
// rst_o (either reset, for an LED only) is active high; done_o, err_o,
// trap_o and beat_o are synchronous to the cores' clock.
`default_nettype none

module duo_system #(
    parameter ROM_FILE   = "build/fpga/duo/rom.hex",  // schedule ROM image
    parameter FW_PREFIX  = "build/fpga/duo/fw",       // board c's program: <prefix><c>.hex
    parameter RAM_PREFIX = "build/fpga/duo/ram",      // board c's DPRAM image: <prefix><c>.hex
    parameter SERV_MASK  = 0,                         // bit c: board c on SERV, else PicoRV32
    parameter BEAT_LOG2  = 0,                         // beat_o changes every 2**BEAT_LOG2 heartbeats
    parameter CPU_CDC    = 0                          // 1: the cores on cpu_clk_i, the rest on clk_i; 0: all on clk_i
) (
    input  wire       clk_i,      // DPRAMs, bus and controller (CPU_CDC 0: everything)
    input  wire       cpu_clk_i,  // the cores' clock (CPU_CDC 1 only)
    input  wire       btn_n_i,    // reset button, active low, asynchronous
    output wire       rst_o,      // the system is in reset
    output wire [1:0] done_o,     // core c stopped (stored to TOHOST)
    output wire [1:0] err_o,      // core c reported a failed check
    output wire [1:0] trap_o,     // core c trapped
    output wire [1:0] beat_o,     // core c's heartbeat, divided
    output wire       ctrl_err_o  // the controller's ROM header is invalid
);

    wire [1:0] beat;
    wire       rst, core_clk, core_rst;

    board_reset u_reset (.clk_i(clk_i), .btn_n_i(btn_n_i), .rst_o(rst));

    generate
        if (CPU_CDC != 0) begin : g_cpu_clock
            assign core_clk = cpu_clk_i;
            board_reset u_cpu_reset (.clk_i(cpu_clk_i), .btn_n_i(~rst), .rst_o(core_rst));
        end else begin : g_one_clock
            wire unused_cpu_clk = cpu_clk_i;  // the cores run on clk_i
            assign core_clk = clk_i;
            assign core_rst = rst;
        end
    endgenerate
    assign rst_o = rst | core_rst;

    // Sizes as in fpga/duo.toml (ram 1024 bytes, n_chan 4) and tools/mk/fpga.mk (2 KiB programs).
    wire [63:0]  code /* verilator public_flat_rd */;   // also read by the simulation harness
    wire [255:0] stat;
    // Each board's DPRAM port A (its core's side) as the DPRAM performs it:
    // read by the simulation harness (fpga/test_fpga_soc.cpp), which counts the
    // sensor's accesses per GlobalTime Import; nothing else uses them.
    wire [1:0]  mon_ack /* verilator public_flat_rd */;
    wire [1:0]  mon_we  /* verilator public_flat_rd */;
    wire [15:0] mon_adr /* verilator public_flat_rd */;
    wire [7:0]  mon_sel;
    wire        mon_clk /* verilator public_flat_rd */;   // the DPRAMs' clock: mon_* change with it
    assign mon_clk = clk_i;
    wire unused_mon = &{1'b0, mon_ack, mon_we, mon_adr, mon_sel, mon_clk};
    wire unused_stat = &{1'b0, stat[255:129], stat[127:1]};  // the heartbeat is STAT 0 bit 0
    albatross_system #(
        .NB(2), .ADDR_WIDTH(8), .RAM_WORDS(512), .N_CHAN(4), .ROM_WORDS(256),
        .ROM_FILE(ROM_FILE), .FW_PREFIX(FW_PREFIX), .RAM_PREFIX(RAM_PREFIX), .SERV_MASK(SERV_MASK),
        .SMALL(1), .CPU_CDC(CPU_CDC),
        // fpga/duo.toml is time-rigid, single-rate, its values go whole, and it
        // has no STATUS channel and no modes: the controller leaves out the
        // counters, the sync poll, the mode switch, the minor-cycle count and
        // the fragments' progress RAM (with them two PicoRV32 boards do not
        // fit the iCEBreaker's UP5K: its block RAMs run out).
        .CTRL_HAS_STATUS(0), .CTRL_HAS_SYNC(0), .CTRL_HAS_MODES(0),
        .CTRL_HAS_FRAGMENTS(0), .CTRL_HAS_MULTIRATE(0)
    ) u_sys (
        .clk_i(clk_i), .rst_i(rst), .cpu_clk_i(core_clk), .cpu_rst_i(core_rst), .stall_i(2'b00),
        .ext_cyc_i(2'b00), .ext_stb_i(2'b00), .ext_we_i(2'b00), .ext_adr_i(16'd0), .ext_sel_i(8'd0),
        .ext_dat_i(64'd0),
        .ctl_dat_i(32'd0), .ctl_ack_i(1'b0), .ctl_err_i(1'b0),          // BUS_HOOK 0: unused
        .bus_cyc_i(1'b0), .bus_stb_i(1'b0), .bus_we_i(1'b0), .bus_adr_i(12'd0), .bus_sel_i(4'd0),
        .bus_dat_i(32'd0),
        .done_o(done_o), .code_o(code), .stat_o(stat), .trap_o(trap_o), .ctl_error_o(ctrl_err_o),
        // Outputs for simulation harnesses: none used here.
        /* verilator lint_off PINCONNECTEMPTY */
        .ext_dat_o(), .ext_ack_o(),
        .ctl_cyc_o(), .ctl_stb_o(), .ctl_we_o(), .ctl_adr_o(), .ctl_sel_o(), .ctl_dat_o(),
        .bus_dat_o(), .bus_ack_o(), .bus_err_o(),
        .ev_valid_o(), .ev_data_o(), .ev_arg_o(), .map_err_o(),
        .mon_a_ack_o(mon_ack), .mon_a_we_o(mon_we), .mon_a_adr_o(mon_adr), .mon_a_sel_o(mon_sel),
        .mon_b_ack_o(), .mon_b_we_o(), .mon_b_adr_o(), .mon_b_sel_o(), .mon_b_wdat_o(), .mon_b_rdat_o(),
        .ctl_time_o(), .ctl_rom_errors_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign err_o  = done_o & {|code[63:32], |code[31:0]};  // stopped with a non-zero exit code
    assign beat   = {stat[128], stat[0]};                     // STAT 0 bit 0: the firmware's heartbeat

    beat_divider #(.LOG2(BEAT_LOG2)) u_beat0 (.clk_i(core_clk), .rst_i(core_rst), .beat_i(beat[0]), .beat_o(beat_o[0]));
    beat_divider #(.LOG2(BEAT_LOG2)) u_beat1 (.clk_i(core_clk), .rst_i(core_rst), .beat_i(beat[1]), .beat_o(beat_o[1]));

endmodule

`default_nettype wire
