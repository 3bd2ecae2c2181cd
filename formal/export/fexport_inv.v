// fexport_inv -- the k-induction invariants of the Export engine's proof
// (formal/export/export.sby task prove, harness fexport.v; docs/verification.md
// "Export engine (unbounded)").  Inputs only, every one an assertion; fexport
// instantiates it with -DF_PROBE, its f_* inputs joined by the script to the
// engine's registers (state_q, need_q, buf_q, run_q, retry_q, drop_q,
// base_q, words_q, word_q, taken_q), the rest the harness's own state.
// Rules: the engine's position is a key kcur (the harness's access order: the
// present access, or the next word's first store while waiting for a word);
// every planned access below kcur is over (acked, or its destination left),
// none above has begun.  From that the invariants fix the harness's records of
// this Export (acks, loads, buffer words acked, Actual stores, errs) and tie the
// engine's copies (act_known_o/act_o/tried_o, buf_q) and the RAM's and the
// consumer's bytes to them, per destination (inv_* below, one label each).
`default_nettype none

module fexport_inv #(
    parameter TAKEN_AT = 1,  // the engine's TAKEN_AT (0 or 1)
    parameter DROP     = 1,  // the engine's DROP (0 or 1)
    parameter AW       = 5,  // word-address bits
    parameter W        = 2   // words of the value
) (
    input wire chk_i, idle_i, done_i, cut_i, stb_i, we_i, new_acc_i, p_stb_i, p_err_i,
    input wire e_we_i, eret_x_i, any_x_i, open_q_i, dist_x_i,
    input wire [1:0] dest_i, known_o_i, published_i, windex_i,
    input wire [1:0] a_d_i, e_d_i, takes_x_i, need_x_i, known_x_i, landed_x_i, la_ok_x_i, rl_ok_x_i,
    input wire [1:0] sa_ack_x_i, sa_err_x_i, held_q_i,
    input wire [3:0] act_o_i, tried_o_i, sel_i, e_sel_i, acks_x_i, copy_x_i, rl_x_i, tried_x_i,
    input wire [3:0] sa_buf_x_i, run_x_i,
    input wire [1:0] kk_i,           // the drop run K in force (2 or 3)
    input wire [2*AW-1:0] f_base_i,
    input wire [31:0] dat_i, e_dat_i, tw0_x_i, tw1_x_i, taken_x_i,
    input wire [AW-1:0] adr_i, e_adr_i,
    input wire [5:0] a_key_i, key_x_i, comp_i, full_i,
    input wire [6*(W+TAKEN_AT)-1:0] wr_q_i,
    input wire [15:0] act_q_i, rl_q_i
);
    localparam       DESTS = 2;                      // destinations
    localparam       S     = W + TAKEN_AT;           // buffer stride
    localparam [2:0] PH_SA = 1 + S;                  // phase of the Actual stores
    genvar g;

    // the engine's registers, joined by the script (connect -set inv.f_* ...)
    (* keep *) wire [2:0]      f_state;     // dut.state_q
    (* keep *) wire [1:0]      f_need;      // dut.need_q
    wire [1:0]                 f_store_k = windex_i - 2'd1; // S_STORE_WORD: the word stored (take_k_q - 1)
    (* keep *) wire [5:0]      f_buf6;      // dut.buf_q (3-bit fields: four-slot buffers 1..4)
    (* keep *) wire            f_four;      // dut.four_q
    wire [3:0]                 f_buf = {f_buf6[4:3], f_buf6[1:0]};
    (* keep *) wire [7:0]      f_run;       // dut.run_q (DROP = 1 only: else optimised away)
    (* keep *) wire            f_retry;     // dut.retry_q
    (* keep *) wire            f_drop;      // dut.drop_q (DROP = 1 only)
    (* keep *) wire [2*AW-1:0] f_base_q;    // dut.base_q
    (* keep *) wire [1:0]      f_words;     // dut.words_q
    (* keep *) wire [31:0]     f_word;      // dut.word_q
    (* keep *) wire [31:0]     f_taken;     // dut.taken_q

    // bit b (1..3) of a buffer set; 0 for b = 0
    function cbit(input [2:0] v, input [1:0] bi);
        cbit = bi == 2'd1 ? v[0] : bi == 2'd2 ? v[1] : bi == 2'd3 ? v[2] : 1'b0;
    endfunction
    // field d of a vector of 2-bit / 1-bit fields
    function [1:0] f2(input [2*DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f2 = 2'd0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f2 = v[2*j +: 2]; end
    endfunction
    function f1(input [DESTS-1:0] v, input [1:0] di);
        integer j;
        begin f1 = 1'b0; for (j = 0; j < DESTS; j = j + 1) if (di == j) f1 = v[j]; end
    endfunction

    localparam [2:0] E_IDLE = 3'd0, E_LA = 3'd1, E_LR = 3'd2, E_WAIT = 3'd3, E_SW = 3'd4, E_ST = 3'd5, E_SA = 3'd6;
    wire       e_acc = f_state == E_LA || f_state == E_LR || f_state == E_SW || f_state == E_ST || f_state == E_SA;
    // the engine's position: the key of its present access (or of the next store
    // when waiting for a word); every planned access below it is over
    wire [2:0] e_ph  = f_state == E_SW ? {1'b0, f_store_k} + 3'd1 : f_state == E_ST ? S[2:0] :
                       f_state == E_SA ? PH_SA : f_state == E_WAIT ? {1'b0, takes_x_i} + 3'd1 : 3'd0;
    wire [5:0] kcur  = f_state == E_IDLE ? 6'h3f : f_state == E_WAIT ? {e_ph, 3'b000} :
                       {e_ph, dest_i, f_state == E_LR};
    wire       e_drop = DROP != 0 && f2(run_x_i, e_d_i) >= kk_i;
    // planned accesses below the position (exact count of an undisturbed Export)
    function [3:0] pcount(input [5:0] kc);
        integer j, l;
        begin
            pcount = 4'd0;
            for (j = 0; j < DESTS; j = j + 1) if (need_x_i[j]) begin
                if (!known_x_i[j] && {3'd0, j[1:0], 1'b0} < kc) pcount = pcount + 4'd1;
                if (!landed_x_i[j]) begin
                    if ({3'd0, j[1:0], 1'b1} < kc) pcount = pcount + 4'd1;
                    for (l = 0; l <= S; l = l + 1)
                        if ({l[2:0] + 3'd1, j[1:0], 1'b0} < kc) pcount = pcount + 4'd1;
                end
            end
        end
    endfunction
    always @* if (chk_i) begin
        inv_open:  assert(open_q_i == (!idle_i || done_i) && f_state <= 3'd6 && (idle_i || (f_need != 2'b00 && !cut_i)));
        inv_idle:  assert(!idle_i || (!stb_i && !f_retry));
        inv_cfg:   assert(idle_i || (f_base_q == f_base_i && f_words == W && f_taken == taken_x_i && windex_i == takes_x_i));
        inv_stb:   assert(stb_i == (e_acc && !f_retry) && f_retry == p_err_i && (!f_retry || dist_x_i));
        inv_wait:  assert(f_state != E_WAIT || (dist_x_i && takes_x_i < W));
        inv_retry: assert(!f_retry || (adr_i == e_adr_i && we_i == e_we_i && sel_i == e_sel_i && dat_i == e_dat_i &&
                                        a_d_i == e_d_i && (DROP == 0 || f_drop == e_drop) && eret_x_i));
        inv_key:   assert(!e_acc || (a_key_i == kcur && f1(f_need, dest_i)));
        inv_words: assert((f_state != E_LA && f_state != E_LR || takes_x_i == 2'd0) &&
                          (takes_x_i <= W) && (f_state != E_SW || (f_store_k < W && {1'b0, f_store_k} + 2'd1 == takes_x_i &&
                                              f_word == (f_store_k == 2'd0 ? tw0_x_i : tw1_x_i))) &&
                          (f_state != E_ST && f_state != E_SA || takes_x_i == W));
        inv_last:  assert(idle_i || !any_x_i || (key_x_i < kcur && (!eret_x_i || e_drop)) ||
                          (key_x_i == kcur && e_acc && (!stb_i || !new_acc_i || eret_x_i)));
        inv_first: assert(idle_i || any_x_i || (e_acc && stb_i && !p_stb_i));
        inv_new:   assert(!(stb_i && any_x_i && key_x_i < kcur) || new_acc_i);
        inv_acks:  assert((idle_i || (dist_x_i ? acks_x_i <= pcount(kcur) : acks_x_i == pcount(kcur))) &&
                          (dist_x_i || (run_x_i == 4'd0 && !eret_x_i)));
        inv_pub:   assert(published_i == (need_x_i & (sa_ack_x_i | landed_x_i)));
    end
    wire [DESTS-1:0] v_wr, v_need, v_fails, v_loads, v_copy, v_act, v_held, v_tried, v_sa, v_land;   // per-d invariants
    generate for (g = 0; g < DESTS; g = g + 1) begin : inv
        wire [1:0] gd   = g;
        wire       live = f_need[g];
        wire [1:0] bq   = f_buf[2*g +: 2];
        wire [1:0] cx   = copy_x_i[2*g +: 2], rx = rl_x_i[2*g +: 2], tx = tried_x_i[2*g +: 2];
        wire [7:0] a    = act_q_i[8*g +: 8], r = rl_q_i[8*g +: 8];
        wire       av   = a[7:2] == 6'd0 && a[1:0] != 2'd0;
        wire       rv   = r[7:2] == 6'd0 && r[1:0] != 2'd0;
        wire [1:0] pk   = (cx != 2'd3 && rx != 2'd3) ? 2'd3 : (cx != 2'd2 && rx != 2'd2) ? 2'd2 : 2'd1;
        wire       sa_k = {PH_SA, gd, 1'b0} < kcur;
        wire [2:0] fl   = full_i[3*g +: 3];
        wire       pre_sa = !sa_ack_x_i[g] && !sa_err_x_i[g];
        reg        wr_ok;
        integer    j, l;
        always @* begin
            wr_ok = 1'b1;
            for (j = 1; j <= 3; j = j + 1)
                for (l = 0; l < S; l = l + 1)
                    if (live && !idle_i)
                        wr_ok = wr_ok && wr_q_i[(3*g+j-1)*S+l] == (bq == j && {l[2:0] + 3'd1, gd, 1'b0} < kcur);
                    else
                        wr_ok = wr_ok && (!wr_q_i[(3*g+j-1)*S+l] || (need_x_i[g] && !landed_x_i[g] && bq == j));
        end
        assign v_wr[g] = wr_ok;
        assign v_need[g] = idle_i || ((!live || need_x_i[g]) && (!landed_x_i[g] || !live) &&
                              (!need_x_i[g] || live || landed_x_i[g] || (DROP != 0 && run_x_i[2*g +: 2] >= kk_i)));
        assign v_fails[g] = (DROP == 0 || run_x_i[2*g +: 2] <= kk_i) &&
                              (idle_i || run_x_i[2*g +: 2] == 2'd0 || {3'd0, gd, known_x_i[g]} <= kcur) &&
                              (DROP == 0 || idle_i || !live ||
                               (dest_i == gd ? f_run == {6'd0, run_x_i[2*g +: 2]} : run_x_i[2*g +: 2] == 2'd0)) &&
                              (DROP == 0 || run_x_i[2*g +: 2] < kk_i || !live || idle_i ||
                               (f_retry && f_drop && e_d_i == gd));
        assign v_loads[g] = idle_i || !live || (la_ok_x_i[g] == (!known_x_i[g] && {3'd0, gd, 1'b0} < kcur) &&
                                                rl_ok_x_i[g] == ({3'd0, gd, 1'b1} < kcur) &&
                                                (!rl_ok_x_i[g] || (bq == pk && !f_buf6[3*g+2])) &&
                                                sa_ack_x_i[g] == sa_k && (!sa_err_x_i[g] || sa_k || kcur == {PH_SA, gd, 1'b0}));
        assign v_copy[g] = idle_i || !live || !pre_sa || (known_o_i[g] == (cx != 2'd0) && (!known_o_i[g] || act_o_i[2*g +: 2] == cx) &&
                           (run_x_i[2*g +: 2] == 2'd0 || {3'd0, gd, known_x_i[g]} <= kcur));
        assign v_act[g] = (!known_x_i[g] || cx != 2'd0) && (known_x_i[g] || la_ok_x_i[g] || cx == 2'd0) && (idle_i || !live || !pre_sa || !(known_x_i[g] || la_ok_x_i[g]) ||
                              (cx != 2'd0 ? a == {6'd0, cx} : !av));
        assign v_held[g] = idle_i || !live || !pre_sa || !rl_ok_x_i[g] || !held_q_i[g] || !rv ||
                              r == {6'd0, rx} || r == a;
        assign v_tried[g] = tried_o_i[2*g +: 2] == (sa_ack_x_i[g] ? 2'd0 : sa_err_x_i[g] ? sa_buf_x_i[2*g +: 2] :
                                                    la_ok_x_i[g] ? 2'd0 : tx) &&
                              (!pre_sa || tx == 2'd0 || a != {6'd0, tx} || cbit(comp_i[3*g +: 3], tx));
        assign v_sa[g] = (!sa_ack_x_i[g] || (a == {6'd0, bq} && cbit(fl, bq) && known_o_i[g] && act_o_i[2*g +: 2] == bq)) &&
                              (!sa_err_x_i[g] || (sa_buf_x_i[2*g +: 2] == bq && cbit(fl, bq))) &&
                              (!sa_err_x_i[g] || sa_ack_x_i[g] || !known_o_i[g]);
        assign v_land[g] = !landed_x_i[g] || ((idle_i || {3'd0, gd, 1'b0} < kcur) && tx != 2'd0 && a == {6'd0, tx} && cbit(comp_i[3*g +: 3], tx) &&
                                               !rl_ok_x_i[g] && pre_sa && la_ok_x_i[g]);
    end endgenerate
    always @* if (chk_i) begin
        inv_three: assert(idle_i || !f_four);
        inv_wr: assert(&v_wr);
        inv_need: assert(&v_need);
        inv_fails: assert(&v_fails);
        // a failure run lasts from an err to the next ack or drop, on a live destination
        inv_run:   assert(DROP == 0 || idle_i || f_run == 8'd0 ||
                          (f_run == {6'd0, f2(run_x_i, dest_i)} && f1(f_need, dest_i) && e_acc && eret_x_i &&
                           e_d_i == dest_i));
        inv_loads: assert(&v_loads);
        inv_copy: assert(&v_copy);
        inv_act: assert(&v_act);
        inv_held: assert(&v_held);
        inv_tried: assert(&v_tried);
        inv_sa: assert(&v_sa);
        inv_land: assert(&v_land);
    end

endmodule

`default_nettype wire
