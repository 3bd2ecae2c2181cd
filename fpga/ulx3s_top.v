// ulx3s_top -- the FPGA demonstration on a ULX3S (ECP5 LFE5U-85F/45F/25F/12F,
// CABGA381, 25 MHz oscillator; pins in constraints/ulx3s.lpf): albatross_system
// with two PicoRV32 boards as on the iCEBreaker (fpga/icebreaker_top.v,
// fpga/duo.toml).  LEDs: led[0]/led[1] the sensor's/actuator's heartbeat
// (beat_divider: a change every 2**BEAT_LOG2 beats, so it blinks visibly),
// led[2]/led[3] a core stopped, led[4] a failed check, led[5] a trap,
// led[6] a controller error, led[7] reset.  btn[0] (PWR, active low) resets.
// wifi_gpio0 is held high so that the board's ESP32 leaves the FPGA alone.
// Clocks: the PLL (EHXPLLL) makes 50 MHz for the two PicoRV32 cores and
// 25 MHz for the DPRAMs, the bus and the controller, which the cores reach
// through albatross_wb_cdc (duo_system with CPU_CDC 1): the controller's
// speed never limits the cores' clock.  The system stays in reset until the
// PLL locks.  (fpga/EHXPLLL.v is the simulation model.)
`default_nettype none

module ulx3s_top #(
    parameter ROM_FILE   = "build/fpga/duo/rom.hex",  // schedule ROM image
    parameter FW_PREFIX  = "build/fpga/duo/fw",       // board c's program: <prefix><c>.hex
    parameter RAM_PREFIX = "build/fpga/duo/ram",      // board c's DPRAM image: <prefix><c>.hex
    parameter BEAT_LOG2  = 6                           // heartbeat LEDs change every 2**BEAT_LOG2 beats (a blink at 50 MHz)
) (
    input  wire       clk_i,         // clk_25mhz
    input  wire       btn_n_i,       // btn[0], active low
    output wire [7:0] led_o,         // led[7:0], active high
    output wire       wifi_gpio0_o   // ESP32 GPIO0: 1 keeps it from resetting the FPGA
);

    wire       rst, ctrl_err, cpu_clk, bus_clk, locked;
    wire [1:0] done, err, beat, trap;

    // 25 MHz in, VCO 600 MHz: CLKOP = 600 / 12 = 50 MHz (fed back: 25 * 2),
    // CLKOS = 600 / 24 = 25 MHz.
    EHXPLLL #(
        .CLKI_DIV(1), .CLKFB_DIV(2), .FEEDBK_PATH("CLKOP"),
        .CLKOP_DIV(12), .CLKOP_CPHASE(5),
        .CLKOS_ENABLE("ENABLED"), .CLKOS_DIV(24), .CLKOS_CPHASE(5)
    ) u_pll (
        .CLKI(clk_i), .CLKFB(cpu_clk), .RST(1'b0), .STDBY(1'b0), .PHASESEL0(1'b0), .PHASESEL1(1'b0),
        .PHASEDIR(1'b1), .PHASESTEP(1'b1), .PHASELOADREG(1'b1), .PLLWAKESYNC(1'b0), .ENCLKOP(1'b0),
        .CLKOP(cpu_clk), .CLKOS(bus_clk), .LOCK(locked)
    );

    duo_system #(
        .ROM_FILE(ROM_FILE), .FW_PREFIX(FW_PREFIX), .RAM_PREFIX(RAM_PREFIX), .BEAT_LOG2(BEAT_LOG2),
        .CPU_CDC(1)
    ) u_duo (
        .clk_i(bus_clk), .cpu_clk_i(cpu_clk), .btn_n_i(btn_n_i & locked), .rst_o(rst), .done_o(done),
        .err_o(err), .trap_o(trap), .beat_o(beat), .ctrl_err_o(ctrl_err)
    );

    assign led_o        = {rst, ctrl_err, |trap, |err, done[1], done[0], beat[1], beat[0]};
    assign wifi_gpio0_o = 1'b1;

endmodule

`default_nettype wire
