// albatross_seq_status -- albatross_sequencer's status counts: rom_errors,
// cycles and the running mode's start time (docs/controller.md "STATUS").
// Rules:
//   * rom_errors_o adds 1 in the clock after each err_i (an invalid or bad
//     entry's fetch, a part's first background mismatch), cycles_o in the
//     clock after each cycle_i (a cycle boundary); both are 16-bit and
//     saturate at 2^16 - 1 (the carry out of the increment says the count
//     is at its top; the event enables the register, so it is not on the
//     carry chain).
//   * since_o is time_i of the clock after commit_i (a boundary that took
//     a loaded mode, the start-up's first cycle's too): time_o in the first
//     clock of the mode's first cycle.  It holds until
//     the next such boundary.
//   * Reset (synchronous) clears the counts; since_o is first written at
//     the first cycle's start.
`default_nettype none

module albatross_seq_status (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        err_i,          // one clock: rom_errors + 1
    input  wire        cycle_i,        // one clock: a cycle boundary (cycles + 1)
    input  wire        commit_i,       // one clock: the boundary takes a loaded mode
    input  wire [31:0] time_i,         // the sequencer's global time
    output wire [15:0] rom_errors_o,
    output wire [15:0] cycles_o,
    output wire [31:0] since_o         // time_i in the first clock of the running mode's first cycle
);

    reg         switched_q;            // the boundary of the last clock took a loaded mode
    reg  [31:0] since_q;
    reg  [15:0] rerr_q, cycles_q;
    wire [16:0] rerr_inc = {1'b0, rerr_q} + 17'd1;
    wire [16:0] cyc_inc  = {1'b0, cycles_q} + 17'd1;

    always @(posedge clk_i) begin
        switched_q <= !rst_i && commit_i;
        if (switched_q) since_q <= time_i;
        if (rst_i) begin
            rerr_q   <= 16'd0;
            cycles_q <= 16'd0;
        end else begin
            if (err_i && !rerr_inc[16]) rerr_q <= rerr_inc[15:0];
            if (cycle_i && !cyc_inc[16]) cycles_q <= cyc_inc[15:0];
        end
    end

    assign rom_errors_o = rerr_q;
    assign cycles_o     = cycles_q;
    assign since_o      = since_q;

endmodule

`default_nettype wire
