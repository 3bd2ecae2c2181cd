// fseq -- property harness of albatross_sequencer (with albatross_schedule_rom,
// albatross_rom_check and albatross_entry_check inside it) for the unbounded proofs of
// formal/sequencer/sequencer.sby (docs/verification.md "Sequencer (unbounded)").
// Rules:
//   * The ROM is a fixed image, fseq_rom.hex, and fseq_rom.vh gives the
//     configuration and the image's fields; both are written by
//     formal/sequencer/gen_rom.py (the schedule compiler's encoder and CRC).
//     The harness models exactly F_NE = 2 entries, both COPY, TIME or STATUS.
//   * Reset is high in the first clock only; enable_i is free (the cover and
//     negative tasks hold it high from the start, -DF_EAGER).  The engines
//     are abstract: slot_done_i is free, except that a slot that got go_o ends
//     (slot_done_i) at the latest in the clock before the next planned slot
//     start, or before H1 for the last slot: the sequencer's one assumption on
//     the engines (it starts a slot only once the previous one is over).  The
//     poll port (ack, err, data) and sync_rl_i are free in every clock.
//   * Times are counted from the harness's own view of the cycle: crel is the
//     number of clocks since the last cycle_o (0 in the cycle_o clock).  All
//     properties are asserted once start-up has ended (the first cycle_o),
//     whatever its length; before that, none of go_o, may_access_o, poll_cyc_o
//     may be high.
//   * Minor cycles: n is the harness's count of the cycles, 0 in the first
//     one, + 1 at each later cycle start, modulo 2^c (c = H2.cluster, F_CL):
//     the contract's count.  Entry k is due in a cycle when n mod 2^rep_k =
//     base_k mod 2^rep_k (E6: the controller reads only base's low rep bits;
//     the images, verify_rom-clean, have base_k < 2^rep_k).  The images'
//     two slots do not share a window, so an entry that is not due (its
//     fetch only, 7 clocks) moves no other's start.
// Properties (labels; S_k = E1 of entry k, D_k = S_k + E2 of entry k,
// MARGIN = TIMEOUT + 2, FETCH = 7):
//   go_time        go_o only in a clock with crel = S_k + FETCH - 1 of a cycle
//                  in which entry k is due (so at most once per entry per
//                  cycle, and never in a minor cycle it is not due in), after
//                  start-up.
//   go_given       in every cycle, go_o is high in clock S_k + FETCH - 1 of
//                  every entry k due in it (valid images: every due slot
//                  starts, exactly on time).
//   count_wrap     (with the probes) the sequencer's count is the contract's:
//                  n_q = n, 0 in the first cycle, wrapping at 2^c.
//   go_fields      with go_o: kind, channel, ND, W, source, destinations and
//                  SYNC flag are entry k's; slot_time_o is the time_o of clock S_k.
//   deadline       may_access_o only while a slot runs (from its go_o to its
//                  slot_done_i) and only in a clock c with c + 1 <= D_k - MARGIN.
//   access_window  conversely, may_access_o is high in every such clock.
//   cycle_start    after the first cycle, cycle_o is high exactly when the
//                  last cycle start is H1 clocks ago, or (sync mode) in the
//                  clock after a poll's ack that shows a valid Actual other
//                  than sync_rl_i: time-rigid cycles are exactly H1 apart.
//   poll_when      poll_cyc_o only in sync mode, after the cycle's last slot
//                  has ended, at entry 0's source (board and base).
//   idle_on_error  no go_o, no poll_cyc_o and no may_access_o while error_o.
//   rom_ok         valid image: error_o never, rom_errors_o stays 0 (the
//                  background check never flags the unchanged ROM).
//   never_starts   invalid image: no cycle ever starts.
//   time_step      time_o counts clocks, so slot_time_o = time_o - (FETCH - 1)
//                  at go_o (not in the PDR task, -DF_PDR: PDR learns the 32-bit
//                  increment relation slowly; k-induction proves it).
// Induction strengthening (white-box, -DF_PROBE): the .sby script joins the
// f_* wires below to the sequencer's and the ROM check's registers after
// flatten (Yosys has no hierarchical references); the inv_* assertions tie
// them to the harness's model and make the property set 1-inductive.
`default_nettype none

module fseq (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        enable_i,
    input  wire        slot_done_i,
    input  wire [31:0] poll_dat_i,
    input  wire        poll_ack_i,
    input  wire        poll_err_i,
    input  wire [1:0]  sync_rl_i
);
`include "albatross_contract.vh"
`include "fseq_rom.vh"

    localparam [31:0] FETCH  = 32'd7;                 // the sequencer's FETCH_CYCLES
    localparam [31:0] MARGIN = F_TIMEOUT + 2;         // deadline margin
    localparam [31:0] D0 = F_S0 + F_L0, D1 = F_S1 + F_L1;
    localparam [31:0] G0 = F_S0 + FETCH - 1, G1 = F_S1 + FETCH - 1;   // go clocks
    localparam        CW = F_TB + 1;                  // crel bits (saturating)

    generate
        if (F_NE != 2) begin : g_ne_check
            fseq_models_two_entries u_error ();
        end
    endgenerate

    wire                  go_o, sync_entry_o, may_access_o, poll_cyc_o, cycle_o, error_o;
    wire [1:0]            kind_o;
    wire [6:0]            chan_o;
    wire [2:0]            nd_o;
    wire [11:0]           words_o;
    wire [3:0]            src_board_o, poll_board_o;
    wire [F_AW-1:0]       src_base_o, poll_adr_o;
    wire [15:0]           dst_board_o, rom_errors_o, cycles_o;
    wire [4*F_AW-1:0]     dst_base_o;
    wire [31:0]           slot_time_o, time_o;

    // The ROM check's CRC step: the sequencer's default in the proofs (the
    // probes' widths and gen_rom.py's F_CRCB follow F_CRC_BITS: a default
    // other than it fails the probes' connect or the invariants); F_WORD_CRC
    // (the covers but the time image's, and the negatives) takes a word a
    // clock, so that their unrolling through the start-up pass is 7 clocks a
    // word shorter.  The k-induction proofs do not depend on it.
    albatross_sequencer #(
        .NB(F_NB), .ADDR_WIDTH(F_AW), .N_CHAN(F_NCHAN), .ROM_WORDS(F_ROM_WORDS), .ROM_FILE("fseq_rom.hex"),
        .TIME_BITS(F_TB), .TIMEOUT(F_TIMEOUT), .POLL(F_POLL), .CLUSTER_BITS(F_CLB)
`ifdef F_WORD_CRC
        , .CRC_BITS(32)
