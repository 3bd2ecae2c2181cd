// fcopy_inv.vh -- induction strengthening of formal/copy/fcopy.v, `include'd in
// its module body (formal/copy/copy.sby, task prove; docs/verification.md "COPY
// path").  With -DF_PROBE the script joins the fi_*/fe_*/fb_* wires to the
// registers of the Import engine, the Export engine and the bus master after
// flatten (Yosys has no hierarchical references), and the inv_* assertions tie
// them to the harness's model: the engines' states and request registers, the
// glue's slot phases, the true Actual copies, each destination's picked buffer
// (never the buffer Actual names or one being read before its Actual store),
// the lockstep progress of the symbolic word (stored at d iff the Export passed
// it) and its value, and the stream link between the engines.
    // ------------------------------------------------------------ induction strengthening
`ifdef F_PROBE
    // the engines' and the bus master's registers, joined by the script after flatten
    (* keep *) wire [2:0]    fi_state;   // u_import.state_q
    (* keep *) wire          fi_stb;     // u_import.stb
    (* keep *) wire          fi_retry;   // u_import.retry_q
    (* keep *) wire [AW-1:0] fi_adr;     // u_import.adr_q
    (* keep *) wire [WW-1:0] fi_words;   // u_import.words_q
    (* keep *) wire [2:0]    fi_act3;    // u_import.act_q
    wire [1:0]               fi_act = fi_act3[1:0];
    (* keep *) wire          fi_four;    // u_import.four_q
    (* keep *) wire          fe_four;    // u_export.four_q
    (* keep *) wire          fi_we;      // u_import.we
    (* keep *) wire [3:0]    fi_sel;     // u_import.sel
    (* keep *) wire [2:0]    fe_state;   // u_export.state_q
    (* keep *) wire          fe_stb;     // u_export.stb_q
    (* keep *) wire          fe_retry;   // u_export.retry_q
    (* keep *) wire [4*AW-1:0] fe_base;  // u_export.base_q
    (* keep *) wire [3:0]    fe_need;    // u_export.need_q
    (* keep *) wire [WW-1:0] fe_words;   // u_export.words_q
    wire [WW-1:0]            fe_sk = exp_index - 1'b1; // S_STORE_WORD: the word stored (take_k_q - 1)
    (* keep *) wire [31:0]   fe_word;    // u_export.word_q
    (* keep *) wire [31:0]   fe_taken;   // u_export.taken_q
    (* keep *) wire [11:0]   fe_buf12;   // u_export.buf_q (3-bit fields)
    wire [7:0]               fe_buf = {fe_buf12[10:9], fe_buf12[7:6], fe_buf12[4:3], fe_buf12[1:0]};
    (* keep *) wire [1:0]    fb_owner;   // u_bus.owner_q
    (* keep *) wire          fb_gap;     // u_bus.gap_q
    (* keep *) wire [1:0]    fb_tmo;     // u_bus.tmo_q
    (* keep *) wire          fb_pend;    // u_bus.pend_q
    (* keep *) wire [40+AW:0] fb_held;   // u_bus.held_q
    (* keep *) wire [40+AW:0] fb_live;   // u_bus.live (the owner's fields now)
    localparam [2:0] I_IDLE = 3'd0, I_LOAD_ACTUAL = 3'd1, I_STORE_RL = 3'd2,
                     I_LOAD_WORD = 3'd4, I_HOLD_WORD = 3'd5, I_WAIT_PULL = 3'd6;
    localparam [2:0] E_IDLE = 3'd0, E_LOAD_ACTUAL = 3'd1, E_LOAD_RL = 3'd2, E_WAIT_WORD = 3'd3,
                     E_STORE_WORD = 3'd4, E_STORE_TAKEN = 3'd5, E_STORE_ACTUAL = 3'd6;
    wire i_acc = fi_state == I_LOAD_ACTUAL || fi_state == I_STORE_RL || fi_state == I_LOAD_WORD;
    wire i_p1  = fi_state == I_LOAD_ACTUAL || fi_state == I_STORE_RL;
    wire i_p2  = fi_state == I_LOAD_WORD || fi_state == I_HOLD_WORD || fi_state == I_WAIT_PULL;
    wire e_acc = fe_state != E_IDLE && fe_state != E_WAIT_WORD;
    wire e_p1  = fe_state == E_LOAD_ACTUAL || fe_state == E_LOAD_RL;
    wire s_rl_v = s_rl[7:2] == 6'd0 && s_rl[1:0] != 2'd0;
    wire [AW-1:0] i_first = f_sbase + BUF_W + (s_rl[1:0] == 2'd1 ? {AW{1'b0}} : s_rl[1:0] == 2'd2 ? w_a : w_a + w_a);
    wire [WW:0] sk1 = {1'b0, fe_sk};
    wire [WW:0] tk1 = {1'b0, exp_index};
    // word f_k is stored (acked) at destination dd in this Export
    function stored;
        input dd;
        begin
            case (fe_state)
                E_WAIT_WORD:    stored = f_k < tk1;
                E_STORE_WORD:   stored = f_k < sk1 || (f_k == sk1 && {1'b0, dd} < exp_dest);
                E_STORE_TAKEN:  stored = f_k < w1 || {1'b0, dd} < exp_dest;
                E_STORE_ACTUAL: stored = 1'b1;
                default:        stored = 1'b0;
            endcase
        end
    endfunction
    // destination dd has picked its buffer in this Export
    function picked;
        input dd;
        begin
            picked = fe_state == E_WAIT_WORD || fe_state == E_STORE_WORD || fe_state == E_STORE_TAKEN ||
                     fe_state == E_STORE_ACTUAL || (e_p1 && {1'b0, dd} < exp_dest);
        end
    endfunction
    reg ok_rl, ok_copy, ok_pick, ok_wr, ok_val;
    integer j;
    reg [1:0] bj;
    reg [7:0] aj, rj;
    always @* begin
        {ok_rl, ok_copy, ok_pick, ok_wr, ok_val} = 5'b11111;
        for (j = 0; j < 2; j = j + 1) begin
            bj = fe_buf[2*j +: 2];
            aj = d_act[8*j +: 8];
            rj = d_rl[8*j +: 8];
            // the consumer owns ReadLocked
            if (rj != {6'd0, c_rl[2*j +: 2]} || c_st[2*j +: 2] == 2'd3 || (f_atomic && c_st[2*j +: 2] == C_STORE))
                ok_rl = 1'b0;
            if (c_st[2*j +: 2] == C_READ && c_rl[2*j +: 2] == 2'd0) ok_rl = 1'b0;
            // the Actual copies are true
            if (exp_known[j] && (exp_act[2*j +: 2] == 2'd0 || aj != {6'd0, exp_act[2*j +: 2]})) ok_copy = 1'b0;
            if (!exp_run_q && st_act[2*j +: 2] != 2'd0 && aj != {6'd0, st_act[2*j +: 2]}) ok_copy = 1'b0;
            // its RL load picks against a true copy of Actual (or an Actual that names no buffer)
            if (fe_state == E_LOAD_RL && exp_dest == j[1:0] && !exp_known[j] && aj[7:2] == 6'd0 && aj[1:0] != 2'd0)
                ok_copy = 1'b0;
            if (fe_state != E_IDLE && fe_need[j] && picked(j[0])) begin
                if (bj == 2'd0) ok_pick = 1'b0;
                // before its Actual store: not the buffer Actual names, not one being read
                if (!(fe_state == E_STORE_ACTUAL && exp_dest >= j[1:0])) begin
                    if (aj == {6'd0, bj}) ok_pick = 1'b0;
                    if (c_st[2*j +: 2] == C_READ && c_rl[2*j +: 2] == bj) ok_pick = 1'b0;
                    if (f_atomic && rj == {6'd0, bj}) ok_pick = 1'b0;
                end
                // the symbolic word of its buffer: stored in this Export iff the lockstep passed it
                if (f_wr[3*j + 0] != (bj == 2'd1 && stored(j[0])) || f_wr[3*j + 1] != (bj == 2'd2 && stored(j[0])) ||
                    f_wr[3*j + 2] != (bj == 2'd3 && stored(j[0])))
                    ok_wr = 1'b0;
                if (stored(j[0]) && d_word[32*(3*j + bj - 1) +: 32] != expect_w) ok_val = 1'b0;
            end
            if (fe_state != E_IDLE && fe_need[j] && !picked(j[0]) && f_wr[3*j +: 3] != 3'b000) ok_wr = 1'b0;
        end
    end
    always @* begin
        if (!init_q) begin
            // three-buffer runs only: the engines' four-slot bits stay clear
            inv_three:     assert(!fi_four && !fe_four && !imp_rl3[2] && (fi_state != I_STORE_RL || !fi_act3[2]) &&
                                  !exp_tried12[2] && !exp_tried12[5] && !exp_tried12[8] && !exp_tried12[11] &&
                                  (!(fe_state != E_IDLE && fe_need[0] && picked(1'b0)) || !fe_buf12[2]) &&
                                  (!(fe_state != E_IDLE && fe_need[1] && picked(1'b1)) || !fe_buf12[5]));
            inv_d_rl:      assert(ok_rl);
            inv_d_copy:    assert(ok_copy);
            inv_d_pick:    assert(ok_pick);
            inv_d_wr:      assert(ok_wr);
            inv_d_val:     assert(ok_val);
            inv_glue_st:   assert(st_act[7:4] == 4'd0 && st_need[3:2] == 2'd0 && st_tried[7:4] == 4'd0 &&
                                  (!imp_run_q || need_q[3:2] == 2'd0) && (imp_run_q || st_rl == 2'd0 || s_rl == {6'd0, st_rl}) &&
                                  exp_known[3:2] == 2'b00 && exp_tried[7:4] == 4'd0);
            inv_glue_run:  assert((!exp_run_q || (imp_run_q && chosen_q)) &&
                                  (exp_idle || exp_run_q) && (!exp_run_q || !exp_idle || exp_done));
            inv_glue_p1:   assert(!(imp_run_q && !chosen_q) || (exp_idle && !exp_done && (i_p1 || (fi_state == I_IDLE && imp_done))));
            inv_glue_skip: assert(!(imp_run_q && chosen_q && !exp_run_q) || (fi_state == I_IDLE && imp_done));
            inv_glue_p2:   assert(!exp_run_q || (fi_state == I_IDLE || i_p2));
            inv_glue_left: assert(imp_run_q || fi_state == I_IDLE || fi_state == I_LOAD_WORD || fi_state == I_HOLD_WORD);
            inv_glue_src:  assert(!chosen_q || (s_rl_v && !(p_busy && p_wb == s_rl[1:0])));
            inv_prod:  assert(p_act != 2'd0 && s_act == {6'd0, p_act} && (!p_busy || (p_wb != 2'd0 && p_wb != p_act)));
            inv_bus:   assert(fb_owner <= 2'd1 && fb_tmo <= 2'd2 && !(fb_gap && m_cyc));
            // the bus master's held access: pending exactly when the property
            // set has one outstanding (not in a failure's gap), and the engine
            // still drives the fields held (the engines obey Wishbone classic)
            inv_bus_pend: assert(fb_pend == (f_out && !fb_gap) && (!fb_pend || fb_held == fb_live));
            inv_i_state: assert(fi_state != 3'd3 && fi_state != 3'd7 &&
                                fi_stb == (i_acc && !fi_retry) && (!fi_retry || i_acc) &&
                                (fi_state == I_IDLE || fi_words == f_w));
            inv_i_p1:    assert((!i_p1 || (fi_adr == f_sbase && fi_we == (fi_state == I_STORE_RL) &&
                                           fi_sel == (fi_state == I_STORE_RL ? SEL_RL : SEL_ACT))) &&
                                (fi_state != I_STORE_RL || (imp_new && fi_act != 2'd0)) &&
                                (!(fi_state == I_LOAD_ACTUAL || fi_state == I_IDLE) || !imp_rl_known ||
                                 (imp_rl != 2'd0 && s_rl == {6'd0, imp_rl})) &&
                                (!(fi_state == I_LOAD_ACTUAL && imp_new) || (imp_rl_known && imp_rl == fi_act)));
            inv_i_p2:    assert(!i_p2 || (imp_index < fi_words && !fi_we && fi_sel == 4'hF && chosen_q &&
                                          imp_rl_known && s_rl_v && imp_rl == s_rl[1:0] &&
                                          fi_adr == i_first + {{(AW-WW){1'b0}}, imp_index}));
            inv_e_state: assert(fe_state != 3'd7 && fe_stb == (e_acc && !fe_retry) && (!fe_retry || e_acc) &&
                                (fe_state == E_IDLE || (fe_base[2*AW-1:0] == {f_dbase1, f_dbase0} && fe_words == f_w &&
                                                        fe_need[3:2] == 2'd0 && fe_need[1:0] != 2'd0 && fe_taken == taken_q)) &&
                                (!e_acc || (fe_need[exp_dest] && exp_dest[1] == 1'b0)));
            inv_e_store: assert(!(fe_state == E_STORE_WORD) || (fe_sk < f_w && exp_index == fe_sk + 1'b1 &&
                                                                f_lk_ok && f_lk == {{(AW-WW){1'b0}}, fe_sk} && fe_word == f_ldata &&
                                                                (sk1 != f_k || fe_word == expect_w)));
            inv_e_k:     assert((!(fe_state == E_WAIT_WORD) || (exp_index < f_w)) &&
                                (!(fe_state == E_STORE_TAKEN || fe_state == E_STORE_ACTUAL) ||
                                 (exp_index == f_w && fe_sk == f_w - 1'b1)) &&
                                (!e_p1 || exp_index == {WW{1'b0}}));
            inv_link:  assert((!(fi_state == I_LOAD_WORD) || fe_state == E_WAIT_WORD || fe_state == E_IDLE) &&
                              (!(fi_state == I_HOLD_WORD) || fe_state == E_IDLE) &&
                              (!(i_p2 && fe_state != E_IDLE) || imp_index == exp_index) &&
                              (!(fi_state == I_WAIT_PULL && fe_state != E_IDLE) || fe_state != E_STORE_TAKEN && fe_state != E_STORE_ACTUAL));
            inv_order: assert(!f_clean || ((!(imp_run_q && !chosen_q) || (f_pend == 2'b00 && !f_lk_ok)) &&
                                           (!exp_run_q || fe_state == E_IDLE ||
                                            ((fe_state == E_STORE_ACTUAL || fe_need[1:0] == (need_q[1:0] & ~exp_published[1:0])) &&
                                             f_pend == (fe_state == E_STORE_WORD ? fe_need[1:0] & (exp_dest[0] ? 2'b10 : 2'b11) : 2'b00)))));
        end
    end
`endif
