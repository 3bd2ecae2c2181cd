// albatross_slot_timing -- albatross_sequencer's clocks: the global time,
// the time within the cycle, the slot's start S and deadline D, and the
// deadline check (docs/controller.md "Global time", "Execution").
// Rules:
//   * time_o counts clocks since reset (32 bits).  Time within a cycle
//     (rel) is TIME_BITS wide, 0 in the clock after new_cycle_i; it is kept
//     as rel + 1 (next_rel_q, rel wraps at 2^TIME_BITS), so that each compare
//     below reads a register, with no incrementer in front of it.
//   * start_o is the E1 (start) taken from rom_i at e1_i (the header's last
//     clock, FETCH clock 6: of the next entry, a mode load's first entry);
//     start_bad_o says its bits above TIME_BITS were not 0.  end_o is D in
//     rel, start + E2 (length), taken at e2_i (FETCH clock 2).  prev_end_o
//     is the end of the last slot that ran in this cycle (end_o at ran_i:
//     FETCH clock 6 of a valid, due entry), 0 from the cycle start; it is
//     TIME_BITS wide, as the entry check (FETCH clock 3) has made such an
//     end at most the cycle length, below 2^TIME_BITS.
//   * at_start_o: in ST_WAIT (wait_i), rel >= start: the clock S of the slot
//     (late only after an overrun); slot_time_o is time_o of that clock.
//     cycle_end_o: rel >= cycle_i - 1 (the running mode's H1).
//   * may_access_o is high in a clock c of a slot (run_i: go_o or the
//     transfer) when an access put on the bus in clock c+1 ends before D
//     even if it times out: c + 1 <= D - MARGIN, MARGIN = TIMEOUT + 2.  It
//     is a register decided in the clock before, from rel + 1 and D
//     (rel + 2 <= D - MARGIN, that is rel + 1 < D - MARGIN; in force only
//     in FETCH clock 6 and in the transfer, where neither a new cycle nor a
//     new D comes between), so the transfer's decisions start at a register.
//     With the entry check (D_BOUNDED 1) the compare is TIME_BITS wide: it
//     is in force only for a valid entry, whose D the check has bounded by
//     MIN_LEN > MARGIN below and by the cycle length (< 2^TIME_BITS) above,
//     so D - MARGIN neither wraps nor needs bit TIME_BITS.  Without it
//     (D_BOUNDED 0) the compare keeps bit TIME_BITS, as D is then unchecked.
//   * Reset (synchronous) clears time_o; rel, S and D are written before
//     they are used (the first cycle's start, the header's E1, the fetch).
`default_nettype none

module albatross_slot_timing #(
    parameter TIME_BITS = 16,  // bits of time within a cycle, 4..31
    parameter MARGIN    = 10,  // clocks an access needs before D: TIMEOUT + 2
    parameter D_BOUNDED = 1    // 1: the entry check bounds a running slot's D (MIN_LEN..cycle length); 0: no check
) (
    input  wire                 clk_i,
    input  wire                 rst_i,         // synchronous, active high
    input  wire [31:0]          rom_i,         // the ROM word read in the previous clock
    input  wire                 e1_i,          // rom_i is an E1: take start
    input  wire                 e2_i,          // rom_i is the fetched entry's E2: take D
    input  wire                 ran_i,         // the fetched entry is a slot of this cycle: prev_end := D
    input  wire                 wait_i,        // the sequencer waits for the slot's start
    input  wire                 run_i,         // go_o or the transfer: may_access_o in force
    input  wire                 new_cycle_i,   // a cycle starts: rel 0 in the next clock
    input  wire [TIME_BITS-1:0] cycle_i,       // the running mode's cycle length
    output wire [31:0]          time_o,        // clocks since reset
    output wire [31:0]          slot_time_o,   // S in global time
    output wire                 at_start_o,    // clock S of the slot
    output wire                 cycle_end_o,   // rel >= cycle_i - 1
    output wire                 may_access_o,  // an access begun next clock ends before D
    output wire [TIME_BITS-1:0] start_o,       // E1 last taken
    output wire                 start_bad_o,   // ... did not fit in TIME_BITS
    output wire [TIME_BITS:0]   end_o,         // D in rel
    output wire [TIME_BITS-1:0] prev_end_o     // the previous valid slot's end
);

    localparam TB = TIME_BITS;
    localparam [TB-1:0] MARGIN_T = MARGIN[TB-1:0];

    reg [31:0]   time_q;
    reg [31:0]   slot_time_q;
    reg [TB:0]   next_rel_q;    // rel + 1: the time within the cycle of the next clock
    reg [TB-1:0] start_q;
    reg          start_bad_q;
    reg [TB:0]   end_q;
    reg [TB-1:0] prev_end_q;
    reg          in_time_q;

    wire         start_now = wait_i && next_rel_q > {1'b0, start_q};   // rel >= start
    wire [TB:0]  e2_end    = {1'b0, start_q} + {1'b0, rom_i[TB-1:0]};
    wire         in_time_d;    // rel + 1 < D - MARGIN (rel this clock's)
    generate
        if (D_BOUNDED != 0) begin : g_bounded
            wire [TB-1:0] dm = end_q[TB-1:0] - MARGIN_T;   // D - MARGIN
            /* verilator lint_off UNUSEDSIGNAL */  // (only the borrow is read)
            wire [TB:0]   df = {1'b0, next_rel_q[TB-1:0]} - {1'b0, dm};
            /* verilator lint_on UNUSEDSIGNAL */
            assign in_time_d = df[TB];                     // the borrow: rel + 1 < D - MARGIN
        end else begin : g_unbounded
            assign in_time_d = {1'b0, next_rel_q[TB-1:0]} < end_q - {1'b0, MARGIN_T};
        end
    endgenerate

    always @(posedge clk_i) begin
        in_time_q <= in_time_d;
        if (rst_i) begin
            time_q     <= 32'd0;
        end else begin
            time_q     <= time_q + 32'd1;
            next_rel_q <= {1'b0, next_rel_q[TB-1:0]} + 1'b1;
            if (start_now) slot_time_q <= time_q;
            if (e1_i) begin
                start_q     <= rom_i[TB-1:0];
                start_bad_q <= rom_i[31:TB] != 0;
            end
            if (e2_i)  end_q      <= e2_end;
            if (ran_i) prev_end_q <= end_q[TB-1:0];     // (end_q <= cycle_i: bit TB is 0)
            if (new_cycle_i) begin
                next_rel_q <= {{TB{1'b0}}, 1'b1};
                prev_end_q <= {TB{1'b0}};
            end
        end
    end

    assign time_o       = time_q;
    assign slot_time_o  = slot_time_q;
    assign at_start_o   = start_now;
    assign cycle_end_o  = next_rel_q >= {1'b0, cycle_i};   // late only if a slot overran: recover
    assign may_access_o = run_i && in_time_q;              // c + 1 + MARGIN <= D (D >= MIN_LEN > MARGIN)
    assign start_o      = start_q;
    assign start_bad_o  = start_bad_q;
    assign end_o        = end_q;
    assign prev_end_o   = prev_end_q;

endmodule

`default_nettype wire
