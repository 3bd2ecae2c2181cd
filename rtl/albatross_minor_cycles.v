// albatross_minor_cycles -- albatross_sequencer's minor-cycle count and the
// due test of the entry it fetches next (docs/controller.md "Minor cycles").
// Rules:
//   * n_q counts the minor cycles of the entry the sequencer's entry register
//     names: 0 after reset and after clear_i (the mode load's new first
//     entry), + 1 modulo 2^CLUSTER_BITS at step_i (the entry register wraps
//     to the mode's first entry).  As 2^c divides 2^CLUSTER_BITS, n_q mod 2^c
//     is the contract's count (which wraps at 2^c, c the running mode's
//     cluster) and n_q mod 2^rep its residue for every rep <= c: no compare
//     with the cluster, the count wraps by its width.
//   * E6 of that entry arrives in rom_i: in the clock after e6_hdr_i (read
//     after the start-up pass) or e6_fetch_i (read in FETCH clock 6), or with
//     e6_mode_i (the mode load's).  In that clock the due test is made and
//     kept, with what the entry check needs of E6, until the next E6: due_o
//     (n mod 2^rep = base mod 2^rep, i.e. the low rep bits of n_q and base
//     agree: base's higher bits are not read; base < 2^rep is a rule of the
//     image, checked by the compiler, not here) and rep_o.
//   * HAS_MULTIRATE 0: no count; every entry is due (due_o = 1) and E6 must
//     be 0: rep_o is 1 when E6's base or rep is not 0 (else 0), so the entry
//     check's rule rep <= MAX_REP (its MAX_REP is 0) rejects it.  With
//     HAS_E6_CHECK 0 too, nothing of E6 is kept (rep_o 0).
//   * Reset (synchronous) clears the count and the E6 strobes.
`default_nettype none

module albatross_minor_cycles #(
    parameter HAS_MULTIRATE = 1,  // 1: the count and the due test; 0: every entry due
    parameter HAS_E6_CHECK  = 1,  // 1: rep_o for the entry check; 0: not used
    parameter CLUSTER_BITS  = 15  // bits of the count, 1..15
) (
    input  wire        clk_i,
    input  wire        rst_i,         // synchronous, active high
    input  wire        step_i,        // the entry register wraps to the mode's first entry: count + 1
    input  wire        clear_i,       // the mode load's new first entry: count 0
    input  wire        e6_hdr_i,      // E6 of entry 0 is read now (after the start-up pass)
    input  wire        e6_fetch_i,    // E6 of the next entry is read now (FETCH clock 6)
    input  wire        e6_mode_i,     // rom_i holds E6 of the new mode's first entry
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [31:0] rom_i,         // the ROM word read in the previous clock (E6's fields only)
    /* verilator lint_on UNUSEDSIGNAL */
    output wire        due_o,         // the entry is due in the minor cycle it runs in
    output wire [3:0]  rep_o          // its E6 rep
);

`include "albatross_contract.vh"

    localparam CB = CLUSTER_BITS;
    localparam MR = HAS_MULTIRATE != 0;
    localparam KEEP = MR || HAS_E6_CHECK != 0;

    reg           due_q;
    reg  [3:0]    rep_q;                     // E6's rep (the entry check's)
    reg  [CB-1:0] n_q;
    reg           e6_hdr_q, e6_fetch_q;      // rom_i holds E6 read after the start-up pass / by FETCH clock 6
    wire [3:0]    e6_rep  = rom_i[ALB_ROM_E6_REP_LSB +: 4];
    wire [14:0]   e6_base = rom_i[ALB_ROM_E6_BASE_LSB +: 15];
    // due: the low rep bits of n and base agree (agree[i]: bits 0 .. i-1 agree)
    reg  [15:0]   agree;
    integer       ai;
    always @* begin
        agree[0] = 1'b1;
        for (ai = 1; ai < 16; ai = ai + 1)
            agree[ai] = agree[ai-1] && (ai > CB || n_q[(ai > CB ? CB : ai) - 1] == e6_base[ai-1]);
    end
    always @(posedge clk_i) begin
        e6_hdr_q   <= !rst_i && e6_hdr_i && KEEP;
        e6_fetch_q <= !rst_i && e6_fetch_i && KEEP;
        if (e6_hdr_q || e6_fetch_q || (e6_mode_i && KEEP)) begin
            due_q    <= !MR || agree[e6_rep];
            rep_q    <= MR ? e6_rep : {3'd0, e6_rep != 4'd0 || e6_base != 15'd0};
        end
    end
    always @(posedge clk_i) begin
        if (rst_i || !MR)  n_q <= {CB{1'b0}};
        else if (clear_i)  n_q <= {CB{1'b0}};
        else if (step_i)   n_q <= n_q + 1'b1;                           // the next cycle's count
    end

    assign due_o  = !MR || due_q;
    assign rep_o  = KEEP ? rep_q : 4'd0;

endmodule

`default_nettype wire