`endif
    ) dut (
        .clk_i(clk_i), .rst_i(rst_i), .enable_i(enable_i),
        .go_o(go_o), .kind_o(kind_o), .chan_o(chan_o), .nd_o(nd_o), .words_o(words_o),
        .src_board_o(src_board_o), .src_base_o(src_base_o), .dst_board_o(dst_board_o),
        .dst_base_o(dst_base_o), .slot_time_o(slot_time_o), .sync_entry_o(sync_entry_o),
        .may_access_o(may_access_o), .slot_done_i(slot_done_i),
        .poll_cyc_o(poll_cyc_o), .poll_board_o(poll_board_o), .poll_adr_o(poll_adr_o),
        .poll_dat_i(poll_dat_i), .poll_ack_i(poll_ack_i), .poll_err_i(poll_err_i), .sync_rl_i(sync_rl_i),
        .time_o(time_o), .cycle_o(cycle_o), .error_o(error_o), .rom_errors_o(rom_errors_o),
        .cycles_o(cycles_o), .mode_req_i(1'b0), .mode_req_mode_i(4'd0), .mode_o(), .mode_reject_o()
    );

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;

    // ------------------------------------------------------------ the model
    reg           started_q;      // a cycle has started (start-up is over)
    reg [CW-1:0]  crel_q;         // clocks since the last cycle start (saturating)
    reg           busy_q;         // a slot runs: go_o given, slot_done_i not yet
    reg           cur_q;          // the entry of that slot (or of the last one)
    reg           last_done_q;    // the cycle's last slot is over
    reg           hit_q;          // the last clock had a poll hit
    reg           rst_q;
    reg  [31:0]   time_q;         // time_o of the last clock
    reg  [31:0]   ts_q;           // time_o of the last planned slot start S
    reg  [7:0]    n_q;            // the minor-cycle count of the last clock's cycle

    wire [CW-1:0] crel   = cycle_o ? {CW{1'b0}} : crel_q;
    wire [31:0]   crel32 = {{(32-CW){1'b0}}, crel};
    wire          at_go0 = started_q && crel32 == G0;
    wire          at_go1 = started_q && crel32 == G1;
    wire          busy   = go_o || busy_q;
    wire          cur    = go_o ? at_go1 : cur_q;
    wire [31:0]   dl     = cur ? D1 : D0;
    wire          open_w = busy && crel32 + 32'd1 + MARGIN <= dl;   // an access may begin next clock
    wire [7:0]    actual = poll_dat_i[8*ALB_CH_OFF_ACTUAL +: 8];
    // the count of this clock's cycle: 0 in the first cycle, + 1 modulo 2^c at every later start
    localparam [7:0] CL_MASK = (8'd1 << F_CL) - 8'd1;
    wire [7:0]    n_cur  = !cycle_o ? n_q : started_q ? ((n_q + 8'd1) & CL_MASK) : 8'd0;
    wire          due0   = ((n_cur ^ F_B0[7:0]) & ((8'd1 << F_R0) - 8'd1)) == 8'd0;   // n = base mod 2^rep
    wire          due1   = ((n_cur ^ F_B1[7:0]) & ((8'd1 << F_R1) - 8'd1)) == 8'd0;
    wire          hit    = poll_cyc_o && poll_ack_i && actual != 8'd0 && actual[7:2] == 6'd0 &&
                           actual[1:0] != sync_rl_i;

    always @(posedge clk_i) begin
        rst_q  <= rst_i;
        time_q <= time_o;
        if ((started_q || cycle_o) && (crel32 == F_S0 || crel32 == F_S1)) ts_q <= time_o;
        n_q    <= n_cur;
        if (rst_i) begin
            started_q   <= 1'b0;
            crel_q      <= {CW{1'b0}};
            busy_q      <= 1'b0;
            cur_q       <= 1'b0;
            last_done_q <= 1'b0;
            hit_q       <= 1'b0;
        end else begin
            if (cycle_o) started_q <= 1'b1;
            crel_q      <= (&crel) ? crel : crel + 1'b1;
            busy_q      <= go_o || (busy_q && !slot_done_i);
            cur_q       <= cur;
            // (entry 1 not due: over after its fetch, in the clock of its go had it been due)
            last_done_q <= (last_done_q && !cycle_o) || (busy_q && slot_done_i && cur_q) ||
                           ((started_q || cycle_o) && crel32 == G1 && !due1);
            hit_q       <= hit;
        end
    end

    // ------------------------------------------------------------ assumptions
    always @* begin
        assume(rst_i == init_q);
`ifdef F_EAGER
        assume(enable_i);     // bounded tasks (cover, negatives): start-up begins at once
