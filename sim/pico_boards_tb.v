// pico_boards_tb -- a self-clocked test bench of pico_boards for event-driven
// simulators (Icarus Verilog): the same four-board system that
// sim/mobot_sim.cpp drives under Verilator, here with its clock, reset and
// end in Verilog, so the two simulators can be compared on one workload
// (make bench-sim-speed).  No faults, no stalls.  Plusargs: those of
// pico_boards (+fw0..3, +ram0..3, +rom) and +cycles=N (default 20000): the
// run ends after N clocks with a line giving the cycles, the controller time
// and the boards that reported done.  Timing: 10 ns clock, reset for 8 clocks.
`default_nettype none
`timescale 1ns/1ps

module pico_boards_tb;

    reg         clk_q = 1'b0;
    reg         rst_q = 1'b1;
    wire [3:0]  done, trap, bus_err, ev_valid, dp_ack, dp_we;
    wire [127:0] code, ev_data, ev_arg;
    wire [511:0] stat;
    wire [47:0] dp_adr;     // NB x ADDR_WIDTH (12)
    wire [7:0]  aw;
    wire [15:0] dp_sel, rom_errors;
    wire [31:0] time_now;
    wire [3:0]  timer_rd;
    wire [127:0] timer;
    wire [3:0]  mode;
    wire        error, m_cyc, m_stb, m_ack, m_err, fi_new, fi_dead;
    // Outputs this bench does not look at (it only measures speed).
    wire unused = &{1'b0, ev_valid, dp_ack, dp_we, code, ev_data, ev_arg, stat, dp_adr, dp_sel,
                    rom_errors, m_cyc, m_stb, m_ack, m_err, fi_new, fi_dead, timer_rd, timer, mode, aw};

    pico_boards u_dut (
        .clk_i(clk_q), .rst_i(rst_q), .stall_i(4'd0), .fi_kind_i(2'd0), .fi_dead_i(4'd0),
        .fi_new_o(fi_new), .fi_dead_o(fi_dead),
        .done_o(done), .code_o(code), .stat_o(stat), .ev_valid_o(ev_valid), .ev_data_o(ev_data),
        .ev_arg_o(ev_arg), .dp_ack_o(dp_ack), .dp_we_o(dp_we), .dp_adr_o(dp_adr), .dp_sel_o(dp_sel),
        .trap_o(trap), .bus_err_o(bus_err), .time_o(time_now), .error_o(error),
        .rom_errors_o(rom_errors), .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_ack_o(m_ack), .m_err_o(m_err),
        .timer_rd_o(timer_rd), .timer_o(timer), .mode_o(mode), .aw_o(aw)
    );

    always #5 clk_q <= ~clk_q;

    integer cycles, n;
    initial begin
        if (!$value$plusargs("cycles=%d", cycles)) cycles = 20000;
        for (n = 0; n < 8; n = n + 1) @(posedge clk_q);
        rst_q = 1'b0;
        for (n = 0; n < cycles; n = n + 1) @(posedge clk_q);
        $display("pico_boards_tb: %0d cycles, controller time %0d, done %b, trap %b, bus error %b, error %b",
                 cycles, time_now, done, trap, bus_err, error);
        $finish;
    end

endmodule

`default_nettype wire
