// albatross_mode_switch -- the schedule modes of albatross_sequencer
// (docs/controller.md "Modes"): which mode runs, a pending request, and the
// reads of the requested mode's descriptor before the cycle boundary.
// Rules:
//   * The running schedule: entries first_o .. end_o - 1, cycle length
//     cycle_o, drop run drop_o, and the modes it may switch to; cluster_o
//     (2^c minor cycles) is the last loaded mode's: the running one's
//     whenever the sequencer fetches an entry (a load runs only while it
//     waits for the cycle end, and the boundary takes it).  They are
//     registers that take a loaded mode's values at a cycle boundary
//     (switch_i) and change nowhere else.  The header is the load of mode 0
//     (hdr1_i: rom_i = H1, hdr2_i: rom_i = H2): the cycle and next mask of
//     H1, the drop run and the cluster of H2, entries 0 .. NE - 1 (ne_i), or
//     with H2.modes = M > 0 entries 0 .. H2.start_end - 1; the first cycle's
//     boundary takes them.  The header and descriptor words keep each of
//     these fields at the same bits, so a loaded value has one source, the
//     ROM word.  With M = 0 no request
//     is ever taken.
//   * req_i (one clock, req_mode_i): a request.  One for a mode the running
//     mode may switch to (its next mask) becomes pending, replacing a
//     pending one whose load has not begun; one for the running mode, or
//     while a load runs, is ignored; any other (a mode >= M, or a switch
//     the description does not allow) is rejected: reject_o in the clock
//     after, and the running mode goes on.
//   * The load starts in a clock with idle_i (the sequencer waits for the cycle
//     end, and waits, the boundary held, until the load is over: idle_i then
//     stays high) and takes a ROM read a clock (its word in rom_i the clock
//     after): the requested mode's D0 (its cycle and entries; read in the
//     clock the load starts), D1 (its drop run and next mask), D2 (its
//     cluster), read at read_adr_o while read_o, then E1 of its first entry
//     (e1_rd_o: the sequencer reads E1 of its entry register, which
//     first_ld_o has set to the new first entry in the clock before; e1_o
//     high while rom_i holds it: the sequencer's next start) and its E6
//     (e6_rd_o: the sequencer reads E6 of its entry register; e6_o high
//     while rom_i holds it: the due fields of the first entry).  Then it waits, loaded, for the
//     boundary: the sequencer starts no cycle while hold_o (pending, not
//     loaded), and at the boundary (switch_i) the new mode's values replace
//     the running ones (next_first_o gives the first entry of the cycle that
//     starts).  A load takes 6 clocks (hold_o low from the 6th).
//   * HAS_MODES 0: the start-up mode runs for good: no request is taken and
//     the mode table is never read (the entries, cycle, drop run and cluster
//     still come from the header).
//   * Reset clears the mode (0), the pending request and the load.
`default_nettype none

module albatross_mode_switch #(
    parameter ROM_AW    = 10,  // ROM word-address bits
    parameter TIME_BITS = 16,  // bits of a cycle length
    parameter HAS_MODES = 1    // 1: mode switches; 0: mode 0 runs for good (no request is taken, no table read)
) (
    input  wire              clk_i,
    input  wire              rst_i,          // synchronous, active high
    input  wire              hdr1_i,         // rom_i holds H1
    input  wire              hdr2_i,         // rom_i holds H2
    input  wire [7:0]        ne_i,           // H0.NE (from hdr2_i on)
    input  wire [31:0]       rom_i,          // the ROM word read in the previous clock
    input  wire              req_i,          // a mode request (one clock)
    input  wire [3:0]        req_mode_i,
    input  wire              idle_i,         // the sequencer waits for the cycle end: the ROM port is free
    input  wire              switch_i,       // the cycle boundary (new_cycle)
    output wire              read_o,         // a read of the mode table this clock
    output wire [ROM_AW-1:0] read_adr_o,
    output wire              first_ld_o,     // the sequencer's entry register takes next_first_o (the new first entry)
    output wire              e1_rd_o,        // the sequencer reads E1 of its entry register this clock
    output wire              e6_rd_o,        // the sequencer reads E6 of its entry register this clock
    output wire              e1_o,           // rom_i holds E1 of the new mode's first entry
    output wire              e6_o,           // rom_i holds E6 of the new mode's first entry
    output wire              hold_o,         // a request is pending and not loaded: no cycle start yet
    output wire              reject_o,       // one clock: a request was rejected
    output wire              commit_o,       // this boundary takes the loaded mode (switch_i with it loaded)
    output wire [3:0]        mode_o,         // the running mode
    output wire [7:0]        first_o,        // the running mode's entries first_o .. end_o - 1
    output wire [7:0]        end_o,
    output wire [7:0]        next_first_o,   // the first entry of a cycle that starts in this clock
    output wire [TIME_BITS-1:0] cycle_o,     // the running mode's cycle length
    output wire [7:0]        drop_o,         // the running mode's drop run K
    output wire [3:0]        cluster_o       // the running mode's cluster c (2^c minor cycles)
);

`include "albatross_contract.vh"

    localparam TB = TIME_BITS;
    // The load's steps, by the word each reads (its data is in rom_i in the next step).
    localparam [2:0] L_IDLE = 3'd0,   // (reads D0 in the clock the load starts)
                     L_D1 = 3'd1, L_D2 = 3'd2, L_E1 = 3'd3, L_E6 = 3'd4, L_READY = 3'd5;

    generate
        if (ALB_ROM_H1_CYCLE_LSB != ALB_ROM_D0_CYCLE_LSB || ALB_ROM_H1_NEXT_LSB != ALB_ROM_D1_NEXT_LSB ||
            ALB_ROM_H2_DROP_RUN_LSB != ALB_ROM_D1_DROP_RUN_LSB || ALB_ROM_H2_START_END_LSB != ALB_ROM_D0_END_LSB ||
            ALB_ROM_H2_CLUSTER_LSB != ALB_ROM_D2_CLUSTER_LSB || ALB_ROM_D2_CLUSTER_W != 4)
        begin : g_contract_check
            albatross_mode_switch_contract_mismatch u_error ();
        end
    endgenerate

    reg [3:0]    modes_q, mode_q, idx_q;
    reg [7:0]    table_q;
    reg          pend_q, reject_q, e6_q;
    reg [2:0]    step_q;
    // the loaded mode (n_*) and the running one
    reg [TB-1:0] n_cycle_q, cycle_q;
    reg [7:0]    n_first_q, n_end_q, n_drop_q, first_q, end_q, drop_q;
    reg [15:0]   n_next_q, next_q;            // the modes it may switch to
    reg [3:0]    n_cluster_q;

    localparam  MODES   = HAS_MODES != 0;
    wire        taken   = MODES && req_i && modes_q != 4'd0 && step_q == L_IDLE && req_mode_i != mode_q;
    wire        allowed = next_q[req_mode_i] && req_mode_i < modes_q;
    wire        commit  = switch_i && step_q == L_READY;
    wire        h2modes = rom_i[ALB_ROM_H2_MODES_LSB +: 4] != 4'd0;
    wire        start   = MODES && step_q == L_IDLE && pend_q && idle_i;   // D0 read now (the load starts unless taken)
    // rom_i holds: H1 or D0 (cycle, end, first), H1 or D1 (next), H2 or D1 (drop run), H2 or D2 (cluster)
    wire        ld_d0   = MODES && step_q == L_D1;
    wire        ld_d1   = MODES && step_q == L_D2;
    wire        ld_d2   = MODES && step_q == L_E1;
    // Descriptor idx takes the place of entry table + idx: Dj at {desc, 100} + j.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [7:0]         desc   = table_q + {4'd0, idx_q};
    wire [ROM_AW+10:0] d_adr  = {{ROM_AW{1'b0}}, desc, step_q == L_D1 ? 3'b101 : step_q == L_D2 ? 3'b110 : 3'b100};
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk_i) begin
        if (hdr1_i || ld_d0) n_cycle_q <= rom_i[ALB_ROM_D0_CYCLE_LSB +: TB];
        if (hdr1_i || ld_d1) n_next_q  <= rom_i[ALB_ROM_D1_NEXT_LSB +: 16];
        if (hdr2_i || ld_d1) n_drop_q  <= rom_i[ALB_ROM_D1_DROP_RUN_LSB +: 8];
        if (hdr2_i || ld_d0) n_end_q   <= (hdr2_i && !h2modes) ? ne_i : rom_i[ALB_ROM_D0_END_LSB +: 8];
        if (hdr2_i)     n_first_q <= 8'd0;
        else if (ld_d0) n_first_q <= rom_i[ALB_ROM_D0_FIRST_LSB +: 8];
        if (hdr2_i || ld_d2) n_cluster_q <= rom_i[ALB_ROM_D2_CLUSTER_LSB +: 4];
        if (commit) begin
            cycle_q   <= n_cycle_q;
            next_q    <= n_next_q;
            drop_q    <= n_drop_q;
            end_q     <= n_end_q;
            first_q   <= n_first_q;
        end
    end

    always @(posedge clk_i) begin
        reject_q <= 1'b0;
        e6_q     <= 1'b0;
        if (rst_i) begin
            mode_q  <= 4'd0;
            modes_q <= 4'd0;
            pend_q  <= 1'b0;
            step_q  <= L_IDLE;
        end else if (hdr2_i) begin                 // mode 0 loaded: the first boundary takes it
            modes_q <= rom_i[ALB_ROM_H2_MODES_LSB +: 4];
            table_q <= rom_i[ALB_ROM_H2_TABLE_LSB +: 8];
            idx_q   <= 4'd0;
            pend_q  <= 1'b1;
            step_q  <= L_READY;
        end else begin
            if (taken) begin
                if (allowed) begin
                    pend_q <= 1'b1;
                    idx_q  <= req_mode_i;
                end else reject_q <= 1'b1;
            end
            case (step_q)
                L_IDLE: if (start && !taken) step_q <= L_D1;   // D0 read now
                L_D1:   step_q <= L_D2;                        // D1 read now; rom_i = D0 (ld_d0)
                L_D2:   step_q <= L_E1;                        // D2 read now; rom_i = D1 (ld_d1)
                L_E1:   step_q <= L_E6;                        // E1 read now; rom_i = D2 (ld_d2)
                L_E6: begin                                    // E6 read now (e6_rd_o); rom_i = E1 (e1_o)
                    e6_q   <= 1'b1;
                    step_q <= L_READY;
                end
                default: if (switch_i) begin               // L_READY: the boundary
                    mode_q <= idx_q;
                    pend_q <= 1'b0;
                    step_q <= L_IDLE;
                end
            endcase
        end
    end

    assign read_o       = start || (MODES && (step_q == L_D1 || step_q == L_D2));
    assign read_adr_o   = d_adr[ROM_AW-1:0];
    assign first_ld_o   = ld_d1;                   // n_first_q holds the new first entry from this clock on
    assign e1_rd_o      = MODES && step_q == L_E1;
    assign e6_rd_o      = MODES && step_q == L_E6;
    assign e1_o         = MODES && step_q == L_E6;
    assign e6_o         = MODES && e6_q;
    assign hold_o       = pend_q && step_q != L_READY;
    assign reject_o     = reject_q;
    assign commit_o     = commit;
    assign mode_o       = MODES ? mode_q : 4'd0;
    assign first_o      = MODES ? first_q : 8'd0;
    assign end_o        = end_q;
    assign next_first_o = MODES ? ((commit || ld_d1) ? n_first_q : first_q) : 8'd0;
    assign cycle_o      = cycle_q;
    assign drop_o       = drop_q;
    assign cluster_o    = n_cluster_q;

endmodule

`default_nettype wire
