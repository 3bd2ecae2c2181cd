// fmode_switch -- formal harness of albatross_mode_switch: every input free
// (the ROM word, the requests, the sequencer's idle clocks and its cycle
// boundaries), reset in the first clock, the header (H1 then H2) read once
// before any request, as the sequencer reads it; as the sequencer does, an
// idle stretch lasts until a boundary, and no boundary comes while hold_o.
// Proves by k-induction:
//   base_at_boundary  the running schedule (first_o, end_o, cycle_o, drop_o)
//                     and mode_o change only in the clock after a cycle
//                     boundary with a loaded mode (switch_i), or after the
//                     header;
//   cluster_at_load   cluster_o (the loaded mode's) changes only after the
//                     header or a load's D2 data (step L_E1);
//   declared_mode     with M = H2.modes > 0 the running mode is below M;
//                     without modes it stays 0 and no request is taken (the
//                     header's load of mode 0 is the only one);
//   allowed_switch    a switch goes to a mode the running one may switch to
//                     (its next mask: H1.next, then the loaded D1.next);
//   no_hold_idle      without a pending request nothing holds the boundary;
//   reads_when_idle   the mode table (and, by the sequencer, the first
//                     entry's E1 and E6) is read only in idle clocks;
//   e1_after_first    the sequencer's E1 read comes in the clock after it
//                     took the new first entry (first_ld_o);
//   e6_after_first    the sequencer's E6 read comes two clocks after it took
//                     the new first entry, its E1 read between them;
// and covers a switch to mode 1 and back to mode 0 (cover task).
`default_nettype none

module fmode_switch (
    input wire clk_i
);
`include "albatross_contract.vh"

    localparam TB = 12;
    (* anyseq *) reg [31:0] rom;
    (* anyseq *) reg        req, idle, sw, hdr1, hdr2;
    (* anyseq *) reg [3:0]  req_mode;
    (* anyseq *) reg [7:0]  ne;

    reg        init_q = 1'b1;     // the reset clock
    reg        run_q  = 1'b0;     // the first boundary (it takes mode 0, loaded by the header) has passed
    reg [1:0]  hdr_q  = 2'd0;     // 0 before H1, 1 after H1, 2 after H2: requests only after
    always @(posedge clk_i) begin
        init_q <= 1'b0;
        if (hdr1 && hdr_q == 2'd0) hdr_q <= 2'd1;
        if (hdr2 && hdr_q == 2'd1) hdr_q <= 2'd2;
        if (hdr_q == 2'd2 && sw && f_step == 3'd5) run_q <= 1'b1;
    end
    // The sequencer's header: H1, then H2, once, before any request or boundary.
    always @* begin
        assume(!(hdr1 && hdr2));
        if (hdr_q != 2'd0 || init_q) assume(!hdr1);
        if (hdr_q != 2'd1 || init_q) assume(!hdr2);
        if (hdr_q != 2'd2) assume(!req && !sw && !idle);
        assume(!(sw && hold));
    end
    // the sequencer waits for the cycle end (idle) until the boundary
    reg idle_q = 1'b0, sw_q = 1'b0;
    always @(posedge clk_i) begin
        idle_q <= idle;
        sw_q   <= sw;
    end
    always @* if (idle_q && !sw_q) assume(idle);

    wire        read, hold, reject;
    wire [9:0]  read_adr;
    wire        e1, e1_rd, e6, e6_rd, first_ld;
    wire [3:0]  cluster;
    wire [3:0]  mode;
    wire [7:0]  first, last_end, next_first, drop;
    wire [TB-1:0] cycle;
    albatross_mode_switch #(.ROM_AW(10), .TIME_BITS(TB)) dut (
        .clk_i(clk_i), .rst_i(init_q), .hdr1_i(hdr1), .hdr2_i(hdr2), .ne_i(ne), .rom_i(rom),
        .req_i(req), .req_mode_i(req_mode), .idle_i(idle), .switch_i(sw),
        .read_o(read), .read_adr_o(read_adr), .first_ld_o(first_ld), .e1_rd_o(e1_rd), .e6_rd_o(e6_rd), .e1_o(e1), .e6_o(e6),
        .hold_o(hold), .reject_o(reject), .commit_o(), .mode_o(mode),
        .first_o(first), .end_o(last_end), .next_first_o(next_first), .cycle_o(cycle), .drop_o(drop),
        .cluster_o(cluster));

    // The header's number of modes, as the harness saw it.
    reg [3:0]  f_modes;
    always @(posedge clk_i) if (hdr2) f_modes <= rom[ALB_ROM_H2_MODES_LSB +: 4];

    // Probes (sby `connect`): the module's own state.
    (* keep *) wire       f_pend;
    (* keep *) wire [2:0] f_step;
    (* keep *) wire [3:0] f_idx, f_modes_q, f_mode_q;
    (* keep *) wire [15:0] f_next_q;

    reg first_ld_q = 1'b0, first_ld_q2 = 1'b0, e1_rd_q = 1'b0, e6_rd_q = 1'b0;
    always @(posedge clk_i) begin
        first_ld_q  <= first_ld;
        first_ld_q2 <= first_ld_q;
        e1_rd_q     <= e1_rd;
        e6_rd_q     <= e6_rd;
    end
    reg past_valid = 1'b0;
    reg past_allowed;             // the pending mode was in the running mode's next mask, a clock ago
    always @(posedge clk_i) begin
        past_valid   <= 1'b1;
        past_allowed <= f_next_q[f_idx];
    end
    always @(posedge clk_i) if (past_valid && !$past(init_q) && !init_q) begin
        if (!$past(hdr1) && !$past(hdr2) && !($past(sw) && $past(f_step) == 3'd5)) begin
            base_at_boundary: assert($stable(first) && $stable(last_end) && $stable(cycle) && $stable(drop) &&
                                     $stable(mode));
        end
        if (!$past(hdr2) && !($past(f_step) == 3'd3)) begin
            cluster_at_load: assert($stable(cluster));
        end
        if ($past(sw) && $past(f_step) == 3'd5 && $past(run_q)) begin
            allowed_switch: assert(mode == $past(f_idx) && past_allowed);
        end
    end
    always @* if (!init_q && hdr_q == 2'd2) begin
        declared_mode: assert(f_modes == 4'd0 ? mode == 4'd0 : mode < f_modes);
        modes_kept:    assert(f_modes_q == f_modes && f_mode_q == mode);
        // invariants for the induction
        step_pend:     assert(f_step <= 3'd5 && (f_step == 3'd0 || f_pend));
        no_hold_idle:  assert(f_pend || !hold);
        reads_when_idle: assert(!(read || e1_rd || e6_rd) || idle);
        e1_after_first:  assert(!e1_rd || (f_step == 3'd3 && first_ld_q && !read));
        e6_after_first:  assert(!e6_rd || (f_step == 3'd4 && first_ld_q2 && e1_rd_q && e1));
        e6_data:         assert(!e6 || (f_step == 3'd5 && e6_rd_q));
        if (run_q) begin
            pend_known: assert(!f_pend || (f_idx < f_modes && f_idx != mode && f_next_q[f_idx]));
            no_modes:   assert(f_modes != 4'd0 || !f_pend);
        end else begin
            header_load: assert(f_pend && f_step == 3'd5 && f_idx == 4'd0 && mode == 4'd0);
        end
    end
    always @* begin
        init_first: assert(!init_q || (hdr_q == 2'd0 && !run_q));
        run_after_header: assert(!run_q || hdr_q == 2'd2);
    end
    always @* if (!init_q && hdr_q != 2'd2) begin
        before_header: assert(!f_pend && f_step == 3'd0 && mode == 4'd0);
    end

    // Non-vacuity: a switch to mode 1, then back to mode 0.
    reg seen1 = 1'b0;
    always @(posedge clk_i) if (mode == 4'd1) seen1 <= 1'b1;
    always @* begin
        cover_switch:      cover(mode == 4'd1);
        cover_switch_back: cover(seen1 && mode == 4'd0);
        cover_reject:      cover(reject);
    end
endmodule

`default_nettype wire
