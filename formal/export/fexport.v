// fexport -- proof harness of albatross_export, the Export engine (formal/export/
// export.sby, docs/verification.md "Export engine (unbounded)").
//
// The engine's master port is checked against formal/wb/fwb_master.v (requests
// asserted, answers assumed: ack or err at any time, never both) and answered by
// a model of the RAM holding DESTS = 2 channels at free, non-overlapping bases
// (anyconst): per destination d the control bytes Actual and ReadLocked (8 bits
// each, free at the start, the RAM is never reset) and buffers 1..3 of S = W +
// TAKEN_AT words (W = 2), seen as "word k of buffer b of d acked in this Export"
// bits.  Rules of the environment (every one an assume):
//   * reset in the first clock only; W = words_i = 2; base_i = the bases.
//   * An acked read of a control word returns that channel's Actual and
//     ReadLocked bytes; any other read data is free.  An acked store of Actual
//     lands; one answered with err lands or not (free, f_land_i).
//   * Consumer d (c_op_i[2d +: 2], free each clock): 1 loads Actual (seen := it;
//     held := 1 if it equals ReadLocked: the lock is confirmed); 2 stores
//     ReadLocked := the current Actual (figure 3's store; held := 1); 3 stores
//     ReadLocked := the Actual it loaded earlier (a stale store; held := 0 until
//     a confirming load).  held means the consumer may read buffer ReadLocked.
//   * At start (start_i while idle_o): need_i, same_i (this value is the one the
//     last Export carried), taken_at_i free; act_known_i[d] => act_i[d] is the
//     RAM's Actual of d (so it names a buffer); tried_i[d] = t != 0 and the RAM's
//     Actual of d = t => same_i and buffer t of d holds that value completely
//     (the only case where the engine relies on tried_i).
//   * may_access_i, word_i, word_valid_i free in every clock.
// Ghost: comp[d][b] = buffer b of d holds the current value (the last started
// Export's) completely: set when its S words were acked in one Export, kept by a
// same_i Export, cleared by any other start.
// Properties (labels; "this Export" = from start_i taken to done_o):
//   access_form     every access is to a destination in need_i, on its dest_o, one
//                   of: load Actual (sel 0001, only for an unknown copy), load
//                   ReadLocked (0010), store of a buffer word (1111), store of
//                   Actual (0001, a buffer 1..3).
//   access_order    accesses follow the header's order (loads per d; word 0, word
//                   1, taken_at, Actual, each in d order), each once; after an err
//   retry_same      the next access is the same one again, unless DROP drops d
//                   (the K-th failed attempt of the access in a row; K = drop_run_i,
//                   a free constant 0..3 here, values below 2 read as 2).
//   pick_rule       d's buffer is figure 4's: the last of 1..3 that is neither its
//                   Actual copy (known or read back) nor the ReadLocked loaded.
//   no_locked_write a buffer store of d follows d's acked ReadLocked load, never to
//                   the buffer that load named;
//   no_held_write   nor to the live ReadLocked while consumer d holds it;
//   no_actual_write nor to the buffer the live Actual of d names.
//   complete_publish a store of Actual := b to d only after words 0..S-1 of buffer
//                   b of d were stored and acked in this Export.
//   word_data       word k's stores carry the stream's word k, the taken_at store
//                   taken_at_i sampled at start;
//   word_order      words are taken in order 0..W-1, each once.
//   access_start    an access begins only in the clock after an edge with
//                   may_access_i = 1.
//   drop_dead       DROP = 1: no access to d after K failed attempts of one of its
//                   accesses in a row (run_x: errs of d's present access in a row,
//                   cleared by an ack of d);
//   landed_leave    none after a read-back of Actual equal to tried_i[d] != 0.
//   exact_accesses  at done_o: undisturbed (no err, may_access_i high at every edge
//                   of the Export, word_valid_i high whenever word_ready_o), acks =
//                   ND * (S + 2) + unknown copies, a landed destination counting 1;
//                   disturbed, at most that.
//   no_idle         undisturbed, cyc is high in every clock of the Export before
//                   done_o.
//   published_exact at done_o published_o[d] = Actual acked, or landed read-back;
//   complete_export at done_o without cut_o every d in need_i is published or
//                   (DROP = 1) dropped after K failures in a row: a failing destination
//                   never blocks the others, and one whose failures are not K in a row
//                   is never dropped;
//   fail_copy       after an err on d's Actual store not repeated with an ack:
//                   act_known_o[d] = 0 and tried_o[d] = the buffer tried.
//   copy_ok, published_ok, tried_sound  (every clock) a known copy is the RAM's
//                   Actual; a published d's Actual names a complete buffer; tried_o
//                   meets the tried_i assumption of the next Export.
// Covers (cover task): cov_both (undisturbed, both destinations), cov_unknown (a
// read-back), cov_landed, cov_failed, cov_cut, cov_drop, cov_drop3 (K = 3),
// cov_two_kept (two errs of d, not in a row, and d published), cov_retry, cov_moved (a
// store while the consumer holds a buffer it locked after the engine's load).
// With -DF_PROBE the invariants of fexport_inv.v are added (instance inv); the
// script joins its f_* wires to the engine's registers (Yosys has no
// hierarchical references).
`default_nettype none

module fexport #(
    parameter TAKEN_AT = 1,  // the engine's TAKEN_AT (0 or 1)
    parameter DROP     = 1   // the engine's DROP (0 or 1)
) (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        start_i,
    input  wire [1:0]  need_i,
    input  wire        same_i,
    input  wire [31:0] taken_at_i,
    input  wire [1:0]  act_known_i,
    input  wire [3:0]  act_i,
    input  wire [3:0]  tried_i,
    input  wire        may_access_i,
    input  wire [31:0] word_i,
    input  wire        word_valid_i,
    input  wire [31:0] wb_dat_i,
    input  wire        wb_ack_i,
    input  wire        wb_err_i,
    input  wire        f_land_i,
    input  wire [3:0]  c_op_i,       // consumer d's operation at [2d +: 2]
    input  wire [47:0] f_init_i,    // first clock, per d at [24d +: 24]: Actual, ReadLocked, seen bytes
    input  wire [7:0]  f_init2_i    // first clock, per d at [4d +: 4]: buffers complete (3), held
);
    localparam       DESTS = 2;                      // destinations
    localparam       AW    = 5;                      // word-address bits
    localparam       W     = 2;                      // words of the value
    localparam       S     = W + TAKEN_AT;           // buffer stride
    localparam       CH    = 1 + 3 * S;              // words of a channel
    localparam [2:0] PH_SA = 1 + S;                  // phase of the Actual stores

    (* anyconst *) reg [DESTS*AW-1:0] f_base;
    (* anyconst *) reg [7:0]          f_k;             // drop_run_i, K (0 and 1 read as 2)
    wire [1:0] kk = f_k < 8'd2 ? 2'd2 : f_k[1:0];      // the K in force (f_k <= 3, assumed)

    wire          idle, ready, done, cut;
    wire [1:0]    windex, published, corrupt, known_o, dest;
    wire [3:0]    act_o, tried_o;
    wire [5:0]    tried_o6;     // the engine's 3-bit fields (four-slot buffers 1..4); three-buffer only here
    assign tried_o = {tried_o6[4:3], tried_o6[1:0]};
    wire [1:0]    fails_o;
    wire          cyc, stb, we;
    wire [AW-1:0] adr;
    wire [3:0]    sel;
    wire [31:0]   dat;

    albatross_export #(.ADDR_WIDTH(AW), .WORDS_WIDTH(2), .COUNT_WIDTH(2), .TAKEN_AT(TAKEN_AT),
                       .DESTS(DESTS), .DROP(DROP)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(start_i), .drop_run_i(f_k), .base_i(f_base), .need_i(need_i), .words_i(W[1:0]), .taken_at_i(taken_at_i),
        .act_known_i(act_known_i), .act_i(act_i),
        .tried_i({1'b0, tried_i[3:2], 1'b0, tried_i[1:0]}), .four_i(1'b0), .may_access_i(may_access_i),
        .idle_o(idle), .word_i(word_i), .word_valid_i(word_valid_i), .word_ready_o(ready),
        .word_index_o(windex), .done_o(done), .published_o(published), .corrupt_o(corrupt),
        .cut_o(cut), .fails_o(fails_o), .act_known_o(known_o), .act_o(act_o), .tried_o(tried_o6),
        .dest_o(dest), .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_sel_o(sel),
        .wb_dat_o(dat), .wb_dat_i(wb_dat_i), .wb_ack_i(wb_ack_i), .wb_err_i(wb_err_i)
    );

    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    wire chk = !init_q;

    wire f_past_valid, f_out, f_rack;
    wire [3:0] f_wait;
    fwb_master #(.AW(AW), .DW(32)) wb (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(cyc), .stb_i(stb), .we_i(we), .adr_i(adr), .sel_i(sel),
        .wdat_i(dat), .rdat_i(wb_dat_i), .ack_i(wb_ack_i), .err_i(wb_err_i),
        .f_past_valid_o(f_past_valid), .f_outstanding_o(f_out), .f_wait_o(f_wait), .f_read_ack_o(f_rack));

    // ------------------------------------------------ the access on the bus
    reg  [1:0]    a_d;                               // its destination,
    reg           a_in;                              // inside a channel,
    reg           a_ctrl;                            // the control word,
    reg  [1:0]    a_b;                               // else buffer a_b,
    reg  [1:0]    a_k;                               // word a_k
    reg  [AW-1:0] off;                               // word offset in d's channel (modulo 2**AW)
    integer d, b, k;
    always @* begin
        a_d = 2'd0; a_in = 1'b0; a_ctrl = 1'b0; a_b = 2'd0; a_k = 2'd0;
        for (d = 0; d < DESTS; d = d + 1) begin
            off = adr - f_base[d*AW +: AW];
            if (off == 0) begin
                a_d = d[1:0]; a_in = 1'b1; a_ctrl = 1'b1;
            end
            for (b = 1; b <= 3; b = b + 1)
                for (k = 0; k < S; k = k + 1)
                    if (off == 1 + (b - 1) * S + k) begin
                        a_d = d[1:0]; a_in = 1'b1; a_b = b[1:0]; a_k = k[1:0];
                    end
        end
    end
    wire       k_la = a_in && a_ctrl && !we && sel == 4'b0001;   // load Actual
    wire       k_lr = a_in && a_ctrl && !we && sel == 4'b0010;   // load ReadLocked
    wire       k_st = a_in && !a_ctrl && we && sel == 4'b1111;   // store a buffer word
    wire       k_sa = a_in && a_ctrl && we && sel == 4'b0001;    // store Actual
    wire [2:0] a_ph = k_st ? {1'b0, a_k} + 3'd1 : k_sa ? PH_SA : 3'd0;
    wire [5:0] a_key = {a_ph, a_d, k_lr};            // the header's access order
    wire       go  = chk && start_i && idle;         // an Export begins at this edge
    wire       ack = stb && wb_ack_i;
    wire       err = stb && wb_err_i;
    wire [7:0] rbyte = wb_dat_i[7:0], lbyte = wb_dat_i[15:8];
    wire       rvalid = rbyte[7:2] == 6'd0 && rbyte[1:0] != 2'd0;
    wire       lvalid = lbyte[7:2] == 6'd0 && lbyte[1:0] != 2'd0;

    // ------------------------------------ per destination: RAM, consumer, this Export
    reg  [8*DESTS-1:0]   act_q;      // Actual of d in the RAM, [8d +: 8]
    reg  [8*DESTS-1:0]   rl_q;       // ReadLocked of d
    reg  [8*DESTS-1:0]   seen_q;     // the Actual consumer d loaded last
    reg  [DESTS-1:0]     held_q;     // consumer d may read buffer ReadLocked
    reg  [3*S*DESTS-1:0] wr_q;       // word k of buffer b of d acked in this Export: [(3d+b-1)S+k]
    reg  [3*DESTS-1:0]   comp_q;     // buffer b of d complete: [3d+b-1]
    wire [3*DESTS-1:0]   comp;       // ... including this clock's acks
    wire [3*DESTS-1:0]   full;       // all words of buffer b of d acked in this Export
    reg  [DESTS-1:0]     need_x, known_x, landed_x, la_ok_x, rl_ok_x, sa_ack_x, sa_err_x;
    reg  [2*DESTS-1:0]   copy_x;     // d's Actual copy (0: none), at [2d +: 2]
    reg  [2*DESTS-1:0]   rl_x;       // the ReadLocked loaded (0: none or invalid)
    reg  [2*DESTS-1:0]   tried_x, sa_buf_x, run_x;   // run_x: errs of d's present access in a row (sat. 3)
    reg  [DESTS-1:0]     err1_x;     // d had an err in this Export (cov_two_kept)
    reg  [DESTS-1:0]     err2_x;     // ... and a second one after an ack of d
    wire [DESTS-1:0]     env_known, env_tried;         // the start assumptions
    genvar g, gb, gk;
    generate for (g = 0; g < DESTS; g = g + 1) begin : ch
        for (gb = 0; gb < 3; gb = gb + 1) begin : bf
            assign full[3*g+gb] = &wr_q[(3*g+gb)*S +: S];
            assign comp[3*g+gb] = comp_q[3*g+gb] || full[3*g+gb];
        end
        wire [1:0] op   = c_op_i[2*g +: 2];
        wire [7:0] a    = act_q[8*g +: 8];
        wire       mine = a_d == g;
        always @(posedge clk_i) begin
            if (init_q) begin
                act_q[8*g +: 8]  <= f_init_i[24*g +: 8];
                rl_q[8*g +: 8]   <= f_init_i[24*g+8 +: 8];
                seen_q[8*g +: 8] <= f_init_i[24*g+16 +: 8];
                held_q[g]        <= f_init2_i[4*g+3];
                comp_q[3*g +: 3] <= f_init2_i[4*g +: 3];
                need_x[g] <= 1'b0; landed_x[g] <= 1'b0; sa_ack_x[g] <= 1'b0; sa_err_x[g] <= 1'b0;
                run_x[2*g +: 2] <= 2'd0; la_ok_x[g] <= 1'b0; err1_x[g] <= 1'b0; err2_x[g] <= 1'b0; rl_ok_x[g] <= 1'b0; tried_x[2*g +: 2] <= 2'd0;
                known_x[g] <= 1'b0; copy_x[2*g +: 2] <= 2'd0;
            end else begin
                if (op == 2'd1) begin seen_q[8*g +: 8] <= a; if (a == rl_q[8*g +: 8]) held_q[g] <= 1'b1; end
                if (op == 2'd2) begin seen_q[8*g +: 8] <= a; rl_q[8*g +: 8] <= a; held_q[g] <= 1'b1; end
                if (op == 2'd3) begin rl_q[8*g +: 8] <= seen_q[8*g +: 8]; held_q[g] <= 1'b0; end
                if (k_sa && mine && (ack || (err && f_land_i))) act_q[8*g +: 8] <= dat[7:0];
                if (go) begin
                    need_x[g] <= need_i[g]; known_x[g] <= act_known_i[g]; tried_x[2*g +: 2] <= tried_i[2*g +: 2];
                    copy_x[2*g +: 2] <= act_known_i[g] ? act_i[2*g +: 2] : 2'd0;
                    landed_x[g] <= 1'b0; la_ok_x[g] <= 1'b0; rl_ok_x[g] <= 1'b0; rl_x[2*g +: 2] <= 2'd0;
                    sa_ack_x[g] <= 1'b0; sa_err_x[g] <= 1'b0; run_x[2*g +: 2] <= 2'd0;
                    err1_x[g] <= 1'b0; err2_x[g] <= 1'b0;
                        comp_q[3*g +: 3]   <= same_i ? comp[3*g +: 3] : 3'd0;
                end else begin
                    comp_q[3*g +: 3] <= comp[3*g +: 3];
                    if (err && mine) begin
                        if (run_x[2*g +: 2] != 2'd3) run_x[2*g +: 2] <= run_x[2*g +: 2] + 2'd1;
                        err1_x[g] <= 1'b1;
                        if (err1_x[g] && run_x[2*g +: 2] == 2'd0) err2_x[g] <= 1'b1;
                        if (k_sa) begin sa_err_x[g] <= 1'b1; sa_buf_x[2*g +: 2] <= dat[1:0]; end
                    end
                    if (ack && mine) begin
                        run_x[2*g +: 2] <= 2'd0;
                        if (k_la) la_ok_x[g] <= 1'b1;
                        if (k_la && rvalid) copy_x[2*g +: 2] <= rbyte[1:0];
                        if (k_la && rvalid && rbyte[1:0] == tried_x[2*g +: 2]) landed_x[g] <= 1'b1;
                        if (k_lr) begin rl_ok_x[g] <= 1'b1; rl_x[2*g +: 2] <= lvalid ? lbyte[1:0] : 2'd0; end
                        if (k_sa) sa_ack_x[g] <= 1'b1;
                    end
                end
            end
        end
        for (gb = 0; gb < 3; gb = gb + 1) begin : wb_
            for (gk = 0; gk < S; gk = gk + 1) begin : wk
                always @(posedge clk_i)
                    if (init_q || go) wr_q[(3*g+gb)*S+gk] <= 1'b0;
                    else if (ack && mine && k_st && a_b == gb + 1 && a_k == gk) wr_q[(3*g+gb)*S+gk] <= 1'b1;
            end
        end
        // the start: a known copy is the RAM's Actual; tried_i as the engine relies on it
        wire [1:0] ci = act_i[2*g +: 2], ti = tried_i[2*g +: 2];
        assign env_known[g] = !act_known_i[g] || (a == {6'd0, ci} && ci != 2'd0);
        assign env_tried[g] = ti == 2'd0 || a != {6'd0, ti} || (same_i && cbit(comp[3*g +: 3], ti));
    end endgenerate

    // bit b (1..3) of a buffer set; 0 for b = 0
    function cbit(input [2:0] v, input [1:0] bi);
        cbit = bi == 2'd1 ? v[0] : bi == 2'd2 ? v[1] : bi == 2'd3 ? v[2] : 1'b0;
    endfunction
    // field d of a vector of DESTS fields of 2 bits / 8 bits / 3 bits / 1 bit
    function [1:0] f2(input [2*DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f2 = 2'd0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f2 = v[2*j +: 2]; end
    endfunction
    function [7:0] f8(input [8*DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f8 = 8'd0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f8 = v[8*j +: 8]; end
    endfunction
    function [2:0] f3(input [3*DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f3 = 3'd0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f3 = v[3*j +: 3]; end
    endfunction
    function f1(input [DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f1 = 1'b0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f1 = v[j]; end
    endfunction

    // -------------------------------------------------------------- environment
    wire [AW-1:0] gap = f_base[AW +: AW] - f_base[0 +: AW];
    wire [7:0]    act_d = f8(act_q, a_d), rl_d = f8(rl_q, a_d);
    always @* begin
        assume(rst_i == init_q);
`ifdef F_SMALLDATA
        assume(word_i[31:1] == 0 && taken_at_i[31:1] == 0);
