// fcopy -- proof harness of the COPY path (formal/copy/copy.sby,
// docs/verification.md "COPY path"): albatross_import (PULL = 1) streaming a
// value into albatross_export (DESTS = 4, TAKEN_AT = 1, DROP = 1) through
// albatross_bus_master (REQS = 3, the poll requester idle), wired and driven
// as albatross_controller wires them, for one channel with ND = 2
// destinations.  The controller's glue (choose, need, taken_at, the skip of
// the Import, the slot end and the write-back of the channel state) is
// copied here expression for expression, the state RAM reduced to the one
// channel's registers.
// Environment (free unless stated):
//   * Reset in the first clock only.  go starts a slot only when no slot runs
//     and both engines are idle (the sequencer's slot timing: the deadline
//     ends every access before the next slot's fetch); may_access_i and the
//     global time are free.
//   * The system bus (checked with formal/wb/fwb_master.v, OPT_ABORT: the bus
//     master withdraws a timed-out request) is answered by free ack/err/data;
//     a store that fails (err or timeout) may or may not land.  Three
//     channels at symbolic bases (anyconst) on three boards, W = 1..3
//     (anyconst): the source (stride W) and destinations 0 and 1 (stride W+1,
//     taken_at after the value).
//   * The source's producer is figure 4 with free timing (as in
//     formal/import/fimport.v): it writes only its current buffer WB, picked
//     neither its Actual nor the ReadLocked it loaded.  Each destination's
//     consumer is figure 3 with free timing: load Actual; if it equals its
//     ReadLocked, read that buffer (any number of clocks); else store
//     ReadLocked := the loaded value (now, or in a later clock) and load
//     again.  At the start it may be anywhere in that loop (reading the
//     buffer its ReadLocked names, or about to store an older Actual).  With
//     f_atomic (anyconst) it stores in the clock of its load (the brief's
//     consumer: ReadLocked := the current Actual); without, ReadLocked may
//     come to name the buffer the Export is writing (the confirming load
//     keeps the consumer off it), so no_write_locked holds only with f_atomic.
//   * One symbolic word index f_k = 0..W (anyconst; W is taken_at's word):
//     the model keeps word f_k of every buffer of the three channels.
// Properties (labels; "store at d" = a store request on the system bus to
// destination d's channel):
//   publish_value     a store of Actual := b at d names a buffer 1..3 whose word
//                     f_k holds word f_k of the source buffer ReadLocked names
//                     (f_k < W), or the slot's taken_at (f_k = W);
//   publish_complete  ... and word f_k of that buffer was stored (acked) at d
//                     in this Export: never published before all W words and
//                     taken_at were stored;
//   no_write_read     no store at d to the buffer d's consumer is reading;
//   no_write_locked   (f_atomic) no store at d to the buffer ReadLocked names;
//   dest_stores       a store at d to its control word selects Actual only and
//                     stores 1..3; no load of a destination buffer;
//   src_stores        a store to the source selects its ReadLocked only;
//   in_channel        every access lies inside one of the three channels;
//   order_data        a store of word k < W at d follows the source load of word
//                     k and stores its data; a store of word W stores taken_at;
//   order_exact       in a slot with no failed access: after each source word
//                     load, one store of that word per destination in need, in
//                     index order, before the next source access;
//   one_owner         the two engines never request the bus in the same clock
//                     (and the bus master never sees an overlap).
// Induction strengthening: fcopy_inv.vh (white-box, with -DF_PROBE).
`default_nettype none

module fcopy #(
    parameter AW = 4,   // word-address bits of a board RAM
    parameter WW = 2    // bits of W (W = 1..3)
) (
    input  wire          clk_i,
    input  wire          rst_i,
    input  wire          go_i,
    input  wire          may_access_i,
    input  wire [31:0]   time_i,
    // the system bus slave
    input  wire          ack_i,
    input  wire          err_i,
    input  wire          land_i,
    input  wire [31:0]   rdat_i,
    // the source's producer
    input  wire          pr_begin_i,
    input  wire [1:0]    pr_wb_i,
    input  wire          pr_publish_i,
    input  wire          pr_write_i,
    input  wire [31:0]   pr_data_i,
    // the destinations' consumers
    input  wire [1:0]    c_load_i,
    input  wire [1:0]    c_store_i,
    input  wire [1:0]    c_end_i
);

`include "albatross_contract.vh"

    localparam integer BUF_I = ALB_CH_OFF_BUFFERS / ALB_CH_WORD_BYTES;
    localparam [AW-1:0] BUF_W = BUF_I[AW-1:0];
    localparam integer ACT_BIT = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam integer RL_BIT  = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [3:0]   SEL_ACT = 4'b0001 << (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0]   SEL_RL  = 4'b0001 << (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [3:0]   SRC_B   = 4'd1;                  // boards
    localparam [3:0]   DST_B0  = 4'd2;
    localparam [3:0]   DST_B1  = 4'd3;
    localparam [3:0]   ACTIVE  = 4'b0011;               // ND = 2

    // ------------------------------------------------------------ the channel
    (* anyconst *) reg [AW-1:0] f_sbase, f_dbase0, f_dbase1;
    (* anyconst *) reg [WW-1:0] f_w;
    (* anyconst *) reg [WW:0]   f_k;
    (* anyconst *) reg          f_atomic;
    wire [WW:0] w1 = {1'b0, f_w};
    always @* assume(f_w != {WW{1'b0}} && f_k <= w1);

    // ------------------------------------------------------------ controller glue
    reg         imp_run_q, exp_run_q, chosen_q, new_q;
    reg  [3:0]  need_q;
    reg  [31:0] taken_q;
    reg  [1:0]  st_rl;
    reg  [3:0]  st_need;
    reg  [7:0]  st_act, st_tried;
    reg  [31:0] st_taken;
    wire        imp_idle, imp_sel, imp_done, imp_new, imp_corrupt, imp_cut, imp_rl_known, imp_fails;
    wire [2:0]  imp_rl3;       // the engines' 3-bit fields (four-slot buffers 1..4): three-buffer only here
    wire [1:0]  imp_rl = imp_rl3[1:0];
    wire [11:0] exp_tried12;
    wire [31:0] imp_word;
    wire        imp_word_valid;
    wire [WW-1:0] imp_index;
    wire        exp_idle, exp_done, exp_cut, exp_fails, exp_ready;
    wire [3:0]  exp_published, exp_corrupt, exp_known;
    wire [7:0]  exp_act, exp_tried;
    wire [1:0]  exp_dest;
    wire [WW-1:0] exp_index;
    wire [2:0]  r_cyc, r_we;
    wire [3*AW-1:0] r_adr;
    wire [11:0] r_sel;
    wire [95:0] r_wdat;
    wire [31:0] bus_rdat;
    wire [2:0]  r_ack, r_err;
    wire        imp_stb, exp_stb;
    wire        go = go_i;
    wire [AW-1:0]   src_base = f_sbase;
    wire [4*AW-1:0] dst_base = {{(2*AW){1'b0}}, f_dbase1, f_dbase0};
    wire [15:0]     dst_board = {4'd0, 4'd0, DST_B1, DST_B0};
    wire [WW-1:0]   words = f_w;

    wire        choose     = imp_run_q && !chosen_q && imp_sel;
    wire [3:0]  need_now   = (imp_new ? 4'hF : st_need) & ACTIVE;
    wire        exp_start  = choose && need_now != 4'd0;
    wire [3:0]  exp_need   = need_now;
    wire [7:0]  exp_tried_in = imp_new ? 8'd0 : st_tried;
    wire [11:0] exp_tried_in12 = {1'b0, exp_tried_in[7:6], 1'b0, exp_tried_in[5:4], 1'b0, exp_tried_in[3:2],
                                  1'b0, exp_tried_in[1:0]};
    assign exp_tried = {exp_tried12[10:9], exp_tried12[7:6], exp_tried12[4:3], exp_tried12[1:0]};
    wire [31:0] exp_taken  = imp_new ? time_i : st_taken;
    wire [3:0]  known_in;
    wire [7:0]  act_after;
    genvar g;
    generate
        for (g = 0; g < 4; g = g + 1) begin : g_known
            assign known_in[g] = st_act[2*g +: 2] != 2'd0;
            assign act_after[2*g +: 2] = exp_known[g] ? exp_act[2*g +: 2] : 2'd0;
        end
    endgenerate

    albatross_import #(.ADDR_WIDTH(AW), .WORDS_WIDTH(WW), .COUNT_WIDTH(1), .PULL(1)) u_import (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(go), .four_i(1'b0), .base_i(src_base), .words_i(words), .rl_known_i(st_rl != 2'd0),
        .rl_i({1'b0, st_rl}),
        .may_access_i(may_access_i), .idle_o(imp_idle),
        .selected_o(imp_sel), .stream_i(choose && need_now != 4'd0),
        .skip_i((choose && need_now == 4'd0) || (exp_run_q && exp_done)),
        .word_o(imp_word), .word_valid_o(imp_word_valid), .word_ready_i(exp_ready), .word_index_o(imp_index),
        .done_o(imp_done), .new_o(imp_new), .corrupt_o(imp_corrupt), .cut_o(imp_cut), .fails_o(imp_fails),
        .rl_known_o(imp_rl_known), .rl_o(imp_rl3),
        .wb_cyc_o(r_cyc[0]), .wb_stb_o(imp_stb), .wb_we_o(r_we[0]), .wb_adr_o(r_adr[0 +: AW]), .wb_sel_o(r_sel[0 +: 4]),
        .wb_dat_o(r_wdat[0 +: 32]), .wb_dat_i(bus_rdat), .wb_ack_i(r_ack[0]), .wb_err_i(r_err[0]));

    // The drop run K (ROM H2): any constant 0..3 (0 and 1 read as 2).
    (* anyconst *) reg [7:0] f_drop_run;
    always @* small_k: assume(f_drop_run <= 8'd3);
    albatross_export #(.ADDR_WIDTH(AW), .WORDS_WIDTH(WW), .COUNT_WIDTH(1), .TAKEN_AT(1), .DESTS(4), .DROP(1)) u_export (
        .clk_i(clk_i), .rst_i(rst_i),
        .drop_run_i(f_drop_run),
        .start_i(exp_start), .four_i(1'b0), .base_i(dst_base), .need_i(exp_need), .words_i(words), .taken_at_i(exp_taken),
        .act_known_i(known_in), .act_i(st_act), .tried_i(exp_tried_in12),
        .may_access_i(may_access_i), .idle_o(exp_idle),
        .word_i(imp_word), .word_valid_i(imp_word_valid), .word_ready_o(exp_ready), .word_index_o(exp_index),
        .done_o(exp_done), .published_o(exp_published), .corrupt_o(exp_corrupt), .cut_o(exp_cut),
        .fails_o(exp_fails), .act_known_o(exp_known), .act_o(exp_act), .tried_o(exp_tried12), .dest_o(exp_dest),
        .wb_cyc_o(r_cyc[1]), .wb_stb_o(exp_stb), .wb_we_o(r_we[1]), .wb_adr_o(r_adr[AW +: AW]), .wb_sel_o(r_sel[4 +: 4]),
        .wb_dat_o(r_wdat[32 +: 32]), .wb_dat_i(bus_rdat), .wb_ack_i(r_ack[1]), .wb_err_i(r_err[1]));

    assign r_cyc[2]          = 1'b0;          // no sync-mode poll
    assign r_we[2]           = 1'b0;
    assign r_adr[2*AW +: AW] = {AW{1'b0}};
    assign r_sel[8 +: 4]     = SEL_ACT;
    assign r_wdat[64 +: 32]  = 32'd0;

    wire          m_cyc, m_stb, m_we, fail;
    wire [AW+3:0] m_adr;
    wire [3:0]    m_sel;
    wire [31:0]   m_wdat;
    reg  [31:0]   m_rdat;
    wire [15:0]   fails_total;
    wire          overlap;
    albatross_bus_master #(.ADDR_WIDTH(AW), .BOARD_BITS(4), .REQS(3), .TIMEOUT(3)) u_bus (
        .clk_i(clk_i), .rst_i(rst_i),
        .r_cyc_i(r_cyc), .r_we_i(r_we), .r_adr_i(r_adr),
        .r_board_i({4'd0, dst_board[4*exp_dest +: 4], SRC_B}),
        .r_sel_i(r_sel), .r_dat_i(r_wdat), .r_dat_o(bus_rdat), .r_ack_o(r_ack), .r_err_o(r_err),
        .m_cyc_o(m_cyc), .m_stb_o(m_stb), .m_we_o(m_we), .m_adr_o(m_adr), .m_sel_o(m_sel),
        .m_dat_o(m_wdat), .m_dat_i(m_rdat), .m_ack_i(ack_i), .m_err_i(err_i),
        .fail_o(fail), .fails_o(fails_total), .overlap_o(overlap));

    reg        slot_end;
    reg [53:0] st_d;
    always @* begin
        slot_end    = (exp_run_q && exp_done) || (imp_run_q && !exp_run_q && imp_done);
        st_d[31:0]  = (chosen_q && new_q) ? taken_q : st_taken;
        st_d[33:32] = imp_run_q ? (imp_rl_known ? imp_rl : 2'd0) : st_rl;
        st_d[37:34] = exp_run_q ? need_q & ~exp_published : st_need;
        st_d[45:38] = exp_run_q ? act_after : st_act;
        st_d[53:46] = exp_run_q ? exp_tried : st_tried;
    end
    always @(posedge clk_i) begin
        if (rst_i) begin
            imp_run_q <= 1'b0;
            exp_run_q <= 1'b0;
            chosen_q  <= 1'b0;
            new_q     <= 1'b0;
            st_rl     <= 2'd0;               // the state RAM is cleared after reset
            st_need   <= 4'd0;
            st_act    <= 8'd0;
            st_tried  <= 8'd0;
            st_taken  <= 32'd0;
        end else begin
            if (go) begin
                imp_run_q <= 1'b1;
                exp_run_q <= 1'b0;
                chosen_q  <= 1'b0;
                new_q     <= 1'b0;
                need_q    <= ACTIVE;
            end
            if (choose) begin
                chosen_q <= 1'b1;
                new_q    <= imp_new;
                need_q   <= need_now;
                taken_q  <= exp_taken;
                if (need_now != 4'd0) exp_run_q <= 1'b1;
            end
            if (slot_end) begin
                imp_run_q <= 1'b0;
                exp_run_q <= 1'b0;
                {st_tried, st_act, st_need, st_rl, st_taken} <= st_d;
            end
        end
    end

`ifdef FORMAL
    // ---------------------------------------------------------------- reset
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);
    always @* if (go) assume(!imp_run_q && !exp_run_q && imp_idle && exp_idle);

    // ------------------------------------------------------------ the system bus
    wire       f_pv, f_out, f_rack;
    wire [3:0] f_wait;
    fwb_master #(.AW(AW+4), .DW(32), .OPT_ABORT(1)) wb (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(m_cyc), .stb_i(m_stb), .we_i(m_we), .adr_i(m_adr),
        .sel_i(m_sel), .wdat_i(m_wdat), .rdat_i(m_rdat), .ack_i(ack_i), .err_i(err_i),
        .f_past_valid_o(f_pv), .f_outstanding_o(f_out), .f_wait_o(f_wait), .f_read_ack_o(f_rack));

    wire          req   = m_cyc && m_stb;
    wire          ackm  = req && ack_i;
    wire          lands = req && m_we && !rst_i && (ack_i || (fail && land_i));   // a store takes effect at this edge
    wire [3:0]    brd   = m_adr[AW +: 4];
    wire [AW-1:0] wadr  = m_adr[AW-1:0];
    /* verilator lint_off UNUSEDSIGNAL */
    wire [AW+WW-1:0] w_wide = {{AW{1'b0}}, f_w};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [AW-1:0] w_a   = w_wide[AW-1:0];
    // source: stride W
    wire [AW-1:0] s_off  = wadr - f_sbase;
    wire          at_src = brd == SRC_B;
    wire          s_ctrl = s_off == {AW{1'b0}};
    wire          s_inb  = s_off >= BUF_W && s_off < BUF_W + w_a + w_a + w_a;
    wire [1:0]    s_buf  = s_off < BUF_W + w_a ? 2'd1 : s_off < BUF_W + w_a + w_a ? 2'd2 : 2'd3;
    wire [AW-1:0] s_k    = s_off - BUF_W - (s_buf == 2'd1 ? {AW{1'b0}} : s_buf == 2'd2 ? w_a : w_a + w_a);
    // destinations: stride W + 1
    wire [AW-1:0] st_a   = w_a + 1'b1;
    wire          at_d0  = brd == DST_B0;
    wire          at_d1  = brd == DST_B1;
    wire          at_d   = at_d0 || at_d1;
    wire          d_ix   = at_d1;
    wire [AW-1:0] d_off  = wadr - (at_d1 ? f_dbase1 : f_dbase0);
    wire          d_ctrl = d_off == {AW{1'b0}};
    wire          d_inb  = d_off >= BUF_W && d_off < BUF_W + st_a + st_a + st_a;
    wire [1:0]    d_buf  = d_off < BUF_W + st_a ? 2'd1 : d_off < BUF_W + st_a + st_a ? 2'd2 : 2'd3;
    wire [AW-1:0] d_k    = d_off - BUF_W - (d_buf == 2'd1 ? {AW{1'b0}} : d_buf == 2'd2 ? st_a : st_a + st_a);
    wire [AW-1:0] fk_a   = {{(AW-WW-1){1'b0}}, f_k};
    wire [2:0]    wr_ix  = {1'b0, d_ix, 1'b0} + {1'b0, d_ix} + {1'b0, d_buf} - 3'd1;   // 3d + b - 1

    // ------------------------------------------------------------ the source channel
    reg  [7:0]  s_act, s_rl;
    reg  [127:0] s_word;           // word f_k of buffer b at [32b +: 32] (b = 1..3; 0 unused)
    reg  [1:0]  p_act;
    reg         p_busy;
    reg  [1:0]  p_wb;
    wire        s_rl_ok   = s_rl[7:2] == 6'd0 && s_rl[1:0] != 2'd0;
    wire        p_begin   = !p_busy && pr_begin_i;
    wire [1:0]  p_wb_n    = p_begin ? pr_wb_i : p_wb;
    wire        p_publish = (p_busy || p_begin) && pr_publish_i;
    always @* begin
        if (init_q) begin
            assume(p_act != 2'd0 && s_act == {6'd0, p_act});
            assume(!p_busy || (p_wb != 2'd0 && p_wb != p_act && (!s_rl_ok || p_wb != s_rl[1:0])));
        end
        if (p_begin) assume(pr_wb_i != 2'd0 && pr_wb_i != p_act && (!s_rl_ok || pr_wb_i != s_rl[1:0]));
    end
    always @(posedge clk_i) begin
        if (p_busy && pr_write_i) s_word[32*p_wb +: 32] <= pr_data_i;   // writes WB while busy
        if (p_publish) begin
            p_act  <= p_wb_n;
            p_busy <= 1'b0;
            s_act  <= {6'd0, p_wb_n};
        end else if (p_begin) begin
            p_busy <= 1'b1;
            p_wb   <= pr_wb_i;
        end
        if (lands && at_src && s_ctrl && m_sel[RL_BIT / 8]) s_rl <= m_wdat[RL_BIT +: 8];
    end

    // ------------------------------------------------------------ the destinations
    // destination d's fields: Actual d_act[8d +: 8], ReadLocked d_rl[8d +: 8],
    // word f_k of buffer b d_word[32(3d + b - 1) +: 32]; its consumer's state
    // c_st[2d +: 2] (0 idle, 1 store pending, 2 reading), the loaded Actual to
    // store c_x[2d +: 2], its ReadLocked copy c_rl[2d +: 2]
    localparam [1:0] C_IDLE = 2'd0, C_STORE = 2'd1, C_READ = 2'd2;
    reg  [15:0]  d_act, d_rl;
    reg  [255:0] d_word;           // (8 slots: an index 3d + b - 1 out of 0..5 reads a slot never written)
    reg  [3:0]   c_st, c_x, c_rl;
    integer d;
    always @* begin
        // at the start a consumer may be anywhere in figure 3: reading the
        // buffer its ReadLocked names, or about to store an Actual it loaded
        if (init_q) begin
            assume(d_rl[7:0] == {6'd0, c_rl[1:0]} && d_rl[15:8] == {6'd0, c_rl[3:2]});
            for (d = 0; d < 2; d = d + 1) begin
                assume(c_st[2*d +: 2] != 2'd3 && (!f_atomic || c_st[2*d +: 2] != C_STORE));
                assume(c_st[2*d +: 2] != C_READ || c_rl[2*d +: 2] != 2'd0);
                assume(c_st[2*d +: 2] != C_STORE || c_x[2*d +: 2] != 2'd0);
            end
        end
    end
    reg [7:0] a_d;
    reg       a_ok;
    always @(posedge clk_i) begin
        for (d = 0; d < 2; d = d + 1) begin
            a_d  = d_act[8*d +: 8];
            a_ok = a_d[7:2] == 6'd0 && a_d[1:0] != 2'd0;
            case (c_st[2*d +: 2])
                C_IDLE: if (c_load_i[d] && a_ok) begin
                    if (a_d[1:0] == c_rl[2*d +: 2]) c_st[2*d +: 2] <= C_READ;
                    else if (f_atomic || c_store_i[d]) begin
                        d_rl[8*d +: 8] <= a_d;
                        c_rl[2*d +: 2] <= a_d[1:0];
                    end else begin
                        c_x[2*d +: 2]  <= a_d[1:0];
                        c_st[2*d +: 2] <= C_STORE;
                    end
                end
                C_STORE: if (c_store_i[d]) begin
                    d_rl[8*d +: 8] <= {6'd0, c_x[2*d +: 2]};
                    c_rl[2*d +: 2] <= c_x[2*d +: 2];
                    c_st[2*d +: 2] <= C_IDLE;
                end
                C_READ: if (c_end_i[d]) c_st[2*d +: 2] <= C_IDLE;
                default: c_st[2*d +: 2] <= C_IDLE;
            endcase
            if (lands && at_d && d_ix == d[0] && d_ctrl) begin
                if (m_sel[ACT_BIT / 8]) d_act[8*d +: 8] <= m_wdat[ACT_BIT +: 8];
                if (m_sel[RL_BIT / 8])  d_rl[8*d +: 8]  <= m_wdat[RL_BIT +: 8];
            end
        end
        if (lands && at_d && d_inb && d_k == fk_a) d_word[32*wr_ix +: 32] <= m_wdat;
    end

    // ------------------------------------------------------------ read data
    always @* begin
        m_rdat = rdat_i;
        if (at_src && s_ctrl) begin
            m_rdat[ACT_BIT +: 8] = s_act;
            m_rdat[RL_BIT +: 8]  = s_rl;
        end else if (at_src && s_inb && s_k == fk_a) begin
            m_rdat = s_word[32*s_buf +: 32];
        end else if (at_d && d_ctrl) begin
            m_rdat[ACT_BIT +: 8] = d_act[8*d_ix +: 8];
            m_rdat[RL_BIT +: 8]  = d_rl[8*d_ix +: 8];
        end
    end

    // ------------------------------------------------------------ trackers
    reg        f_lk_ok;              // a source word was loaded in this slot ...
    reg [AW-1:0] f_lk;               // ... its index
    reg [31:0] f_ldata;              // ... its data
    reg [1:0]  f_pend;               // destinations that still need the last loaded word
    reg        f_clean;              // no failed access in this slot
    reg [5:0]  f_wr;                 // word f_k of buffer b at d stored in this Export: bit 3d + b - 1
    wire       s_wld = req && at_src && !m_we && s_inb;          // a source word load
    wire       d_wst = req && at_d && m_we && d_inb;             // a store into a destination buffer
    wire       d_ast = req && at_d && m_we && d_ctrl;            // a store to a destination's control word
    wire [1:0] pub_b = m_wdat[ACT_BIT +: 2];
    wire [2:0] pub_ix = {1'b0, d_ix, 1'b0} + {1'b0, d_ix} + {1'b0, pub_b} - 3'd1;
    always @(posedge clk_i) begin
        if (rst_i || go) begin
            f_lk_ok <= 1'b0;
            f_pend  <= 2'b00;
            f_clean <= 1'b1;
        end else begin
            if (req && fail) f_clean <= 1'b0;
            if (s_wld && ackm) begin
                f_lk_ok <= 1'b1;
                f_lk    <= s_k;
                f_ldata <= m_rdat;
                f_pend  <= need_q[1:0] & ~exp_published[1:0];
            end
            if (d_wst && ackm && d_k != w_a) f_pend[d_ix] <= 1'b0;
        end
        if (rst_i || exp_start) f_wr <= 6'd0;
        else if (d_wst && ackm && d_k == fk_a) f_wr[wr_ix] <= 1'b1;
    end

    // ------------------------------------------------------------ properties
    wire [31:0] expect_w = f_k == w1 ? taken_q : s_word[32*s_rl[1:0] +: 32];
    wire        pub_ok   = pub_b != 2'd0 && m_wdat[ACT_BIT + 2 +: 6] == 6'd0;
    wire        lowest_ok = d_ix == 1'b0 || !f_pend[0];
    always @* begin
        if (!init_q) begin
            publish_value:    assert(!d_ast || !pub_ok || d_word[32*pub_ix +: 32] == expect_w);
            publish_complete: assert(!d_ast || !pub_ok || f_wr[pub_ix]);
            no_write_read:    assert(!d_wst || !(c_st[2*d_ix +: 2] == C_READ && c_rl[2*d_ix +: 2] == d_buf));
            no_write_locked:  assert(!d_wst || !f_atomic || d_rl[8*d_ix +: 8] != {6'd0, d_buf});
            dest_stores:      assert(!(req && at_d) || (m_we ? (!d_ctrl || (m_sel == SEL_ACT && pub_ok)) : d_ctrl));
            src_stores:       assert(!(req && at_src && m_we) || (s_ctrl && m_sel == SEL_RL));
            in_channel:       assert(!req || (at_src && (s_ctrl || s_inb)) || (at_d && (d_ctrl || d_inb)));
            order_data:       assert(!d_wst || (d_k == w_a ? m_wdat == taken_q :
                                                (f_lk_ok && d_k == f_lk && m_wdat == f_ldata)));
            order_exact:      assert(!f_clean || ((!s_wld || f_pend == 2'b00) &&
                                                  (!(d_wst && d_k != w_a) || (f_pend[d_ix] && lowest_ok))));
            one_owner:        assert(!(r_cyc[0] && r_cyc[1]) && !overlap);
        end
    end

    // ------------------------------------------------------------ covers
    always @* begin
        if (!init_q) begin
            cover_publish:  cover(d_ast && ackm && d_ix && f_clean && f_k == 3'd0);
            cover_taken:    cover(d_ast && ackm && d_ix && f_clean && f_k == w1);
            cover_both:     cover(slot_end && exp_published[1:0] == 2'b11);
            cover_reading:  cover(d_wst && ackm && c_st[1:0] == C_READ && !f_atomic);
            cover_fail_pub: cover(d_ast && ackm && !f_clean);
        end
    end

`include "fcopy_inv.vh"
`endif

endmodule

`default_nettype wire
