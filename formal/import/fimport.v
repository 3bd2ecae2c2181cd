// fimport -- proof harness of albatross_import, the Import engine (the
// consumer's side of the three-buffer protocol, the paper, section 3.1 figure 3;
// formal/import/import.sby, docs/verification.md "Import engine (unbounded)").
//
// The engine's Wishbone master port is checked against formal/wb/fwb_master.v
// (requests asserted, answers assumed: any wait, ack or err).  The slave is a
// model of ONE channel at a symbolic base (anyconst) with a symbolic W = 1..3
// (anyconst): the control word holds Actual (byte 0) and ReadLocked (byte 1),
// bytes 2..3 and every buffer word read as free data.  The engine may only
// write ReadLocked.  A store answered with err may or may not have landed (a
// free input decides).  Rules of the environment:
//   * Reset in the first clock only.  base_i and words_i always name the one
//     channel; a start with a known ReadLocked copy (rl_known_i) gives the
//     value ReadLocked holds (the copy that the engine's rl_known_o/rl_o hand
//     back; rl_copy below proves that hand-back true).
//   * The producer is figure 4 with free timing, one atomic action a clock:
//     begin an Export (load ReadLocked and pick a buffer WB that is neither its
//     private copy of Actual nor that ReadLocked; an invalid ReadLocked locks
//     nothing), write WB during every clock it is busy, publish (Actual := WB,
//     possibly in the clock it began).  The abstraction of the brief (Actual
//     changes only to a buffer != ReadLocked; only buffers that are neither
//     Actual nor ReadLocked are written) is NOT what a real producer does: a
//     consumer that stores ReadLocked := an Actual it loaded before the
//     producer's last publish can make ReadLocked name the buffer the producer
//     is writing; figure 3 is safe only through its confirming load.  This
//     model includes that case.  A fault may also set Actual to an invalid
//     byte (never to a valid one: that is a second producer).
//   * may_access_i, stream_i, skip_i, word_ready_i are free.
// Properties (labels, all from reset, every clock; "word load" = a request
// with we = 0 at a buffer word, "req" = cyc & stb):
//   store_rl_only     every store is to the control word with sel = the
//                     ReadLocked lane only;
//   store_valid       the stored byte is 1..3 ...
//   store_loaded      ... and equals the last Actual loaded (ReadLocked := Actual);
//   in_channel        every access lies inside the channel;
//   lanes             a control load selects the Actual lane only, a word
//                     load all four lanes;
//   load_confirmed    every word load is at word f_k (the stream's index) of the
//                     buffer that the last Actual load returned when it was equal
//                     to ReadLocked in the RAM, with no ReadLocked store since
//                     (the confirming load of figure 3);
//   load_is_rl        ... that buffer is the one ReadLocked names now;
//   load_not_written  ... and is not the buffer the producer may be writing now
//                     (mutual exclusion with the figure-4 producer);
//   select_confirmed  selected_o only after such a confirming load, and the
//                     copy handed out (rl_known_o, rl_o) names that buffer;
//   new_exact         at selected_o, and at done_o of an Import that was not cut
//                     off: new_o == a ReadLocked store was acked in this Import;
//   count_exact       undisturbed (no err, not cut off, Actual unchanged since
//                     start, no skip_i in phase 2): 1 control access (Old) or 3
//                     (New), plus W word loads when streamed (0 if corrupt);
//   no_idle           inside an Import cyc is low only in the clock after an
//                     err, while the caller decides (selected_o), while a word
//                     waits for word_ready_i (word_valid_o), or (PULL) while the
//                     engine waits for word_ready_i to ask for the next word;
//   pull_rule         (PULL) a word load begins only in the clock after one
//                     where word_ready_i was high while the engine waited for it
//                     (or as the repeat of a failed load);
//   err_gap           cyc is low in the clock after an err ...
//   retry_same        ... and the next access is the failed one again;
//   cut_rule          an access begins only in the clock after an edge where
//                     may_access_i was 1;
//   stream_word       word_valid_o carries word f_k, whose data is the data of
//                     its load;
//   rl_copy           when idle, a known copy (rl_known_o) names a buffer and
//                     is what ReadLocked holds in the RAM.
// Induction strengthening (white-box): with -DF_PROBE the script joins the
// f_* probe wires to the engine's registers after flatten (Yosys has no
// hierarchical references) and the inv_* assertions tie them to the model.
`default_nettype none

module fimport #(
    parameter ADDR_WIDTH  = 4,  // word-address bits of the port
    parameter WORDS_WIDTH = 2,  // bits of W (W = 1..3)
    parameter PULL        = 1   // the engine's PULL (1: as albatross_controller wires it)
) (
    input  wire                   clk_i,
    input  wire                   rst_i,
    input  wire                   start_i,
    input  wire [ADDR_WIDTH-1:0]  base_i,
    input  wire [WORDS_WIDTH-1:0] words_i,
    input  wire                   rl_known_i,
    input  wire [1:0]             rl_i,
    input  wire                   may_access_i,
    input  wire                   stream_i,
    input  wire                   skip_i,
    input  wire                   word_ready_i,
    // the slave
    input  wire                   ack_i,
    input  wire                   err_i,
    input  wire                   land_i,     // a store answered with err landed
    input  wire [31:0]            rdat_i,     // free read data (buffers, bytes 2..3)
    // the producer
    input  wire                   pr_begin_i,
    input  wire [1:0]             pr_wb_i,
    input  wire                   pr_publish_i,
    input  wire                   pr_corrupt_i,
    input  wire [7:0]             pr_bad_i
);

`include "albatross_contract.vh"

    localparam integer BUF_I   = ALB_CH_OFF_BUFFERS / ALB_CH_WORD_BYTES;
    localparam integer CTRL_I  = ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES;
    localparam [ADDR_WIDTH-1:0] BUF_W  = BUF_I[ADDR_WIDTH-1:0];
    localparam [ADDR_WIDTH-1:0] CTRL_W = CTRL_I[ADDR_WIDTH-1:0];
    localparam integer ACT_BIT = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam integer RL_BIT  = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [3:0]   SEL_ACT = 4'b0001 << (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0]   SEL_RL  = 4'b0001 << (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam         AW      = ADDR_WIDTH;
    localparam         WW      = WORDS_WIDTH;

    wire          idle, selected, word_valid, done, new_v, corrupt, cut, rl_known;
    wire [31:0]   word;
    wire [WW-1:0] word_index;
    wire [1:0]    fails;
    wire [2:0]    rl3;      // the engine's copy: 3 bits (four-slot L), here three-buffer only
    wire [1:0]    rl = rl3[1:0];
    wire          cyc, stb, we;
    wire [AW-1:0] adr;
    wire [3:0]    sel;
    wire [31:0]   wdat;
    reg  [31:0]   rdat;

    albatross_import #(.ADDR_WIDTH(AW), .WORDS_WIDTH(WW), .COUNT_WIDTH(2), .PULL(PULL)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(start_i), .base_i(base_i), .words_i(words_i), .four_i(1'b0), .rl_known_i(rl_known_i),
        .rl_i({1'b0, rl_i}), .may_access_i(may_access_i), .idle_o(idle),
        .selected_o(selected), .stream_i(stream_i), .skip_i(skip_i),
        .word_o(word), .word_valid_o(word_valid), .word_ready_i(word_ready_i), .word_index_o(word_index),
        .done_o(done), .new_o(new_v), .corrupt_o(corrupt), .cut_o(cut), .fails_o(fails),
        .rl_known_o(rl_known), .rl_o(rl3),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_sel_o(sel),
        .wb_dat_o(wdat), .wb_dat_i(rdat), .wb_ack_i(ack_i), .wb_err_i(err_i)
    );

`ifdef FORMAL
    // ---------------------------------------------------------------- reset
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);

    // ------------------------------------------------------------ Wishbone
    wire          f_pv, f_out, f_rack;
    wire [3:0]    f_wait;
    fwb_master #(.AW(AW), .DW(32)) wb (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(cyc), .stb_i(stb), .we_i(we), .adr_i(adr),
        .sel_i(sel), .wdat_i(wdat), .rdat_i(rdat), .ack_i(ack_i), .err_i(err_i),
        .f_past_valid_o(f_pv), .f_outstanding_o(f_out), .f_wait_o(f_wait), .f_read_ack_o(f_rack));

    // ------------------------------------------------------------ the channel
    (* anyconst *) reg [AW-1:0] f_base;
    (* anyconst *) reg [WW-1:0] f_w;
    always @* begin
        assume(f_w != {WW{1'b0}});
        assume(base_i == f_base);
        assume(words_i == f_w);
    end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [AW+WW-1:0] w_wide = {{AW{1'b0}}, f_w};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [AW-1:0] w_a   = w_wide[AW-1:0];
    wire [AW-1:0] off   = adr - f_base;                       // word offset in the channel
    wire [AW-1:0] b1    = BUF_W;                              // first word of each buffer
    wire [AW-1:0] b2    = BUF_W + w_a;
    wire [AW-1:0] b3    = BUF_W + w_a + w_a;
    wire [AW-1:0] b_end = BUF_W + w_a + w_a + w_a;
    wire          is_ctrl = off == CTRL_W;
    wire          is_buf  = off >= b1 && off < b_end;
    wire [1:0]    buf_of  = off < b2 ? 2'd1 : off < b3 ? 2'd2 : 2'd3;
    wire [AW-1:0] k_of    = off - (buf_of == 2'd1 ? b1 : buf_of == 2'd2 ? b2 : b3);
    wire          req     = cyc && stb;
    wire          ctrl_ld = req && !we && is_ctrl;
    wire          word_ld = req && !we && !is_ctrl;

    reg  [7:0] mem_act;   // Actual in the RAM
    reg  [7:0] mem_rl;    // ReadLocked in the RAM
    always @* begin
        rdat = rdat_i;
        if (is_ctrl) begin
            rdat[ACT_BIT +: 8] = mem_act;
            rdat[RL_BIT +: 8]  = mem_rl;
        end
    end
    wire [7:0] ld_act   = rdat[ACT_BIT +: 8];
    wire       ld_valid = ld_act[7:2] == 6'd0 && ld_act[1:0] != 2'd0;
    wire       rl_valid = mem_rl[7:2] == 6'd0 && mem_rl[1:0] != 2'd0;
    wire       wr_now   = req && we && (ack_i || (err_i && land_i));   // a store lands at this edge

    // ------------------------------------------------------------ the producer
    reg  [1:0] p_act;     // its private copy of Actual
    reg        p_busy;    // an Export under way: writing p_wb
    reg  [1:0] p_wb;
    wire       p_begin   = !p_busy && pr_begin_i;
    wire [1:0] p_wb_n    = p_begin ? pr_wb_i : p_wb;
    wire       p_publish = (p_busy || p_begin) && pr_publish_i;
    wire       p_corrupt = pr_corrupt_i && !p_publish;
    always @* begin
        if (init_q) begin
            assume(p_act != 2'd0 && mem_act == {6'd0, p_act});
            assume(!p_busy || (p_wb != 2'd0 && p_wb != p_act && (!rl_valid || p_wb != mem_rl[1:0])));
        end
        if (p_begin) assume(pr_wb_i != 2'd0 && pr_wb_i != p_act && (!rl_valid || pr_wb_i != mem_rl[1:0]));
        if (p_corrupt) assume(pr_bad_i[7:2] != 6'd0 || pr_bad_i[1:0] == 2'd0);
    end
    always @(posedge clk_i) begin
        if (p_publish) begin
            p_act   <= p_wb_n;
            p_busy  <= 1'b0;
            mem_act <= {6'd0, p_wb_n};
        end else begin
            if (p_begin) begin
                p_busy <= 1'b1;
                p_wb   <= pr_wb_i;
            end
            if (p_corrupt) mem_act <= pr_bad_i;
        end
        // the engine's stores (it should store only ReadLocked)
        if (wr_now && is_ctrl && sel[RL_BIT / 8])  mem_rl  <= wdat[RL_BIT +: 8];
        if (wr_now && is_ctrl && sel[ACT_BIT / 8]) mem_act <= wdat[ACT_BIT +: 8];
    end
    // a known copy at start is what ReadLocked holds
    always @* if (start_i && idle && rl_known_i) assume(rl_i != 2'd0 && mem_rl == {6'd0, rl_i});

    // ------------------------------------------------------------ trackers
    reg        f_prev_req = 1'b0, f_prev_ans = 1'b0, f_prev_may = 1'b0;
    reg        f_retry = 1'b0;       // this clock follows an err
    reg        f_after_retry = 1'b0; // this clock follows a retry clock
    reg        f_fail_we;
    reg [AW-1:0] f_fail_adr;
    reg [3:0]  f_fail_sel;
    wire       f_begin = req && (!f_prev_req || f_prev_ans);   // an access begins in this clock
    wire       f_start = start_i && idle && !rst_i;
    reg [2:0]  f_nctrl, f_nword;     // control accesses / word loads begun in this Import
    reg        f_err, f_act_chg, f_skip2, f_streamed, f_stored;
    reg        f_conf_ok;            // the last Actual load confirmed ReadLocked ...
    reg [1:0]  f_conf;               // ... naming this buffer
    reg        f_last_ok;            // the last Actual load named a buffer ...
    reg [1:0]  f_last_act;           // ... this one
    reg [WW-1:0] f_k;                // index of the stream's current word
    reg [31:0] f_wdata;              // data of the last word load
    reg        f_pwait = 1'b0;       // (PULL) phase 2, the next word load waits for word_ready_i
    reg        f_pwait_go = 1'b0;    // the last clock had f_pwait and word_ready_i
    wire       ld_ack   = ctrl_ld && ack_i;
    wire       conf_now = ld_ack && ld_valid && mem_rl == {6'd0, ld_act[1:0]};
    wire       w_conf_ok = ld_ack ? conf_now : f_conf_ok;
    wire [1:0] w_conf    = ld_ack ? ld_act[1:0] : f_conf;
    wire       taken    = word_valid && word_ready_i;
    wire       last_k   = f_k == f_w - 1'b1;
    always @(posedge clk_i) begin
        f_prev_req    <= req && !rst_i;
        f_prev_ans    <= req && (ack_i || err_i);
        f_prev_may    <= may_access_i;
        f_retry       <= req && err_i && !rst_i;
        f_after_retry <= f_retry;
        if (req && err_i) begin
            f_fail_we  <= we;
            f_fail_adr <= adr;
            f_fail_sel <= sel;
        end
        f_pwait_go <= f_pwait && word_ready_i && !idle;
        if (f_start || rst_i) begin
            f_nctrl    <= 3'd0;
            f_nword    <= 3'd0;
            f_err      <= 1'b0;
            f_act_chg  <= 1'b0;
            f_skip2    <= 1'b0;
            f_streamed <= 1'b0;
            f_stored   <= 1'b0;
            f_conf_ok  <= 1'b0;
            f_last_ok  <= 1'b0;
            f_k        <= {WW{1'b0}};
            f_pwait    <= 1'b0;
        end else begin
            if (f_begin && is_ctrl && f_nctrl != 3'd7) f_nctrl <= f_nctrl + 3'd1;
            if (f_begin && !is_ctrl && f_nword != 3'd7) f_nword <= f_nword + 3'd1;
            if (req && err_i) f_err <= 1'b1;
            if (f_streamed && skip_i) f_skip2 <= 1'b1;
            if (selected && stream_i) begin
                f_streamed <= 1'b1;
                f_k        <= {WW{1'b0}};
            end
            if (req && we && ack_i) f_stored <= 1'b1;
            if (wr_now) f_conf_ok <= 1'b0;
            if (ld_ack) begin
                f_conf_ok  <= conf_now;
                f_conf     <= ld_act[1:0];
                f_last_ok  <= ld_valid;
                f_last_act <= ld_act[1:0];
            end
            if (taken && !last_k) f_k <= f_k + 1'b1;
            // (PULL) waiting for word_ready_i: after stream_i, after a word is
            // taken; over with word_ready_i, skip_i or the cut-off
            if (PULL != 0 && ((selected && stream_i) || (taken && !last_k))) f_pwait <= 1'b1;
            else if (word_ready_i || skip_i || !may_access_i) f_pwait <= 1'b0;
        end
        if (!f_start && (p_publish || p_corrupt)) f_act_chg <= 1'b1;
        if (word_ld && ack_i) f_wdata <= rdat;
    end

    // ------------------------------------------------------------ properties
    wire [7:0] st_byte = wdat[RL_BIT +: 8];
    always @* begin
        if (!init_q) begin
            store_rl_only:    assert(!(req && we) || (is_ctrl && sel == SEL_RL));
            store_valid:      assert(!(req && we) || (st_byte[7:2] == 6'd0 && st_byte[1:0] != 2'd0));
            store_loaded:     assert(!(req && we) || (f_last_ok && st_byte[1:0] == f_last_act));
            in_channel:       assert(!req || is_ctrl || is_buf);
            lanes:            assert(!req || (is_ctrl ? (we || sel == SEL_ACT) : sel == 4'hF));
            load_confirmed:   assert(!word_ld || (f_conf_ok && buf_of == f_conf && k_of == {{(AW-WW){1'b0}}, f_k}));
            load_is_rl:       assert(!word_ld || mem_rl == {6'd0, buf_of});
            load_not_written: assert(!word_ld || !(p_busy && buf_of == p_wb));
            select_confirmed: assert(!selected || (w_conf_ok && rl_known && rl == w_conf));
            new_exact:        assert(!(selected || (done && !cut)) || new_v == f_stored);
            count_exact:      assert(!(done && !cut && !f_err && !f_act_chg && !f_skip2) ||
                                     (f_nctrl == (new_v ? 3'd3 : 3'd1) &&
                                      f_nword == ((f_streamed && !corrupt) ? {1'b0, f_w} : 3'd0)));
            no_idle:          assert(idle || req || f_retry || selected || word_valid ||
                                     (PULL != 0 && f_pwait && !f_pwait_go));
            pull_rule:        assert(PULL == 0 || !(f_begin && !is_ctrl) || f_pwait_go || f_after_retry);
            err_gap:          assert(!f_retry || !req);
            retry_same:       assert(!(f_after_retry && req) || (we == f_fail_we && adr == f_fail_adr && sel == f_fail_sel));
            cut_rule:         assert(!f_begin || f_prev_may);
            stream_word:      assert(!word_valid || (word_index == f_k && (word_ld || word == f_wdata)));
            rl_copy:          assert(!(idle && rl_known) || (rl != 2'd0 && mem_rl == {6'd0, rl}));
        end
    end

    // ------------------------------------------------------------ covers
    always @* begin
        if (!init_q) begin
            cover_new_loop:   cover(done && !cut && new_v && f_nctrl == 3'd5 && f_nword == 3'd3);
            cover_count_new:  cover(done && !cut && !f_err && !f_act_chg && !f_skip2 && new_v && f_nword == 3'd3);
            cover_old_stream: cover(done && !cut && !new_v && !f_err && f_nword == {1'b0, f_w} && f_w == 2'd2);
            cover_corrupt:    cover(done && corrupt && new_v);
            cover_retry:      cover(done && !cut && f_err && f_streamed && f_stored);
            cover_cut_forget: cover(done && cut && f_stored && !rl_known);
            cover_hold:       cover(word_valid && !word_ld && word_ready_i && f_nword == 3'd2);
            // the producer writes the buffer ReadLocked names (a real producer
            // does; the brief's abstraction forbids it), and writes during a stream
            cover_wb_is_rl:   cover(p_busy && rl_valid && p_wb == mem_rl[1:0] && !idle);
            cover_concurrent: cover(word_ld && ack_i && p_busy && f_k == 2'd1);
        end
    end

    // ------------------------------------------------------------ induction strengthening
`ifdef F_PROBE
    (* keep *) wire [2:0]    f_state;    // dut.state_q
    (* keep *) wire          f_stb;      // dut.stb
    (* keep *) wire [AW-1:0] f_adr;      // dut.adr_q
    (* keep *) wire [WW-1:0] f_dwords;   // dut.words_q
    (* keep *) wire [WW-1:0] f_dk;       // dut.k_q
    (* keep *) wire [2:0]    f_dact3;    // dut.act_q
    (* keep *) wire          f_dfour;    // dut.four_q
    wire [1:0] f_dact = f_dact3[1:0];
    (* keep *) wire          f_dretry;   // dut.retry_q
    (* keep *) wire          f_dnew;     // dut.new_q
    (* keep *) wire          f_drlk;     // dut.rl_known
    (* keep *) wire [2:0]    f_drl3;     // dut.rl_q
    wire [1:0] f_drl = f_drl3[1:0];
    (* keep *) wire [31:0]   f_dword;    // dut.word_q
    (* keep *) wire          f_dwe;      // dut.we
    (* keep *) wire [3:0]    f_dsel;     // dut.sel
    localparam [2:0] S_IDLE = 3'd0, S_LOAD_ACTUAL = 3'd1, S_STORE_RL = 3'd2, S_SELECTED = 3'd3,
                     S_LOAD_WORD = 3'd4, S_HOLD_WORD = 3'd5, S_WAIT_PULL = 3'd6;
    wire accessing = f_state == S_LOAD_ACTUAL || f_state == S_STORE_RL || f_state == S_LOAD_WORD;
    wire in_p2     = f_state == S_LOAD_WORD || f_state == S_HOLD_WORD || f_state == S_WAIT_PULL;
    wire [AW-1:0] f_first = f_base + BUF_W + (f_drl == 2'd1 ? {AW{1'b0}} : f_drl == 2'd2 ? w_a : w_a + w_a);
    wire und = !f_err && !f_act_chg && !f_skip2;                  // undisturbed so far
    wire [2:0] w_nctrl = f_nctrl + {2'd0, f_begin && is_ctrl};     // counts with this clock's begin
    wire [2:0] w_nword = f_nword + {2'd0, f_begin && !is_ctrl};
    wire [2:0] n_ctl   = f_dnew ? 3'd3 : 3'd1;
    wire [2:0] dk3     = {{(3-WW){1'b0}}, f_dk};
    always @* begin
        if (!init_q) begin
            inv_three:  assert(!f_dfour && (f_state != S_STORE_RL || !f_dact3[2]) && !f_drl3[2]);  // three-buffer only
            inv_state:  assert(f_state <= S_WAIT_PULL && (PULL != 0 || f_state != S_WAIT_PULL));
            inv_stb:    assert(f_stb == (accessing && !f_dretry));
            inv_retry:  assert(!f_dretry || accessing);
            inv_chan:   assert(f_state == S_IDLE || (f_dwords == f_w && !done && !cut && !corrupt));
            inv_ctrl:   assert(!(f_state == S_LOAD_ACTUAL || f_state == S_STORE_RL) ||
                               (f_adr == f_base + CTRL_W && f_dwe == (f_state == S_STORE_RL) &&
                                f_dsel == (f_state == S_STORE_RL ? SEL_RL : SEL_ACT)));
            inv_store:  assert(f_state != S_STORE_RL ||
                               (f_dnew && f_dact != 2'd0 && f_last_ok && f_dact == f_last_act && !f_streamed &&
                                (!und || (mem_act == {6'd0, f_dact} && w_nctrl == 3'd2 && f_nword == 3'd0))));
            inv_la:     assert(f_state != S_LOAD_ACTUAL ||
                               (f_dnew == f_stored && !f_streamed &&
                                (!f_drlk || (f_drl != 2'd0 && mem_rl == {6'd0, f_drl})) &&
                                (!f_dnew || (f_drlk && f_drl == f_dact)) &&
                                (!und || (w_nctrl == n_ctl && f_nword == 3'd0 &&
                                          (!f_dnew || mem_act == {6'd0, f_dact})))));
            inv_sel:    assert(f_state != S_SELECTED ||
                               (f_adr == f_base + CTRL_W && f_conf_ok && f_drlk && f_drl == f_conf && !f_streamed && f_dnew == f_stored && !f_dwe &&
                                (!und || (f_nctrl == n_ctl && f_nword == 3'd0))));
            inv_p2:     assert(!in_p2 || (f_dk < f_dwords && f_dk == f_k && !f_dwe && f_dsel == 4'hF &&
                                          f_adr == f_first + {{(AW-WW){1'b0}}, f_dk} &&
                                          f_drlk && f_drl == f_conf && f_conf_ok &&
                                          f_streamed && f_dnew == f_stored &&
                                          (!und || (f_nctrl == n_ctl &&
                                                    (f_state == S_LOAD_WORD ? w_nword == dk3 + 3'd1 :
                                                     f_state == S_HOLD_WORD ? f_nword == dk3 + 3'd1 :
                                                                              f_nword == dk3)))));
            inv_idle:   assert(f_state != S_IDLE || !f_drlk || (f_drl != 2'd0 && mem_rl == {6'd0, f_drl}));
            inv_conf:   assert(!f_conf_ok || (mem_rl == {6'd0, f_conf} && f_conf != 2'd0));
            inv_hold:   assert(f_state != S_HOLD_WORD || f_dword == f_wdata);
            inv_pwait:  assert(PULL == 0 || (f_pwait == (f_state == S_WAIT_PULL) &&
                                             (!f_pwait_go || f_state != S_WAIT_PULL)));
            inv_prod:   assert(p_act != 2'd0 && (!p_busy || (p_wb != 2'd0 && p_wb != p_act)) &&
                               (mem_act == {6'd0, p_act} || mem_act[7:2] != 6'd0 || mem_act[1:0] == 2'd0));
            inv_excl:   assert(!(p_busy && f_conf_ok && p_wb == f_conf));
        end
    end
`endif
`endif

endmodule

`default_nettype wire
