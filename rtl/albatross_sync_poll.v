// albatross_sync_poll -- the position-synchronised mode's poll of
// albatross_sequencer (docs/controller.md "Execution"): after the last entry
// of a cycle it loads the SYNC source's control word every POLL clocks, and
// says when a poll shows a new position.
// Rules:
//   * capture_i (the fetch of entry 0, its last clock): the SYNC source's
//     place (board_i, base_i) is kept, and whether entry 0 is a valid SYNC
//     COPY (sync_i).  Reset clears that; the place is data.
//   * While wait_i (the sequencer waits for the cycle end) a clock counter
//     runs, POLL clocks a turn from the last entry's end (entry_over_i sets
//     it to its last value); with HAS_SYNC, a sync-mode ROM (smode_i) and a
//     valid SYNC entry, a poll (poll_cyc_o, a Wishbone classic read of the
//     control word) starts in the clock after each turn's last and ends at
//     its ack or err; a new cycle (new_cycle_i) drops it.
//   * hit_o: a poll's ack that shows a valid Actual other than sync_rl_i
//     (the position is new: the sequencer starts the next cycle).
`default_nettype none

module albatross_sync_poll #(
    parameter ADDR_WIDTH = 10, // word-address bits of a board RAM
    parameter POLL       = 16, // clocks from the start of one poll to the next, >= 2
    parameter HAS_SYNC   = 1   // 1: polls; 0: never (every cycle is H1 long)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,          // synchronous, active high
    input  wire                  capture_i,      // entry 0's fetch ends: take its place and sync_i
    input  wire                  sync_i,         // entry 0 is a valid SYNC COPY
    input  wire [3:0]            board_i,        // entry 0's source place
    input  wire [ADDR_WIDTH-1:0] base_i,
    input  wire                  smode_i,        // the ROM is position-synchronised (H0)
    input  wire                  wait_i,         // the sequencer waits for the cycle end
    input  wire                  entry_over_i,   // an entry is over (the last one: the wait begins)
    input  wire                  new_cycle_i,    // a cycle starts
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [31:0]           poll_dat_i,     // only the Actual byte is read
    /* verilator lint_on UNUSEDSIGNAL */
    input  wire                  poll_ack_i,
    input  wire                  poll_err_i,
    input  wire [1:0]            sync_rl_i,      // the SYNC channel's ReadLocked copy (0: unknown)
    output wire                  poll_cyc_o,
    output wire [3:0]            poll_board_o,
    output wire [ADDR_WIDTH-1:0] poll_adr_o,
    output wire                  hit_o           // a poll shows a new position
);

`include "albatross_contract.vh"

    localparam PC_BITS = $clog2(POLL);
    localparam integer       POLL_LAST_I = POLL - 1;
    localparam [PC_BITS-1:0] POLL_LAST   = POLL_LAST_I[PC_BITS-1:0];

    reg                  sync_ok_q;     // entry 0 is a valid SYNC COPY (this cycle)
    reg [3:0]            brd_q;
    reg [ADDR_WIDTH-1:0] base_q;
    reg [PC_BITS-1:0]    pc_q;
    reg                  poll_q;

    always @(posedge clk_i) begin
        if (!rst_i && capture_i) begin
            brd_q  <= board_i;
            base_q <= base_i;
        end
        if (!rst_i && wait_i) pc_q <= (pc_q == POLL_LAST) ? {PC_BITS{1'b0}} : pc_q + 1'b1;
        if (!rst_i && entry_over_i) pc_q <= POLL_LAST;
        if (rst_i) begin
            sync_ok_q <= 1'b0;
            poll_q    <= 1'b0;
        end else begin
            if (capture_i) sync_ok_q <= sync_i;
            if (wait_i) begin
                if (HAS_SYNC != 0 && smode_i && sync_ok_q && pc_q == POLL_LAST) poll_q <= 1'b1;
                if (poll_q && (poll_ack_i || poll_err_i)) poll_q <= 1'b0;
            end
            if (new_cycle_i) poll_q <= 1'b0;
        end
    end

    assign poll_cyc_o   = poll_q;
    assign poll_board_o = brd_q;
    assign poll_adr_o   = base_q;
    assign hit_o        = poll_q && poll_ack_i && poll_dat_i[8*ALB_CH_OFF_ACTUAL +: 8] != 8'd0 &&
                          poll_dat_i[8*ALB_CH_OFF_ACTUAL + 2 +: 6] == 6'd0 &&
                          poll_dat_i[8*ALB_CH_OFF_ACTUAL +: 2] != sync_rl_i;

endmodule

`default_nettype wire