`endif
        // the engines end a slot before the next planned start (the last one before H1)
        if (busy_q && crel32 == (cur_q ? F_H1 : F_S1) - 32'd1) assume(slot_done_i);
    end

    // ------------------------------------------------------------ properties
    always @* begin
        if (!init_q) begin
            go_time:       assert(!go_o || (at_go0 && due0) || (at_go1 && due1));
            if (F_VALID) begin
                go_given:  assert(!((at_go0 && due0) || (at_go1 && due1)) || go_o);
            end
            if (go_o && at_go0) begin
                go_fields_0: assert(kind_o == F_KIND0 && chan_o == F_CHAN0 && nd_o == F_ND0 && words_o == F_W0 &&
                                  src_board_o == F_SRCB0 && src_base_o == F_SRCA0 && dst_board_o == F_DSTB0 &&
                                  dst_base_o == F_DSTA0 && sync_entry_o == F_SYNC0 &&
                                  slot_time_o == ts_q);
            end
            if (go_o && at_go1) begin
                go_fields_1: assert(kind_o == F_KIND1 && chan_o == F_CHAN1 && nd_o == F_ND1 && words_o == F_W1 &&
                                  src_board_o == F_SRCB1 && src_base_o == F_SRCA1 && dst_board_o == F_DSTB1 &&
                                  dst_base_o == F_DSTA1 && sync_entry_o == F_SYNC1 &&
                                  slot_time_o == ts_q);
            end
            deadline:      assert(!may_access_o || (started_q && open_w));
            access_window: assert(!(started_q && open_w) || may_access_o);
            if (started_q) begin
                cycle_start: assert(cycle_o == ({{(32-CW){1'b0}}, crel_q} == F_H1 || hit_q));
            end
            poll_when:     assert(!poll_cyc_o || (F_SMODE && started_q && last_done_q && !cycle_o &&
                                                  poll_board_o == F_SRCB0 && poll_adr_o == F_SRCA0));
            idle_on_error: assert(!error_o || !(go_o || poll_cyc_o || may_access_o));
            if (F_VALID) begin
                rom_ok:    assert(!error_o && rom_errors_o == 16'd0);
            end else begin
                never_starts: assert(!cycle_o && !started_q);
            end
`ifndef F_PDR
            if (!rst_q) begin
                time_step: assert(time_o == time_q + 32'd1);
            end
`endif
        end
    end

    // ------------------------------------------------------------ non-vacuity
    always @* begin
        if (!init_q) begin
            if (F_VALID) begin
                c_go1:      cover(go_o && at_go1);
                c_go0_late: cover(go_o && at_go0 && n_cur != 8'd0);   // entry 0 in a later minor cycle
                c_cycle2:   cover(cycle_o && started_q);
                c_last_acc: cover(may_access_o && crel32 + 32'd1 + MARGIN == D0);
            end else begin
                c_error:    cover(error_o);
            end
            if (F_SMODE) begin
                c_poll:     cover(poll_cyc_o);
                c_early:    cover(cycle_o && started_q && hit_q);
            end
        end
    end
`ifdef F_PROBE
`ifdef F_WORD_CRC
    fseq_probe_tables_are_for_F_CRC_BITS u_error ();   // (gen_rom.py's F_CRCB)
`endif
    // ------------------------------------------------------------ induction strengthening
    // Joined by sequencer.sby after flatten (white-box; the sequencer's state
    // encoding is mirrored here).  No named wire may be a plain alias of an f_*
    // wire (e.g. w = {0, f_x}): `connect -set` would cut the alias off and
    // leave it undriven; use the f_* wires in expressions instead.
    localparam [2:0] ST_HEADER = 3'd0, ST_CHECK = 3'd1, ST_ERROR = 3'd2, ST_WAIT = 3'd3,
                     ST_FETCH = 3'd4, ST_TRANSFER = 3'd5, ST_CYCLE_END = 3'd6;
    localparam       AW = $clog2(F_ROM_WORDS);
    localparam [AW-1:0] LAST_W = F_ROM_WORDS - 1;      // the image's last word
    localparam       XW = AW + F_CB;                   // the ROM check's read index {word, chunk}
    localparam integer    LAST_C_I = F_CHUNKS - 1;
    localparam [F_CB-1:0] LAST_C   = LAST_C_I[F_CB-1:0];
    localparam [XW-1:0]   LAST_X   = {LAST_W, LAST_C};  // the last word's last chunk
    localparam [XW-1:0]   STEP_X   = (F_CHUNKS > 1) ? 1 : 2;   // (one chunk: the chunk bit stays 0)
    (* keep *) wire [2:0]          f_state, f_step;
    (* keep *) wire [F_TB-1:0]     f_cycle, f_start;
    (* keep *) wire [F_TB:0]       f_next_rel, f_end;   // f_next_rel: rel + 1
    (* keep *) wire [F_TB-1:0]     f_prev_end;          // a valid slot's end: TB bits (its bit TB would be 0)
    (* keep *) wire [7:0]          f_ne, f_ent;
    (* keep *) wire [XW-1:0]       f_bg_adr, f_bg_dadr;
    (* keep *) wire                f_smode, f_sync_ok, f_start_bad, f_bad, f_sflag, f_poll, f_bg_data, f_last;
    (* keep *) wire [31:0]         f_slot_time, f_crc;
    (* keep *) wire [7:0]          f_drop;
    (* keep *) wire [7:0]          f_ent_end;     // the cycle's entry end (no modes: NE)
    (* keep *) wire                f_mpend;       // the mode switch: a request pending (never: no request comes)
    (* keep *) wire [2:0]          f_mstep;       // ... and its load step
    (* keep *) wire [7:0]          f_mfirst;      // the cycle's first entry (no modes: 0)
    (* keep *) wire [3:0]          f_mmodes;      // the image's modes (these images: none)
    (* keep *) wire [F_TB-1:0]     f_rcycle;      // the running mode's cycle, drop run, end and first entry
    (* keep *) wire [7:0]          f_rdrop, f_rend, f_rfirst;    // (f_cycle .. f_mfirst: the loaded mode's)
    (* keep *) wire [1:0]          f_kind;
    (* keep *) wire [6:0]          f_chan;
    (* keep *) wire [2:0]          f_nd;
    (* keep *) wire [11:0]         f_w;
    (* keep *) wire [13:0]         f_e3;
    (* keep *) wire [3:0]          f_sbrd, f_sync_brd;
    (* keep *) wire [F_AW-1:0]     f_sbase, f_sync_base;
    (* keep *) wire [15:0]         f_dbrd;
    (* keep *) wire [4*F_AW-1:0]   f_dbase;
    (* keep *) wire [33*(F_NE+1)-1:0] f_sig;         // the prefix signatures, part r at [33r +: 33]
    (* keep *) wire [32:0]         f_sig_q;
    localparam                     RGB = $clog2((F_ROM_WORDS - 4) / 8 + 1);   // the ROM check's part bits
    (* keep *) wire                f_lwr;         // the ROM check writes a start-up prefix now ...
    (* keep *) wire [RGB-1:0]      f_mpart;       // ... of this part (from the CRC register)
    (* keep *) wire                f_mism;        // the ROM check's registered mismatch
    (* keep *) wire [31:0]         f_rom_q;       // the ROM's read register
    (* keep *) wire                f_lastq, f_ent0q;   // the entry that runs is the last / entry 0
    (* keep *) wire                f_dueq;        // the due test on the E6 read ahead
    (* keep *) wire [3:0]          f_rep;         // its rep (the entry check's)
    (* keep *) wire [F_CLB-1:0]    f_nq;          // the sequencer's minor-cycle count (of entry f_ent's cycle)
    (* keep *) wire                f_e6h, f_e6f;  // rom_q holds E6 read after the start-up pass / by FETCH clock 6
    (* keep *) wire [3:0]          f_cl;          // the loaded mode's cluster

    wire          run    = started_q || cycle_o;        // start-up is over
    wire          fetch  = f_state == ST_FETCH;
    wire          xfer   = f_state == ST_TRANSFER;
    // The entry register moves on to the next entry (entry 0 after the last) in
    // FETCH clock 5: the entry fetched or run, e1, is f_ent until then, the one
    // before it from FETCH clock 6 on.
    wire          e1     = (fetch && f_step <= 3'd5) ? f_ent == 8'd1 :
                           (fetch || xfer || f_state == ST_CYCLE_END) ? f_ent == 8'd0 : f_ent == 8'd1;
    wire [31:0]   s_ent  = e1 ? F_S1 : F_S0;
    wire [31:0]   d_ent  = e1 ? D1 : D0;
    wire [31:0]   s_nxt  = f_ent == 8'd1 ? F_S1 : F_S0;     // the start of entry f_ent
    // E6 of entry 0 and 1 (word 4 + 8k + 6), and the verdict the sequencer holds: on entry f_ent's,
    // but while fetching (FETCH clocks 1 .. 6 and the clock after, whose rom_q holds the next one's)
    // on the fetched one's; judged at the count of the cycle it runs in (entry 0 after the last entry:
    // the next cycle's)
    wire [31:0]   e6w0   = F_ROM[32*10 +: 32];
    wire [31:0]   e6w1   = F_ROM[32*18 +: 32];
    wire          e6_of1 = f_e6f ? f_ent == 8'd0 : fetch ? e1 : f_ent == 8'd1;
    wire          wrapped = (fetch && f_step == 3'd6 && e1) || (xfer && e1) || f_state == ST_CYCLE_END;
    wire [7:0]    n_nxt  = (n_cur + 8'd1) & CL_MASK;
    wire          due0n  = ((n_nxt ^ F_B0[7:0]) & ((8'd1 << F_R0) - 8'd1)) == 8'd0;
    wire          due_want = e6_of1 ? due1 : (wrapped && !f_e6f) ? due0n : due0;
    wire [3:0]    e6_rep_w  = e6_of1 ? F_R1[3:0] : F_R0[3:0];
    // the slots run so far in the cycle (prev_end: the last due one's end)
    wire [F_TB:0] pe1    = due0 ? D0[F_TB:0] : {(F_TB+1){1'b0}};
    wire [F_TB:0] pe2    = due1 ? D1[F_TB:0] : pe1;
    wire          got1   = xfer || (fetch && f_step >= 3'd2);   // E0's fields are in
    wire          got2   = xfer || (fetch && f_step >= 3'd3);   // E2
    wire          got3   = xfer || (fetch && f_step >= 3'd4);   // E3
    wire          got4   = xfer || (fetch && f_step >= 3'd5);   // E4
    wire          got5   = xfer || (fetch && f_step >= 3'd6);   // E5
    // start_q: the fetched entry's start until FETCH clock 6, then the next entry's (entry 0's after the last)
    wire [31:0]   st_want = fetch ? s_ent : s_nxt;
    wire [XW-1:0] bg_nxt = f_bg_dadr == LAST_X ? {XW{1'b0}} : f_bg_dadr + STEP_X;
    wire [31:0]   crcb   = F_CRCB[32*f_bg_dadr +: 32];
    // the word a main read of the last clock left in rom_q: the header reads, the
    // entry's words E0, E2..E5, then the next entry's E1 (after the last entry: entry 0's;
    // f_ent is the next entry then); E6 of the next entry in the clock after the fetch (f_e6f)
    // (entry k's words start at 4 + 8k: the sequencer derives its addresses from ent_q)
    reg  [31:0]   main_a;
    wire          hdr    = f_state == ST_HEADER;
    wire [31:0]   e_base = 32'd4 + 32'd8 * {24'd0, f_ent};
    always @* begin
        case (f_step)
            3'd1:    main_a = hdr ? 32'd0 : e_base;
            3'd2:    main_a = hdr ? 32'd1 : e_base + 32'd2;
            3'd3:    main_a = hdr ? 32'd2 : e_base + 32'd3;
            3'd4:    main_a = hdr ? 32'd5 : e_base + 32'd4;
            3'd5:    main_a = e_base + 32'd5;
            default: main_a = hdr ? 32'd0 : e_base + 32'd1;   // HEADER: word 0 while it waits
        endcase
    end
    wire [31:0]   rom_main = F_ROM[32*main_a[AW-1:0] +: 32];
    wire          hdr_ok = f_ne == F_NE && f_smode == F_SMODE && f_cycle == F_H1[F_TB-1:0] && f_drop == F_DROP &&
                          f_ent_end == F_NE && f_mfirst == 8'd0 && f_mmodes == 4'd0;
    wire [F_TB:0] pe_want = f_state == ST_CYCLE_END ? pe2 : xfer ? (e1 ? pe2 : pe1) : e1 ? pe1 : {(F_TB+1){1'b0}};
    // a part's signature is stored once the start-up pass has checked its last word
    // (written in the clock after that check: pending then)
    wire [F_NE:0] sig_ok;
    genvar r;
    generate for (r = 0; r <= F_NE; r = r + 1) begin : g_sig
        assign sig_ok[r] = !(run || (f_state == ST_CHECK && {{(32-AW){1'b0}}, f_bg_dadr[XW-1:F_CB]} > 8 * r + 3)) ||
                           f_sig[33*r +: 33] == {1'b0, F_PFX[32*r +: 32]} ||
                           (f_lwr && {{(32-RGB){1'b0}}, f_mpart} == r);
    end endgenerate
    // the pending start-up write: the part whose last chunk was checked in the last clock, its
    // prefix in the CRC register (the last part's: in the clock after the pass, the read index back at 0)
    wire [31:0]   lwr_word = 32'd8 * {{(32-RGB){1'b0}}, f_mpart} + 32'd4;
    wire [XW-1:0] lwr_x    = f_last ? {XW{1'b0}} : {lwr_word[AW-1:0], {F_CB{1'b0}}};
    always @* begin
        if (!init_q) begin
            inv_reset: assert(!rst_q || (f_state == ST_HEADER && f_step == 3'd0 && !f_bg_data && f_bg_adr == 0 &&
                                         f_crc == F_CRCB[31:0] && !error_o && !started_q && !f_poll));
            if (!rst_q) begin
                inv_bg:  assert(f_bg_adr == (f_bg_data ? bg_nxt : f_bg_dadr) && f_bg_dadr <= LAST_X);
                // (in the clock after the start-up pass's last check: the whole image's CRC)
                inv_crc: assert(f_crc == ((f_state == ST_CHECK && f_last) ? F_CRC_ALL : crcb));
            end
            inv_poll:    assert(!f_poll || (f_state == ST_CYCLE_END && f_smode && f_sync_ok));
            // the mode switch: mode 0 loaded by the header, taken at the first
            // boundary; no request comes, so no load ever runs after it
            if (run) begin
                inv_nomode:  assert(!f_mpend && f_mstep == 3'd0 && f_rcycle == f_cycle && f_rdrop == f_drop &&
                                    f_rend == f_ent_end && f_rfirst == f_mfirst);
            end else begin
                inv_mode0:   assert((f_state == ST_HEADER && f_step <= 3'd3) ? (!f_mpend && f_mstep == 3'd0)
                                                                          : (f_mpend && f_mstep == 3'd5));
            end
            inv_sync:    assert(!f_sync_ok || (F_SYNC0 && f_sync_brd == F_SRCB0 && f_sync_base == F_SRCA0));
            if (!run) begin
                inv_start: assert(!started_q && !cycle_o && !busy_q && !hit_q &&
                                  (f_state == ST_HEADER || f_state == ST_CHECK || (!F_VALID && f_state == ST_ERROR)));
            end
            if (f_state == ST_HEADER) begin
                inv_header: assert(f_step <= 3'd4 && !error_o && !f_last && (rst_q || (!f_bg_data && f_bg_dadr == 0)) &&
                                   (rst_q || (!f_e6h && !f_e6f && f_ent == 8'd0 && f_nq == {F_CLB{1'b0}})) &&
                                   (f_step < 3'd2 || (f_ne == F_NE && f_smode == F_SMODE)) &&
                                   (f_step < 3'd3 || f_cycle == F_H1[F_TB-1:0]) &&
                                   (f_step < 3'd4 || (f_drop == F_DROP && f_ent_end == F_NE && f_mfirst == 8'd0 &&
                                                      f_mmodes == 4'd0)));
            end
            if (f_state == ST_CHECK) begin
                inv_check: assert(hdr_ok && !error_o && f_start == F_S0[F_TB-1:0] && !f_start_bad &&
                                  (!f_last || (!f_bg_data && f_bg_dadr == 0)) && f_ent == 8'd0 && !f_e6f && !f_e6h &&
                                  f_cl == F_CL[3:0] && f_nq == {F_CLB{1'b0}});
            end
            if (f_state == ST_ERROR) begin
                inv_error: assert(!F_VALID && error_o && !cycle_o && !started_q && !f_last && (!f_bg_data || f_bg_dadr == 0));
            end
            inv_sig: assert(&sig_ok);
            inv_lwr: assert(!f_lwr || (f_state == ST_CHECK && f_bg_dadr == lwr_x &&
                                       f_crc == F_PFX[32*f_mpart +: 32] &&
                                       (!f_last || {{(32-RGB){1'b0}}, f_mpart} == F_NE)));
            // the unchanged ROM never mismatches its prefixes (so no bad mark is pending)
            inv_mism: assert(!f_mism);
            // the signature read register: the background part, or at FETCH clock 1 the entry's
            if (run && f_bg_data) begin
                inv_sig_q: assert(f_sig_q == {1'b0, F_PFX[32*f_bg_dadr[XW-1:F_CB+3] +: 32]});
            end
            if (run && fetch && f_step == 3'd1) begin
                inv_sig_f: assert(f_sig_q == {1'b0, F_PFX[32*({31'd0, f_ent[0]} + 32'd1) +: 32]});
            end
            // the ROM read register: a background read, a header read, a fetch read
            if (!rst_q && f_bg_data) begin
                inv_rom_bg: assert(f_rom_q == F_ROM[32*f_bg_dadr[XW-1:F_CB] +: 32]);
            end
            if ((hdr && !rst_q) || (fetch && main_a < F_ROM_WORDS)) begin
                inv_rom_main: assert(f_rom_q == rom_main);
            end
            inv_rom_e6: assert(!f_e6f || f_rom_q == (f_ent == 8'd1 ? e6w1 : e6w0));
            // E6 of entry 0, read in the clock after the start-up pass, in the first cycle's first clock
            inv_rom_e6h: assert(!f_e6h || (f_rom_q == e6w0 && cycle_o && !started_q && !f_e6f));
            if (run) begin
                inv_run: assert(hdr_ok && !error_o && f_next_rel == {1'b0, crel[F_TB-1:0]} + 1'b1 && crel32 < F_H1 &&
                                f_ent <= 8'd1 &&
                                f_start == st_want[F_TB-1:0] && !f_start_bad &&
                                {1'b0, f_prev_end} == pe_want && (busy_q == xfer) && (!xfer || cur_q == e1) &&
                                ((last_done_q && !cycle_o) == (f_state == ST_CYCLE_END)));
                // the due test's inputs: the count (count_wrap), the cluster, the due fields
                count_wrap: assert(f_nq == (wrapped ? n_nxt[F_CLB-1:0] : n_cur[F_CLB-1:0]));
                inv_cl:     assert(f_cl == F_CL[3:0]);
                inv_due: assert(f_e6h || (f_dueq == due_want && f_rep == e6_rep_w));
                inv_e6f: assert(!f_e6f || (crel32 == (f_ent == 8'd1 ? F_S0 : F_S1) + FETCH && f_state != ST_FETCH));
                // the entry that runs, from FETCH clock 6 on
                if ((fetch && f_step == 3'd6) || xfer || f_state == ST_CYCLE_END) begin
                    inv_ran: assert(f_lastq == e1 && f_ent0q == !e1);
                end
                case (f_state)
                    ST_WAIT:      inv_wait:  assert(crel32 <= s_ent && (!e1 || crel32 >= G0 + (due0 ? 32'd2 : 32'd1)));
                    ST_FETCH:     inv_fetch: assert(crel32 == s_ent + {29'd0, f_step} && f_step >= 3'd1 &&
                                                    f_step <= 3'd6 && !f_bad && f_slot_time == ts_q &&
                                                    (f_step <= 3'd5 || f_ent == {7'd0, !e1}));
                    ST_TRANSFER:  inv_xfer:  assert(crel32 > s_ent + FETCH - 32'd1 && f_ent == {7'd0, !e1} &&
                                                    crel32 < (e1 ? F_H1 : F_S1) && (e1 ? due1 : due0));
                    ST_CYCLE_END: inv_end:   assert(f_ent == 8'd0 && crel32 >= G1 + (due1 ? 32'd2 : 32'd1));
                    default:      inv_state: assert(1'b0);
                endcase
                // entry 0's fetch is over in this cycle: its poll capture is made
                if ((f_state == ST_WAIT && f_ent == 8'd1) || (fetch && e1) || xfer || f_state == ST_CYCLE_END) begin
                    inv_sync_ok: assert(f_sync_ok == F_SYNC0);
                end
                if (got1) begin
                    inv_e0: assert(f_kind == (e1 ? F_KIND1 : F_KIND0) && f_sflag == (e1 ? F_SYNC1 : F_SYNC0) &&
                                   f_chan == (e1 ? F_CHAN1 : F_CHAN0) && f_nd == (e1 ? F_ND1 : F_ND0) &&
                                   f_w == (e1 ? F_W1 : F_W0) && f_e3 == 14'd3 * {2'd0, f_w});
                end
                if (got2) begin
                    inv_e2: assert(f_end == d_ent[F_TB:0]);
                end
                if (got3) begin
                    inv_e3: assert(f_sbrd == (e1 ? F_SRCB1 : F_SRCB0) && f_sbase == (e1 ? F_SRCA1 : F_SRCA0));
                end
                if (got4) begin
                    inv_e4: assert(f_dbrd[7:0] == (e1 ? F_DSTB1[7:0] : F_DSTB0[7:0]) &&
                                   f_dbase[2*F_AW-1:0] == (e1 ? F_DSTA1[2*F_AW-1:0] : F_DSTA0[2*F_AW-1:0]));
                end
                if (got5) begin
                    inv_e5: assert(f_dbrd[15:8] == (e1 ? F_DSTB1[15:8] : F_DSTB0[15:8]) &&
                                   f_dbase[4*F_AW-1:2*F_AW] == (e1 ? F_DSTA1[4*F_AW-1:2*F_AW] : F_DSTA0[4*F_AW-1:2*F_AW]));
                end
            end
        end
    end
`endif
`endif

endmodule

`default_nettype wire