`endif
        no_overlap: assume(gap >= CH && gap <= (1 << AW) - CH);
        small_k: assume(f_k <= 8'd3);
        if (go) known_copy: assume(&env_known);
        if (go) tried_copy: assume(&env_tried);
        // the RAM answers a read of a control word with its bytes
        if (chk && wb_ack_i && stb && !we && a_in && a_ctrl)
            read_ctrl: assume(wb_dat_i[7:0] == act_d && wb_dat_i[15:8] == rl_d);
    end

    // ------------------------------------------------------- this Export, seen from the bus
    reg        open_q;                               // an Export under way (to its done_o)
    reg  [3:0] acks_x;
    reg        dist_x;                               // disturbed
    reg        any_x;                                // an access has begun
    reg  [5:0] key_x;                                // the key of the last access
    reg        eret_x;                               // ... it ended with err
    reg  [1:0] e_d;                                  // the last err: destination, access
    reg  [AW-1:0] e_adr; reg e_we; reg [3:0] e_sel; reg [31:0] e_dat;
    reg  [31:0] tw0_x, tw1_x, taken_x;               // stream words taken, taken_at
    reg  [1:0] takes_x;                              // words taken
    reg        p_stb, p_ans, p_may, p_err;
    wire       new_acc = stb && (!p_stb || p_ans);
    wire       dropped = DROP != 0 && f2(run_x, e_d) >= kk;
    wire       take = open_q && ready && word_valid_i;
    wire [1:0] pick_c = f2(copy_x, a_d), pick_r = f2(rl_x, a_d);
    wire [1:0] pick = (pick_c != 2'd3 && pick_r != 2'd3) ? 2'd3 : (pick_c != 2'd2 && pick_r != 2'd2) ? 2'd2 : 2'd1;
    reg  [3:0] expect_n;
    always @* begin
        expect_n = 4'd0;
        for (d = 0; d < DESTS; d = d + 1)
            if (need_x[d]) expect_n = expect_n + {3'd0, !known_x[d]} + (landed_x[d] ? 4'd0 : S + 2);
    end

    always @(posedge clk_i) begin
        p_stb <= stb; p_ans <= wb_ack_i || wb_err_i; p_may <= may_access_i; p_err <= !init_q && err;
        if (init_q) begin
            open_q <= 1'b0; any_x <= 1'b0; eret_x <= 1'b0; acks_x <= 4'd0; takes_x <= 2'd0; dist_x <= 1'b0;
        end else if (go) begin
            open_q <= 1'b1; taken_x <= taken_at_i; acks_x <= 4'd0; dist_x <= !may_access_i;
            any_x <= 1'b0; eret_x <= 1'b0; takes_x <= 2'd0;
        end else begin
            if (done) open_q <= 1'b0;
            if (open_q && (!may_access_i || err || (ready && !word_valid_i))) dist_x <= 1'b1;
            if (take) begin
                takes_x <= takes_x + 2'd1;
                if (windex == 2'd0) tw0_x <= word_i; else tw1_x <= word_i;
            end
            if (new_acc) begin any_x <= 1'b1; key_x <= a_key; end
            if (ack || err) eret_x <= err;
            if (err) begin e_d <= a_d; e_adr <= adr; e_we <= we; e_sel <= sel; e_dat <= dat; end
            if (ack) acks_x <= acks_x + 4'd1;
        end
    end

    // ---------------------------------------------------------------- properties
    wire [7:0] b8 = {6'd0, a_b};
    always @* if (chk && open_q && stb) begin
        access_form: assert(a_in && f1(need_x, a_d) && dest == a_d && (k_la || k_lr || k_st || k_sa) &&
                            (!k_la || !f1(known_x, a_d)) && (!k_st || a_b != 2'd0) &&
                            (!k_sa || (dat[7:2] == 6'd0 && dat[1:0] != 2'd0)));
        if (new_acc && any_x && eret_x && !dropped)
            retry_same: assert(adr == e_adr && we == e_we && sel == e_sel && dat == e_dat);
        if (new_acc && any_x && !(eret_x && !dropped))
            access_order: assert(a_key > key_x);
        if (k_st) begin
            pick_rule:       assert(a_b == pick);
            no_locked_write: assert(f1(rl_ok_x, a_d) && a_b != pick_r);
            no_held_write:   assert(!(f1(held_q, a_d) && rl_d == b8));
            no_actual_write: assert(act_d != b8);
            word_data:       assert(a_k < W ? ({1'b0, a_k} < {1'b0, takes_x} &&
                                               dat == (a_k == 2'd0 ? tw0_x : tw1_x)) : dat == taken_x);
        end
        if (k_sa) complete_publish: assert(cbit(f3(full, a_d), dat[1:0]));
        if (new_acc) access_start: assert(p_may);
        if (DROP != 0) drop_dead: assert(f2(run_x, a_d) < kk);
        landed_leave: assert(!f1(landed_x, a_d));
    end
    // The engine's 3-bit tried fields keep their top bit clear (three-buffer runs only here).
    always @* if (chk) three_tried: assert(!tried_o6[5] && !tried_o6[2]);
    always @* if (chk && take) word_order: assert(windex == takes_x && takes_x < W);
    always @* if (chk && open_q && !done && !dist_x) no_idle: assert(stb);
    always @* if (chk && open_q && done) exact_accesses: assert(dist_x ? acks_x <= expect_n : acks_x == expect_n);
    // per destination, then one label each
    wire [DESTS-1:0] ok_pub_exact, ok_fail_copy, ok_copy, ok_pub, ok_tried, ok_complete;
    generate for (g = 0; g < DESTS; g = g + 1) begin : out
        wire [7:0] a  = act_q[8*g +: 8];
        wire [1:0] t  = tried_o[2*g +: 2];
        wire [2:0] c  = comp[3*g +: 3];
        assign ok_pub_exact[g] = published[g] == (need_x[g] && (sa_ack_x[g] || landed_x[g]));
        assign ok_fail_copy[g] = !(sa_err_x[g] && !sa_ack_x[g]) || (!known_o[g] && t == sa_buf_x[2*g +: 2]);
        assign ok_copy[g]      = !known_o[g] || a == {6'd0, act_o[2*g +: 2]};
        assign ok_pub[g]       = !published[g] || (a[7:2] == 6'd0 && cbit(c, a[1:0]));
        assign ok_tried[g]     = t == 2'd0 || a != {6'd0, t} || cbit(c, t);
        assign ok_complete[g]  = !need_x[g] || published[g] || (DROP != 0 && run_x[2*g +: 2] >= kk);
    end endgenerate
    always @* if (chk && open_q && done) begin
        published_exact: assert(&ok_pub_exact);
        fail_copy:       assert(&ok_fail_copy);
        if (!cut) complete_export: assert(&ok_complete);
    end
    always @* if (chk) begin
        copy_ok:      assert(&ok_copy);
        published_ok: assert(&ok_pub);
        tried_sound:  assert(&ok_tried);
    end

`ifdef F_PROBE
    // ---------------------------------------------- induction strengthening (white-box)
    fexport_inv #(.TAKEN_AT(TAKEN_AT), .DROP(DROP), .AW(AW), .W(W)) inv (
        .chk_i(chk), .f_base_i(f_base), .idle_i(idle),
        .done_i(done), .cut_i(cut), .stb_i(stb), .dest_i(dest), .known_o_i(known_o), .act_o_i(act_o),
        .tried_o_i(tried_o), .published_i(published), .windex_i(windex), .adr_i(adr), .we_i(we), .sel_i(sel),
        .dat_i(dat), .a_d_i(a_d), .a_key_i(a_key), .new_acc_i(new_acc), .p_stb_i(p_stb), .p_err_i(p_err),
        .e_adr_i(e_adr), .e_we_i(e_we), .e_sel_i(e_sel), .e_dat_i(e_dat), .e_d_i(e_d), .eret_x_i(eret_x),
        .any_x_i(any_x), .key_x_i(key_x), .open_q_i(open_q), .dist_x_i(dist_x), .acks_x_i(acks_x),
        .takes_x_i(takes_x), .tw0_x_i(tw0_x), .tw1_x_i(tw1_x), .taken_x_i(taken_x), .need_x_i(need_x),
        .known_x_i(known_x), .landed_x_i(landed_x), .la_ok_x_i(la_ok_x), .rl_ok_x_i(rl_ok_x),
        .sa_ack_x_i(sa_ack_x), .sa_err_x_i(sa_err_x), .copy_x_i(copy_x), .rl_x_i(rl_x), .tried_x_i(tried_x),
        .sa_buf_x_i(sa_buf_x), .run_x_i(run_x), .kk_i(kk), .wr_q_i(wr_q), .comp_i(comp), .full_i(full),
        .act_q_i(act_q), .rl_q_i(rl_q), .held_q_i(held_q));
