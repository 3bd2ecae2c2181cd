// duo_system -- the FPGA demonstration as every board top uses it: the
// system of fpga/duo.toml (albatross_soc: two boards, 'sensor' = board 0
// and 'actuator' = board 1, with the sizes the compiler's images are made
// for), its reset (board_reset: power-on and the reset button) and the
// heartbeats divided for the eye (beat_divider).  A top adds only its pins
// and LED mapping.  One clock; rst_o is synchronous, active high.
`default_nettype none

module duo_system #(
    parameter ROM_FILE   = "build/fpga/duo/rom.hex",  // schedule ROM image
    parameter FW_PREFIX  = "build/fpga/duo/fw",       // board c's program: <prefix><c>.hex
    parameter RAM_PREFIX = "build/fpga/duo/ram",      // board c's DPRAM image: <prefix><c>.hex
    parameter SERV_MASK  = 0,                         // bit c: board c on SERV, else PicoRV32
    parameter BEAT_LOG2  = 0                          // beat_o changes every 2**BEAT_LOG2 heartbeats
) (
    input  wire       clk_i,
    input  wire       btn_n_i,    // reset button, active low, asynchronous
    output wire       rst_o,      // the system is in reset
    output wire [1:0] done_o,     // core c stopped (stored to TOHOST)
    output wire [1:0] err_o,      // core c reported a failed check
    output wire [1:0] trap_o,     // core c trapped
    output wire [1:0] beat_o,     // core c's heartbeat, divided
    output wire       ctrl_err_o  // the controller's ROM header is invalid
);

    wire [1:0] beat;

    board_reset u_reset (.clk_i(clk_i), .btn_n_i(btn_n_i), .rst_o(rst_o));

    // Sizes as in fpga/duo.toml (ram 1024 bytes, n_chan 4) and mk/fpga.mk (2 KiB programs).
    albatross_soc #(
        .NB(2), .ADDR_WIDTH(8), .RAM_WORDS(512), .N_CHAN(4), .ROM_WORDS(256),
        .ROM_FILE(ROM_FILE), .FW_PREFIX(FW_PREFIX), .RAM_PREFIX(RAM_PREFIX), .SERV_MASK(SERV_MASK)
    ) u_soc (
        .clk_i(clk_i), .rst_i(rst_o), .done_o(done_o), .err_o(err_o), .beat_o(beat),
        .trap_o(trap_o), .ctrl_err_o(ctrl_err_o)
    );

    beat_divider #(.LOG2(BEAT_LOG2)) u_beat0 (.clk_i(clk_i), .rst_i(rst_o), .beat_i(beat[0]), .beat_o(beat_o[0]));
    beat_divider #(.LOG2(BEAT_LOG2)) u_beat1 (.clk_i(clk_i), .rst_i(rst_o), .beat_i(beat[1]), .beat_o(beat_o[1]));

endmodule

`default_nettype wire
