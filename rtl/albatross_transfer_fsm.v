// albatross_transfer_fsm -- the state machine of the transfer datapath
// (albatross_transfer): one state register that runs, on one Wishbone B4
// classic requester port, the consumer's Import of the source (the paper's
// figure 3; four-slot kind: Simpson's mechanism on single-writer bytes) and
// the producer's Export (figure 4) to up to 4 destinations, streaming the
// value word by word (one source load, then one store per destination).
// Rules:
//   * Entry fields and per-channel state as albatross_transfer states them;
//     no per-channel state is kept here between slots.
//   * COPY, Import (source, the controller is the consumer).  Three-buffer:
//     load Actual; if it differs from the ReadLocked copy (0 unknown), store
//     ReadLocked := Actual and load Actual again, until a load equals the
//     copy (New if a store was made).  Four-slot: load the control word, c =
//     1 + 2 pair(A) + Slot[pair(A)]; c = L: Old; else store ReadLocked := A,
//     load the control word again, L := 1 + 2 pair(A) + Slot[pair(A)]: New.
//     Actual naming no buffer ends the slot (corrupt; 0, not started:
//     nothing new, no count).  In the ack clock of the final control load
//     the value is chosen: the destinations that need it are all active ones
//     if New (new_o: taken_at := the time now), else those still in need
//     (st_need_i); none: the slot ends.  A cut-off after a
//     ReadLocked store and before its confirming load forgets the copy.
//   * REQUEST (request_i, a COPY with no destination): a New value's word 0
//     is loaded (buffer rl, k = 0) and, in the clock of its ack, offered
//     as a mode request (mode_req_o, mode_req_mode_o: its low 4 bits, 15 if
//     a higher bit is set); then the slot ends.  An Old value ends the slot
//     at once.
//   * Export, to the destinations d in need in index order: per d, load its
//     whole control word (both kinds: Actual with ReadLocked, so no copy of
//     Actual is kept); an Actual equal to the buffer of a failed Actual
//     store shows it landed: published, d leaves (four-slot: only if the Slot
//     byte names that buffer too); four-slot, a Slot byte naming the buffer of
//     this value's Slot store (tried) while Actual does not shows the value
//     complete and unpublished: store Actual := that buffer at once (S_DST_PUB,
//     no word written again: the value is never completed twice), then d
//     leaves, published; else pick the buffer
//     (albatross_transfer_pick: neither Actual nor ReadLocked; four-slot
//     from ReadLocked and the Slot bytes); then per word k: one source load
//     (COPY; TIME: the slot time; STATUS: status_i at index_o) and one store
//     per d; then per d taken_at (word W, stride W + 1), four-slot the Slot
//     byte, then Actual (published).  TIME and STATUS run the Export alone
//     from go_i.
//   * Failures (err_i, which includes the bus master's timeout): cyc drops
//     for one clock; then the same access again if may_access_i, else the
//     cut-off (the slot ends).  A destination access failing K = drop_run_i
//     (below 2: 2) times in a row drops that destination for the slot (the
//     next access follows in the clock after the K-th failure).  Source
//     accesses are retried until the deadline.  A destination's buffer
//     picked is its buffer tried (st_tried_i / tried_o), from its control
//     load until its Actual store is answered: a failed Actual store, or a
//     cut-off or a drop after its (four-slot) Slot store, leaves it for the
//     next control load to recognise.
//   * Timing: every access begins in the clock after an edge where
//     may_access_i is 1, in the clock after the previous ack (no idle bus
//     clock inside a transfer); go_i's first access is on the bus in the
//     next clock.  done_o is high for one clock after the last ack, the
//     cut-off or the decision that nothing is to be done.  Reset clears
//     control state only.
//   * Values over several runs (albatross_transfer_frag: cont_i, lastf_i,
//     mid_i): at go_i, cont_i (a run that goes on with a value) starts with
//     the source word load from the held buffer (st_rl_i) into the picked
//     buffers (st_tried_i) of the destinations still in the value
//     (st_need_i): no Import, no control load.  wend_o: the stores of a
//     word have ended (every destination still in the value has it); with
//     lastf_i the publication follows, else the next word, until the
//     deadline cuts the slot off.  need_any_o: a destination is still in
//     the value and not published; safe_o: none of those has had a Slot or
//     Actual store begun in this slot (a value may go on only then: a
//     begun one may have landed, which only a control load can tell).
//     need_o after a value that goes on (mid_i): the destinations still in
//     it, not published; aband_o: those dropped.
// Parts: albatross_transfer_pick (the control-word decode and the buffer
// picks), albatross_transfer_dest (the per-destination registers),
// albatross_transfer_order (the destinations' order).
`default_nettype none

module albatross_transfer_fsm (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    // the entry (sequencer registers, held for the slot; albatross_transfer's ports)
    input  wire        go_i, copy_i, time_kind_i, four_i, request_i,
    input  wire [3:0]  active_i,
    input  wire        may_access_i,   // an access begun next clock ends before the deadline
    input  wire [7:0]  drop_run_i,     // K (ROM H2)
    // the channel's state (state RAM, valid at go_i and through the slot)
    input  wire [2:0]  st_rl_i,
    input  wire [3:0]  st_need_i,
    input  wire [11:0] st_tried_i,
    input  wire [31:0] status_i,       // STATUS words
    input  wire        status_valid_i,
    // albatross_transfer_frag: the slot goes on with a value (at go_i), the
    // value's last word is taken, the value goes on (after the slot)
    input  wire        cont_i, lastf_i, mid_i,
    output wire        take_o,         // a word is taken (the word index + 1)
    output wire        cont_q_o,       // the slot goes on with a value (cont_i at go_i)
    output wire        wend_o,         // the stores of a word have ended
    output wire        safe_o,         // no Slot or Actual store begun for a destination still in the value
    output wire        need_any_o,     // a destination is in the value, not published
    // the access (albatross_transfer_access): one strobe per access kind
    output wire        dst_o, src_act_o, src_rl_o, src_word_o, dst_word_o, dst_tkn_o, dst_slot_o, dst_fin_o,
    output wire [1:0]  d_o,            // the current destination
    output wire [2:0]  ald_o,          // the source Actual last loaded
    output wire [2:0]  buf_d_o,        // d's picked buffer
    output wire [31:0] word_o,         // the word the destination stores write
    // results, valid with done_o (albatross_transfer's ports)
    output wire        done_o, imp_run_o, exp_run_o, new_o,
    output wire [2:0]  rl_o,
    output wire [3:0]  need_o, aband_o,
    output wire [11:0] tried_o,
    output wire [2:0]  transfers_o, corrupt_o,
    output wire        mode_req_o,
    output wire [3:0]  mode_req_mode_o,
    // requester port (cyc = stb; the address and data: albatross_transfer_access)
    output wire        cyc_o,
    input  wire [31:0] dat_i,
    input  wire        ack_i,
    input  wire        err_i
);

    // States: bit 3 = a destination access.
    localparam [3:0] S_IDLE     = 4'd0,
                     S_SRC_ACT  = 4'd1,   // load the source's Actual (four-slot: control word)
                     S_SRC_RL   = 4'd2,   // store the source's ReadLocked
                     S_SRC_SLOT = 4'd3,   // four-slot: load the control word again, pick L
                     S_SRC_WORD = 4'd4,   // load source word k
                     S_WAIT     = 4'd5,   // a word is wanted and not there (bus idle)
                     S_DST_CTRL = 4'd9,   // load d's control word (Actual, ReadLocked, Slots), pick
                     S_DST_WORD = 4'd10,  // store word k - 1 to d
                     S_DST_TKN  = 4'd11,  // store taken_at to d
                     S_DST_SLOT = 4'd12,  // four-slot: store d's Slot byte
                     S_DST_FIN  = 4'd13,  // store d's Actual
                     S_DST_PUB  = 4'd15;  // four-slot: store d's Actual only (its value complete from a Slot store before)

    (* fsm_encoding = "none" *)
    reg [3:0]  state_q;
    reg        stb_q, retry_q, drop_q, done_q;
    reg        early_q;               // the slot ended while a source load was on the bus
    reg [7:0]  run_q;
    reg [1:0]  d_q;
    reg [31:0] word_q;
    reg [2:0]  ald_q;                 // the source Actual last loaded
    reg [2:0]  rl_q;
    reg        new_q, icor_q, imp_q, exp_q;
    reg [3:0]  serve_q, need_q, pub_q, cor_q;
    reg        cont_q;                // the slot goes on with a value (no Import)
    reg [3:0]  att_q;                 // destinations with a Slot or Actual store begun in this slot
    wire [2:0] buf_d, tried_d;
    wire       dst      = state_q[3];
    wire       ack      = ack_i && stb_q;
    wire       drop_now = retry_q && drop_q;
    wire [3:0] d_bit    = 4'b0001 << d_q;     // the current destination
    wire       e_start, take_en;              // an Export starts; a word is taken (below)
    // need_now: the destinations of a value chosen now.
    wire [3:0] need_now = (new_q ? 4'hF : st_need_i) & active_i;

    // The control word just loaded and the picks (albatross_transfer_pick).
    wire [2:0] a_byte, pick_l, pick;
    wire       a_valid, a_zero, r_valid, r_zero, a_match, t_done;
    albatross_transfer_pick u_pick (
        .dat_i(dat_i), .four_i(four_i), .ald_i(ald_q), .rl_i(rl_q), .tried_i(tried_d),
        .a_byte_o(a_byte), .a_valid_o(a_valid), .a_zero_o(a_zero), .r_valid_o(r_valid), .r_zero_o(r_zero),
        .a_match_o(a_match), .pick_l_o(pick_l), .pick_o(pick), .t_done_o(t_done));
    wire       ctrl_ld  = state_q == S_DST_CTRL;
    wire       fin_st   = (state_q | 4'b0010) == S_DST_PUB;   // S_DST_FIN or S_DST_PUB: the Actual store
    wire       t_act    = a_valid && a_byte[2:0] == tried_d;
    // landed: Actual names the buffer tried (four-slot: and so does its Slot
    // byte); complete: four-slot, the Slot byte does and Actual does not.
    wire       landed   = ack && ctrl_ld && (four_i ? t_done && t_act : t_act && tried_d != 3'd0);
    wire       complete = ack && ctrl_ld && t_done && !t_act;
    wire       leave    = dst && (drop_now || landed || (ack && state_q == S_DST_PUB));
    // The destinations' order (albatross_transfer_order): next_d above d_q,
    // first_d in need_m (need_q without d if it leaves now), first_in in a
    // starting need.
    wire [3:0] start_need = go_i ? active_i : need_now;
    wire [3:0] need_m;
    wire       left_any, has_next;
    wire [1:0] next_d, first_d, first_in;
    albatross_transfer_order u_order (
        .need_q_i(need_q), .d_i(d_q), .leave_i(leave), .start_need_i(start_need[2:0]), .need_m_o(need_m),
        .left_any_o(left_any), .has_next_o(has_next), .next_d_o(next_d), .first_d_o(first_d), .first_in_o(first_in));

    // ------------------------------------------------------------ values over several runs
    wire [3:0] c_need   = st_need_i & active_i;
    wire       cont = cont_i, lastf = lastf_i, mid = mid_i;   // (albatross_transfer_frag)

    // ------------------------------------------------------------ steps
    wire       adv      = ack || drop_now;
    wire       ctrl_end = adv && (ctrl_ld ? !complete : state_q == S_DST_PUB);
    wire       want     = state_q != S_WAIT && !has_next && left_any &&
                          (ctrl_end || (adv && state_q == S_DST_WORD && !lastf));
    wire       word_ok  = !copy_i && (time_kind_i || status_valid_i);
    wire       choose   = ack && ((state_q == S_SRC_ACT && a_valid && a_match) || state_q == S_SRC_SLOT);
    wire       req_load = request_i && new_q;         // a New request value: load its word 0
    wire [7:0] k_run    = drop_run_i[7:1] == 7'd0 ? 8'd2 : drop_run_i;
    wire [7:0] run_inc  = run_q + 8'd1;
    // Cut off between the ReadLocked store and its confirming load: forget.
    wire       forget   = state_q == S_SRC_RL || ((state_q == S_SRC_SLOT || (state_q == S_SRC_ACT && new_q)) && !choose);

    // req: the main block below begins an access in this clock, branch by
    // branch (every begin_access call and the retry: keep it in step).
    wire       nrm      = !go_i && !(err_i && stb_q) && !(retry_q && !drop_q);
    wire       dst_go   = complete || has_next ||
                          (want ? (!copy_i && word_ok)
                                : ((state_q == S_DST_WORD && lastf) || state_q == S_DST_TKN || state_q == S_DST_SLOT));
    wire       req      = !rst_i && ((go_i && !copy_i) || (!go_i && !(err_i && stb_q) && retry_q && !drop_q) ||
                          (nrm && ((ack && ((state_q == S_SRC_ACT && a_valid && !a_match) || state_q == S_SRC_RL ||
                                            (state_q == S_SRC_WORD && !request_i))) ||
                                   (state_q == S_WAIT && word_ok) || (choose && (need_now != 4'd0 || req_load)) ||
                                   (adv && dst && left_any && dst_go))));

    // Put an access on the bus in the next clock; when may_access_i is low the
    // slot is cut off instead, in one place after the main block (req).
    task begin_access; input [3:0] s; input [1:0] d; begin d_q <= d; state_q <= s; stb_q <= 1'b1; end endtask
    task finish; begin state_q <= S_IDLE; stb_q <= 1'b0; done_q <= 1'b1; end endtask
    // Start the Export to start_need.
    task start_export;
        begin
            {exp_q, serve_q, need_q, run_q} <= {1'b1, start_need, start_need, 8'd0};
            begin_access(S_DST_CTRL, first_in);
        end
    endtask

    always @(posedge clk_i) begin
        done_q <= 1'b0;
        if (rst_i) begin
            state_q  <= S_IDLE;
            d_q      <= 2'd0;
            rl_q     <= 3'd0;
            run_q    <= 8'd0;
            {stb_q, retry_q, drop_q, imp_q, exp_q, new_q, icor_q, cont_q} <= 8'd0;
            att_q    <= 4'd0;
            {serve_q, need_q, pub_q, cor_q} <= 16'd0;
        end else if (go_i) begin
            imp_q    <= copy_i;
            rl_q     <= st_rl_i;
            cont_q   <= cont;
            {exp_q, new_q, icor_q, retry_q, drop_q, att_q, pub_q, cor_q} <= 17'd0;
            if (cont) begin
                // A run that goes on with a value: its first word from the held buffer.
                imp_q   <= 1'b0;
                exp_q   <= 1'b1;
                serve_q <= c_need;
                need_q  <= c_need;
                run_q   <= 8'd0;
                d_q     <= 2'd0;
                if (may_access_i) {state_q, stb_q} <= {S_SRC_WORD, 1'b1};
                else finish;
            end else if (copy_i) begin
                serve_q <= active_i;
                d_q     <= 2'd0;
                if (may_access_i) {state_q, stb_q} <= {S_SRC_ACT, 1'b1};
                else finish;
            end else start_export;
        end else if (err_i && stb_q) begin
            // A failed access: cyc low for a clock; count the run of a
            // destination access.
            stb_q   <= 1'b0;
            retry_q <= 1'b1;
            drop_q  <= dst && run_inc == k_run;
            if (dst) run_q <= run_inc;
        end else if (retry_q && !drop_q) begin
            retry_q <= 1'b0;
            stb_q   <= 1'b1;                       // (or the cut-off: req)
        end else begin
            retry_q <= 1'b0;
            drop_q  <= 1'b0;
            if (dst) need_q <= need_m;
            if (adv) run_q <= 8'd0;
            case (state_q)
                S_SRC_ACT: if (ack) begin
                    ald_q <= a_byte[2:0];
                    if (!a_valid) begin
                        icor_q <= !a_zero;
                        finish;
                    end else if (!a_match) begin
                        new_q <= 1'b1;
                        begin_access(S_SRC_RL, 2'd0);
                    end
                end
                S_SRC_RL: if (ack) begin
                    if (!four_i) rl_q <= ald_q;
                    begin_access(four_i ? S_SRC_SLOT : S_SRC_ACT, 2'd0);
                end
                S_SRC_SLOT: if (ack) rl_q <= pick_l;
                S_SRC_WORD: if (ack) begin
                    if (request_i) finish;                              // the mode request (mode_req_o)
                    else begin_access(S_DST_WORD, first_d);             // take word k_q
                end
                S_WAIT: if (word_ok) begin_access(S_DST_WORD, first_d);
                        else if (!may_access_i || copy_i) finish;       // the cut-off (COPY: only entered without may_access_i)
                S_DST_CTRL: if (ack && ((!r_valid && !r_zero) || (!a_valid && !a_zero))) cor_q <= cor_q | d_bit;
                default: ;
            endcase
            if (landed || (ack && fin_st)) pub_q <= pub_q | d_bit;
            // The value is chosen: New (taken_at now) or Old.
            if (choose) begin
                serve_q  <= need_now;
                if (req_load) begin_access(S_SRC_WORD, 2'd0);          // word 0 (k_q is 0 from go_i)
                else if (need_now == 4'd0) finish;
                else start_export;
            end
            // The next destination access (adv is 0 outside them).
            if (adv && dst) begin
                if (complete) begin
                    state_q <= S_DST_PUB;                  // d_q stays
                    stb_q   <= 1'b1;
                end
                else if (!left_any) finish;
                else if (has_next) begin_access(state_q == S_DST_PUB ? S_DST_CTRL : state_q, next_d);
                else if (want) begin
                    if (copy_i) begin
                        if (may_access_i) begin
                            state_q <= S_SRC_WORD;
                            stb_q   <= 1'b1;
                        end else begin
                            state_q <= S_WAIT;
                            stb_q   <= 1'b0;
                        end
                    end else if (word_ok) begin_access(S_DST_WORD, first_d);
                    else begin
                        state_q <= S_WAIT;
                        stb_q   <= 1'b0;
                    end
                end
                else if (state_q == S_DST_WORD && lastf) begin_access(S_DST_TKN, first_d);
                else if (state_q == S_DST_TKN) begin_access(four_i ? S_DST_SLOT : S_DST_FIN, first_d);
                else if (state_q == S_DST_SLOT) begin_access(S_DST_FIN, first_d);
                else if (state_q == S_DST_FIN) finish;
            end
        end
        if (req && !may_access_i) begin                  // the cut-off
            finish;
            if (forget) rl_q <= 3'd0;
        end
        // A source word load on the bus when the deadline check fails ends the
        // slot there (done_o); the load itself finishes (ack, or err) silently.
        if (early_q) done_q <= 1'b0;
        if (!rst_i && !go_i && state_q == S_SRC_WORD && !may_access_i && !early_q) begin
            done_q  <= 1'b1;
            early_q <= 1'b1;
        end
        if (rst_i || go_i) early_q <= 1'b0;
        if (!rst_i && !go_i && stb_q && (state_q == S_DST_SLOT || fin_st)) att_q <= att_q | d_bit;
    end

    // ------------------------------------------------------------ per-destination fields
    // albatross_transfer_dest, on the events of the current destination d_q.
    assign     e_start  = (go_i && (!copy_i || cont)) || (nrm && choose && need_now != 4'd0);
    // e_pick: d's control load picks its buffer (unless its Slot byte names
    // the buffer tried: then that buffer stays, landed or complete).  A
    // later fragment's buffers are the first fragment's picks (st_tried_i).
    wire       e_pick   = nrm && ack && ctrl_ld && !t_done;
    wire       e_fin    = nrm && ack && fin_st;
    wire       no_tried = go_i ? !copy_i : new_q;   // a fresh value (a later fragment's picks come in)
    albatross_transfer_dest u_dest (
        .clk_i(clk_i), .rst_i(rst_i), .start_i(e_start), .st_tried_i(st_tried_i), .fresh_i(no_tried), .d_i(d_q),
        .set_pick_i(e_pick), .clr_i(e_fin), .pick_i(pick), .tried_d_o(tried_d), .tried_o(tried_o));
    assign     buf_d    = tried_d;                     // d's buffer picked is its buffer tried

    // ------------------------------------------------------------ the word stored
    // word_q: the word the stores write, taken when the first store begins:
    // the source word (its load's ack clock) or a STATUS word (TIME's value
    // is slot_time_i itself).
    assign take_en = (nrm && ack && state_q == S_SRC_WORD) ||
                   (nrm && word_ok && (state_q == S_WAIT || (adv && dst && want)));
    always @(posedge clk_i) if (take_en) word_q <= copy_i ? dat_i : status_i;

    // ------------------------------------------------------------ the access
    assign {dst_o, src_act_o, src_rl_o, src_word_o} = {dst, state_q == S_SRC_ACT, state_q == S_SRC_RL, state_q == S_SRC_WORD};
    assign {dst_word_o, dst_tkn_o, dst_slot_o, dst_fin_o} = {state_q == S_DST_WORD, state_q == S_DST_TKN, state_q == S_DST_SLOT, fin_st};
    assign {d_o, ald_o, buf_d_o, word_o, cyc_o} = {d_q, ald_q, buf_d, word_q, stb_q};
    // (albatross_transfer_frag)
    // wend: the last destination's store of a word is answered or dropped
    // (no destination after it: the next word or the publication follows).
    wire       wend     = nrm && adv && state_q == S_DST_WORD && !has_next;
    wire [3:0] live     = need_q & ~pub_q;    // still in the value, not published
    assign {take_o, cont_q_o, wend_o} = {take_en, cont_q, wend};
    assign safe_o      = (att_q & live) == 4'd0;
    assign need_any_o  = live != 4'd0;

    // ------------------------------------------------------------ results
    function [2:0] popcount4; input [3:0] v; popcount4 = {2'd0, v[0]} + {2'd0, v[1]} + {2'd0, v[2]} + {2'd0, v[3]}; endfunction
    assign done_o      = done_q;
    assign imp_run_o   = imp_q;
    assign exp_run_o   = exp_q;
    assign new_o       = nrm && choose && new_q;
    assign rl_o        = rl_q;
    // A value that goes on (mid): the destinations still in it, not
    // published (the dropped ones out).  A value that ends: those served
    // and not published stay in need, and the next run Imports afresh,
    // its control loads seeing a landed or complete store.
    assign aband_o     = serve_q & ~pub_q & ~(need_q & {4{mid}});
    assign need_o      = (mid ? need_q : serve_q) & ~pub_q;
    assign transfers_o = exp_q ? popcount4(pub_q) : 3'd0;
    assign corrupt_o   = {2'd0, icor_q} + popcount4(cor_q);
    assign mode_req_o      = nrm && ack && state_q == S_SRC_WORD && request_i && !early_q;
    assign mode_req_mode_o = (|dat_i[31:4]) ? 4'hF : dat_i[3:0];

endmodule

`default_nettype wire