`endif

    // ------------------------------------------------------------------ covers
    always @* if (chk && open_q && done) begin
        cov_both:    cover(!dist_x && need_x == 2'b11 && known_x == 2'b11 && published == 2'b11);
        cov_unknown: cover(!dist_x && need_x == 2'b01 && known_x == 2'b00 && landed_x == 2'b00 && published[0]);
        cov_landed:  cover(landed_x != 2'b00);
        cov_failed:  cover((sa_err_x & ~sa_ack_x) != 2'b00);
        cov_cut:     cover(cut && sa_ack_x != 2'b00);
        if (DROP != 0) cov_drop: cover(run_x[1:0] >= kk && sa_ack_x[1]);
        if (DROP != 0) cov_drop3: cover(kk == 2'd3 && run_x[1:0] == 2'd3 && sa_ack_x[1]);
        if (DROP != 0) cov_two_kept: cover(kk == 2'd2 && err2_x[0] && published[0]);
    end
    always @* if (chk && open_q && new_acc && any_x && eret_x && !dropped) cov_retry: cover(k_st);
    // a store while the consumer holds a buffer it locked after the engine's load
    always @* if (chk && open_q && stb && k_st)
        cov_moved: cover(f1(held_q, a_d) && rl_d[7:2] == 6'd0 && rl_d[1:0] != 2'd0 && rl_d[1:0] != pick_r);

    wire unused = &{1'b0, cut, corrupt, fails_o, cyc, f_past_valid, f_out, f_wait, f_rack};
endmodule

`default_nettype wire
