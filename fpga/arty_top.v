// arty_top -- the FPGA demonstration on a Digilent Arty A7 (XC7A35T or
// XC7A100T, CSG324, 100 MHz oscillator; pins and clock in
// constraints/arty_a7.xdc): albatross_system with two PicoRV32 boards as on the
// iCEBreaker (fpga/icebreaker_top.v, fpga/duo.toml).  LEDs: LD4/LD5 the
// sensor's/actuator's heartbeat (beat_divider: a change every 2**BEAT_LOG2
// beats, so it blinks visibly), LD6/LD7 a core stopped; RGB LED LD0 red on
// any error (a failed check, a trap, a controller error), green while
// running.  The red RESET button (ck_rst, active low) resets.
`default_nettype none

module arty_top #(
    parameter ROM_FILE   = "build/fpga/duo/rom.hex",  // schedule ROM image
    parameter FW_PREFIX  = "build/fpga/duo/fw",       // board c's program: <prefix><c>.hex
    parameter RAM_PREFIX = "build/fpga/duo/ram",      // board c's DPRAM image: <prefix><c>.hex
    parameter BEAT_LOG2  = 7                           // heartbeat LEDs change every 2**BEAT_LOG2 beats (a blink at 100 MHz)
) (
    input  wire       clk_i,       // CLK100MHZ
    input  wire       btn_n_i,     // ck_rst, active low
    output wire [3:0] led_o,       // LD4..LD7, active high
    output wire       led0_r_o,    // RGB LED LD0, red
    output wire       led0_g_o     // RGB LED LD0, green
);

    wire       rst, ctrl_err, bad;
    wire [1:0] done, err, beat, trap;

    duo_system #(
        .ROM_FILE(ROM_FILE), .FW_PREFIX(FW_PREFIX), .RAM_PREFIX(RAM_PREFIX), .BEAT_LOG2(BEAT_LOG2)
    ) u_duo (
        .clk_i(clk_i), .cpu_clk_i(clk_i), .btn_n_i(btn_n_i), .rst_o(rst), .done_o(done), .err_o(err), .trap_o(trap),
        .beat_o(beat), .ctrl_err_o(ctrl_err)
    );

    assign bad      = |err | |trap | ctrl_err;
    assign led_o    = {done[1], done[0], beat[1], beat[0]};
    assign led0_r_o = bad;
    assign led0_g_o = ~bad & ~rst;

endmodule

`default_nettype wire
