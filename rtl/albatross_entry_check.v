// albatross_entry_check -- the field checks of albatross_sequencer's entry
// fetch (docs/controller.md "Validation"): combinational,
// one ROM word a clock of the fetch.
// Rules (bad_o high: the entry being fetched is invalid):
//   * FETCH clock 1 (E0): kind above 3; the SYNC flag on other than entry 0
//     of a sync-mode ROM with kind COPY; SYNC with FOUR_SLOT (the sync-mode
//     poll compares Actual with a three-buffer ReadLocked copy); a non-IDLE entry with ND outside
//     1..4 (a REQUEST COPY: ND not 0) or a channel id >= N_CHAN; REQUEST
//     on another kind or with SYNC; MODE on other than a STATUS with W = 2;
//     COPY with W = 0, TIME with W != 1, STATUS with W != 2*N_CHAN+1 (MODE:
//     2); or the background check's bad mark.
//   * Clock 2 (E2, length): E1 did not fit (start_bad_i), the length does
//     not fit in TIME_BITS or is below MIN_LEN, or a due entry (due_i)
//     starts before the end of the previous slot that ran in this cycle (a
//     valid, due entry's; prev_end_i: entries of disjoint due sets may share
//     a window); or the entry's E6 breaks its rules: rep above the mode's
//     cluster (cluster_i) or above MAX_REP (the sequencer's count:
//     CLUSTER_BITS).  The sequencer reads E6 ahead of the fetch and keeps
//     rep (rep_i) (rtl/albatross_minor_cycles.v).  E6's base is not checked:
//     the due test reads only its low rep bits (base < 2^rep is a rule of the
//     image that the compiler checks).  MAX_REP 0 (no minor cycles): E6 must
//     be 0 (the sequencer then gives rep 1 for any E6 other than 0).
//   * Clock 3: the slot ends after the cycle (end_i > H1; end_i is the
//     register clock 2 wrote, so no adder stands between the ROM's output
//     and this compare).
//   * Clocks 3..5 (E3..E5): a place (source of a COPY, destinations 0..ND-1)
//     with board >= NB or base + 3*(W or W+1) past 2^ADDR_WIDTH (FOUR_SLOT,
//     on any kind: 4 buffers, base + 4*(W or W+1)).
`default_nettype none

module albatross_entry_check #(
    parameter NB         = 4,    // boards on the system bus, 1..16
    parameter ADDR_WIDTH = 10,   // word-address bits of a board RAM, 3..12
    parameter N_CHAN     = 32,   // channel ids, 1..128
    parameter TIME_BITS  = 16,   // bits of time within a cycle, 4..31
    parameter MIN_LEN    = 17,   // shortest valid slot in clocks (fetch and deadline margin)
    parameter HAS_ENTRY_CHECK = 1, // 1: the field checks; 0: only the background check's bad marks
    parameter MAX_REP    = 15    // the largest rep (E6) the sequencer counts, 0..15
) (
    input  wire [2:0]           step_i,       // FETCH clock 1..5 (others: no check)
    input  wire [31:0]          rom_i,        // the ROM word of this clock
    input  wire                 ent0_i,       // the entry is entry 0
    input  wire                 smode_i,      // the ROM is position-synchronised
    input  wire                 bad_mark_i,   // the background check marked the entry bad
    input  wire [1:0]           kind_i,       // E0's kind (from clock 2 on)
    input  wire                 four_i,       // E0's FOUR_SLOT flag (from clock 2 on)
    input  wire [2:0]           nd_i,         // E0's ND (from clock 2 on)
    input  wire [13:0]          e3_i,         // 3 * W (four_i: 4 * W)
    input  wire [TIME_BITS-1:0] start_i,      // E1
    input  wire                 start_bad_i,  // E1 did not fit in TIME_BITS
    input  wire [TIME_BITS-1:0] cycle_i,      // H1
    input  wire [TIME_BITS-1:0] prev_end_i,   // the end of the previous slot run in this cycle (<= cycle_i)
    input  wire [TIME_BITS:0]   end_i,        // start + length (E2's, from clock 3 on)
    input  wire [3:0]           cluster_i,    // the running mode's cluster
    input  wire                 due_i,        // the entry is due in this cycle
    input  wire [3:0]           rep_i,        // the entry's E6 rep (MAX_REP 0: 1 when E6 is not 0)
    output reg                  bad_o
);

`include "albatross_contract.vh"

    localparam CHK = HAS_ENTRY_CHECK != 0;

    localparam TB = TIME_BITS;
    localparam integer W_STATUS_I = 2 * N_CHAN + 1;
    localparam [11:0]  W_STATUS   = W_STATUS_I[11:0];   // W of a STATUS entry
    localparam         EFLAG_SYNC = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_SYNC; // E0's SYNC flag
    localparam         EFLAG_FOUR = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_FOUR_SLOT; // E0's FOUR_SLOT flag
    localparam         EFLAG_REQUEST = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_REQUEST; // E0's REQUEST flag
    localparam         EFLAG_MODE = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_MODE; // E0's MODE flag

    // x < k for a constant k, as logic: Yosys maps a relational operator to
    // a carry chain with a LUT per bit even when one side is constant.
    function below;
        input [31:0] x;
        input [31:0] k;
        integer i;
        reg lt, eq;
        begin
            lt = 1'b0;
            eq = 1'b1;
            for (i = 31; i >= 0; i = i - 1) begin
                if (k[i] && !x[i]) lt = lt | eq;
                eq = eq & (x[i] == k[i]);
            end
            below = lt;
        end
    endfunction

    wire [3:0]  e0_kind = rom_i[ALB_ROM_E0_KIND_LSB +: 4];
    wire [3:0]  e0_nd   = rom_i[ALB_ROM_E0_ND_LSB +: 4];
    wire [7:0]  e0_id   = rom_i[ALB_ROM_E0_ID_LSB +: 8];
    wire [11:0] e0_w    = rom_i[ALB_ROM_E0_W_LSB +: 12];
    wire        e0_idle = e0_kind == ALB_KIND_IDLE;
    wire        e0_req  = rom_i[EFLAG_REQUEST];
    wire        e0_bad  = e0_kind[3:2] != 2'd0 ||
                          (rom_i[EFLAG_SYNC] && !(ent0_i && smode_i && e0_kind == ALB_KIND_COPY && !rom_i[EFLAG_FOUR] &&
                                                   !e0_req)) ||
                          (e0_req && (e0_kind != ALB_KIND_COPY || e0_nd != 4'd0)) ||
                          (!e0_idle && ((e0_nd == 4'd0 && !e0_req) || !below({28'd0, e0_nd}, 32'd5) ||
                                        !below({24'd0, e0_id}, N_CHAN))) ||
                          (e0_kind == ALB_KIND_COPY && e0_w == 12'd0) ||
                          (e0_kind == ALB_KIND_TIME && e0_w != 12'd1) ||
                          (rom_i[EFLAG_MODE] && (e0_kind != ALB_KIND_STATUS || e0_w != 12'd2)) ||
                          (e0_kind == ALB_KIND_STATUS && e0_w != W_STATUS && !rom_i[EFLAG_MODE]);
    // a < b as the borrow of a - b: a carry chain alone (Yosys maps an
    // equal-width relational operator to a carry chain and an equality tree)
    /* verilator lint_off UNUSEDSIGNAL */  // (only the borrow of each is read)
    wire [4:0]  rc_df   = {1'b0, cluster_i} - {1'b0, rep_i};          // rep > cluster: rc_df[4]
    wire [TB:0] pe_df   = {1'b0, start_i} - {1'b0, prev_end_i};       // start < prev_end: pe_df[TB]
    /* verilator lint_on UNUSEDSIGNAL */
    wire        e6_bad  = rc_df[4] || (MAX_REP < 15 && !below({28'd0, rep_i}, MAX_REP + 1));
    wire        e2_bad  = start_bad_i || rom_i[31:TB] != 0 || below({{(32-TB){1'b0}}, rom_i[TB-1:0]}, MIN_LEN) ||
                          (pe_df[TB] && due_i) || e6_bad;
    wire        end_bad = end_i > {1'b0, cycle_i};
    // base + span < 2^ADDR_WIDTH: the bits of each above ADDR_WIDTH are 0 and
    // the sum of the low ADDR_WIDTH bits has no carry out (a carry chain, no sum).
    localparam AW = ADDR_WIDTH;
    function place_ok;                 // board < NB and base + 3*stride < 2^ADDR_WIDTH
        input [15:0]   p;
        input [AW-1:0] span_lo;        // the span's low bits (the others: e3d_ok)
        reg [11:0] base;
        reg [AW:0] lo;
        begin
            base = p[ALB_ROM_PLACE_BASE_LSB +: 12];
            lo = {1'b0, base[AW-1:0]} + {1'b0, span_lo};
            place_ok = below({28'd0, p[ALB_ROM_PLACE_BOARD_LSB +: 4]}, NB) && ({4'd0, base} >> AW) == 16'd0 && !lo[AW];
        end
    endfunction
    // One span for both halves: 3 (four: 4) * W in clock 3 (the source, of
    // W words), 3 (four: 4) * (W + 1) in clocks 4 and 5 (the destinations).
    wire [13:0] e3d    = e3_i + ((step_i == 3'd3) ? 14'd0 : four_i ? 14'd4 : 14'd3);
    wire        e3d_ok = ({2'd0, e3d} >> AW) == 16'd0;
    wire        lo_ok  = e3d_ok && place_ok(rom_i[15:0], e3d[AW-1:0]);
    wire        hi_ok  = e3d_ok && place_ok(rom_i[31:16], e3d[AW-1:0]);
    always @* begin
        case (step_i)
            3'd1:    bad_o = (CHK && e0_bad) || bad_mark_i;
            3'd2:    bad_o = CHK && e2_bad;
            3'd3:    bad_o = CHK && (end_bad || (kind_i == ALB_KIND_COPY[1:0] && !lo_ok));
            3'd4:    bad_o = CHK && ((nd_i != 3'd0 && !lo_ok) || (nd_i >= 3'd2 && !hi_ok));
            3'd5:    bad_o = CHK && ((nd_i >= 3'd3 && !lo_ok) || (nd_i == 3'd4 && !hi_ok));
            default: bad_o = 1'b0;
        endcase
    end

endmodule

`default_nettype wire
