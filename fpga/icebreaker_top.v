// icebreaker_top -- the FPGA demonstration on an iCEBreaker (iCE40UP5K-SG48,
// 12 MHz oscillator; pins in constraints/icebreaker.pcf): albatross_system with
// two boards, 'sensor' (board 0, a SERV core) exporting Sample and
// 'actuator' (board 1, a PicoRV32) importing and checking it (fpga/duo.toml,
// fpga/firmware/duo_*.c).  The bit-serial SERV sensor shows the two sides of
// a channel at very different speeds; SERV_MASK 0 puts both boards on
// PicoRV32, which also fits the UP5K (test-fpga-icebreaker-pico2).
// LEDs (the PMOD2 snap-off and the two on-board LEDs): LED1/LED2 blink with
// the sensor's/actuator's heartbeat (every 256 Exports / New Imports), LED3
// and LED4 light when a core stopped, LED5 on a controller error; the green
// on-board LED is the actuator's heartbeat, the red one lights on any error
// (a failed check, a trap, a controller error).  BTN_N resets everything.
`default_nettype none

module icebreaker_top #(
    parameter ROM_FILE   = "build/fpga/duo/rom.hex",  // schedule ROM image
    parameter FW_PREFIX  = "build/fpga/duo/fw",       // board c's program: <prefix><c>.hex
    parameter RAM_PREFIX = "build/fpga/duo/ram",      // board c's DPRAM image: <prefix><c>.hex
    parameter SERV_MASK  = 1                          // board 0 (sensor) on SERV; 0: both on PicoRV32
) (
    input  wire clk_i,      // 12 MHz
    input  wire btn_n_i,    // BTN_N, active low
    output wire led_r_n_o,  // LEDR_N, active low
    output wire led_g_n_o,  // LEDG_N, active low
    output wire [4:0] led_o // PMOD2 LED1..LED5, active high
);

    wire       ctrl_err;
    wire [1:0] done, err, beat, trap;

    // The heartbeat blinks visibly at 12 MHz as it is (BEAT_LOG2 0).  No LED
    // is left for the reset state.
    duo_system #(
        .ROM_FILE(ROM_FILE), .FW_PREFIX(FW_PREFIX), .RAM_PREFIX(RAM_PREFIX), .SERV_MASK(SERV_MASK)
    ) u_duo (
        .clk_i(clk_i), .cpu_clk_i(clk_i), .btn_n_i(btn_n_i),
        /* verilator lint_off PINCONNECTEMPTY */
        .rst_o(),
        /* verilator lint_on PINCONNECTEMPTY */
        .done_o(done), .err_o(err), .trap_o(trap), .beat_o(beat), .ctrl_err_o(ctrl_err)
    );

    assign led_o     = {ctrl_err, done[1], done[0], beat[1], beat[0]};
    assign led_g_n_o = ~beat[1];
    assign led_r_n_o = ~(|err | |trap | ctrl_err);

endmodule

`default_nettype wire
