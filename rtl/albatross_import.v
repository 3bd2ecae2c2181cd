// albatross_import -- the Import engine: the consumer's side of the
// three-buffer protocol (the paper, section 3.1, figure 3) in hardware, on one Wishbone
// B4 classic master port.  It runs one Import of a channel at a time and
// hands the value out as a word stream; it keeps no per-channel state of its
// own beyond the transfer (the ReadLocked copy comes in with start_i and goes
// out on rl_known_o/rl_o), so a controller can run many channels through one
// engine and albatross_import_endpoint can keep one channel in registers.
// With four_i at start it runs the consumer of the four-slot kind instead
// (Simpson's four-slot mechanism on single-writer bytes;
// rtl/albatross_contract.toml [layout.four_slot]): wait-free, a fixed number
// of accesses whatever the producer does.
// Rules:
//   * Four-slot (four_i): the copy (rl_i/rl_o) is L, the buffer 1..4 read
//     last (0 unknown).  Load the control word (all four lanes): Actual A
//     and c = 1 + 2 pair(A) + Slot_pair(A) of that word.  If c is L: Old,
//     phase 2 reads buffer L (not "A is L": a producer between its Slot and
//     Actual stores leaves Actual one value behind the buffer the last Import
//     read, which would then be New twice).  Else store ReadLocked := A,
//     load the control word again and take b = 1 + 2p + Slot_p with p =
//     pair(A) = (A - 1) >> 1 and Slot_p bit 0 of byte 2 + p (never b = A: a
//     producer that loaded ReadLocked before the store may be rewriting A
//     itself); L := b, New, phase 2 reads buffer b.  An Actual outside 1..4
//     ends the Import with corrupt_o.  Undisturbed: exactly 1 (Old) or 3
//     (New) control accesses plus W loads, whatever the producer does; the
//     Old/New decision is made at the first load.  A cut-off after the
//     ReadLocked store and before the second load's ack forgets L (the next
//     Import takes the value as New).
//   * Access order.  Phase 1: load Actual.  If the ReadLocked copy is unknown
//     or differs from it, store ReadLocked := Actual and load Actual again,
//     until a load equals the copy: the result is New if ReadLocked was
//     stored in this Import, else Old.  An Actual that names no buffer ends
//     the Import with corrupt_o (nothing is read, the copy is kept).  Then
//     selected_o: the caller answers stream_i (read the value) or skip_i
//     (end without reading).  skip_i while a word waits to be taken (or, with
//     PULL, to be asked for) ends the Import there; so does may_access_i low.  Phase 2: load the W words of buffer ReadLocked
//     in address order, one load per word handed out on word_o.
//   * Accesses: one at a time; cyc = stb from request to ack; wb_we_o and
//     wb_sel_o are decoded from the state (meaningful only with cyc).  The
//     engine relies on Wishbone's answers: ack or err only in a clock with a
//     request, never both.  With no fault
//     and a consumer that takes every word in its ack clock (word_ready_i),
//     the next access is on the bus in the clock after the previous ack: no
//     idle bus clock inside an Import.  Undisturbed, an Import is 1 (Old) or
//     3 (New) control accesses, plus W loads when streamed; with albatross_dpram
//     each access is 2 clocks back to back.  Control accesses select their
//     byte lane only (sel), word loads all four.
//   * Word stream: word_valid_o is high in a word load's ack clock (word_o =
//     wb_dat_i) or, if word_ready_i was low then, from the next clock on with
//     the held word, until word_ready_i.  The next load begins in the clock
//     after the word is taken.  word_index_o is the word's index 0..W-1.
//   * PULL = 1 (the controller, where both engines share one bus): a word
//     load begins only in the clock after one where word_ready_i is high
//     while the engine waits for it (after stream_i, and after each word is
//     taken), so the consumer's own accesses never overlap the loads.
//   * Failures: an access answered with err counts in fails_o; cyc/stb drop
//     for one clock, and in that clock may_access_i decides: the same access
//     again in the next clock, or the cut-off.  may_access_i gates every access: an access begins in the clock
//     after an edge where it is 1; an access due at an edge where it is 0
//     ends the Import there with cut_o.  An Import cut off between its store
//     of ReadLocked and the confirming load of Actual forgets its copy
//     (rl_known_o = 0): the store may have landed, and the next Import must
//     take that buffer as a new value.
//   * Timing: start_i is taken when idle_o; the first access is on the bus in
//     the next clock.  done_o is high for one clock after the last ack (or
//     the cut-off or skip edge); new_o, corrupt_o, cut_o, fails_o and the
//     state outputs hold until the next start.  Reset clears control state
//     (the copy becomes unknown), never a data register.
`default_nettype none

module albatross_import #(
    parameter ADDR_WIDTH  = 10, // word-address bits of the port (wb_adr_o)
    parameter WORDS_WIDTH = 12, // bits of words_i: W from 1 to 2**WORDS_WIDTH - 1
    parameter COUNT_WIDTH = 8,  // bits of fails_o (saturating)
    parameter PULL        = 0   // 1: load the next word only when word_ready_i asks for it
) (
    input  wire                   clk_i,
    input  wire                   rst_i,        // synchronous, active high
    // command and the channel's state
    input  wire                   start_i,      // begin an Import (taken when idle_o)
    input  wire [ADDR_WIDTH-1:0]  base_i,       // channel base, word address
    input  wire [WORDS_WIDTH-1:0] words_i,      // W, the value's words (>= 1)
    input  wire                   four_i,       // the channel is of the four-slot kind (sampled at start)
    input  wire                   rl_known_i,   // the ReadLocked copy (four-slot: L) is known ...
    input  wire [2:0]             rl_i,         // ... and is this buffer (1..3; four-slot 1..4)
    input  wire                   may_access_i, // 1: an access may begin (deadline); tie 1 if none
    output wire                   idle_o,       // no Import under way: start_i is taken
    // end of phase 1
    output wire                   selected_o,   // new_o is valid; stream_i / skip_i decide
    input  wire                   stream_i,     // read the value now (sampled with selected_o)
    input  wire                   skip_i,       // end without reading (sampled with selected_o)
    // the value, one word per load
    output wire [31:0]            word_o,
    output wire                   word_valid_o,
    input  wire                   word_ready_i,
    output wire [WORDS_WIDTH-1:0] word_index_o, // 0..W-1
    // results
    output wire                   done_o,       // one clock: the Import is over
    output wire                   new_o,        // ReadLocked was stored: a value never read before
    output wire                   corrupt_o,    // Actual named no buffer
    output wire                   cut_o,        // ended by may_access_i
    output wire [COUNT_WIDTH-1:0] fails_o,      // accesses answered with err in this Import
    output wire                   rl_known_o,   // the copy after the Import (live)
    output wire [2:0]             rl_o,         // ... its buffer (0 while unknown)
    // Wishbone B4 classic master
    output wire                   wb_cyc_o,
    output wire                   wb_stb_o,
    output wire                   wb_we_o,
    output wire [ADDR_WIDTH-1:0]  wb_adr_o,     // word address
    output wire [3:0]             wb_sel_o,
    output wire [31:0]            wb_dat_o,
    input  wire [31:0]            wb_dat_i,
    input  wire                   wb_ack_i,
    input  wire                   wb_err_i
);

`include "albatross_contract.vh"

    // Channel layout: both control bytes in one word, buffers from BUF_WORD_I.
    localparam integer          CTRL_WORD_I = ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES;
    localparam integer          BUF_WORD_I  = ALB_CH_OFF_BUFFERS / ALB_CH_WORD_BYTES;
    localparam [ADDR_WIDTH-1:0] CTRL_WORD   = CTRL_WORD_I[ADDR_WIDTH-1:0];
    localparam                  ACT_BIT     = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam                  RL_BIT      = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_ACT     = 4'b0001 << (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_RL      = 4'b0001 << (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    // Four-slot: the slot bytes Slot0, Slot1 (rtl/albatross_contract.toml
    // [layout.four_slot]).
    localparam integer          OFF_SLOT0   = ALB_CH_OFF_SLOT0;
    localparam integer          OFF_SLOT1   = ALB_CH_OFF_SLOT1;
    localparam                  SLOT0_BIT   = 8 * (OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam                  SLOT1_BIT   = 8 * (OFF_SLOT1 % ALB_CH_WORD_BYTES);

    // The engine relies on: both control bytes (four-slot: all four) in one
    // word, the buffers from the next word on, three buffers numbered 1..3
    // (four-slot: 1..4, 3 bits).
    generate
        if (ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES != ALB_CH_OFF_READLOCKED / ALB_CH_WORD_BYTES ||
            BUF_WORD_I != CTRL_WORD_I + 1 ||
            ALB_CH_BUFFER1 != 1 || ALB_CH_BUFFER_LAST != 3 || ALB_CH_BUFFERS != 3 ||
            OFF_SLOT0 / ALB_CH_WORD_BYTES != CTRL_WORD_I || OFF_SLOT1 / ALB_CH_WORD_BYTES != CTRL_WORD_I ||
            ALB_CH_WORD_BYTES != 4 || ADDR_WIDTH < 2 || WORDS_WIDTH < 1 || COUNT_WIDTH < 1) begin : g_contract_check
            albatross_import_contract_mismatch u_error ();
        end
    endgenerate

    // States.
    localparam [2:0] S_IDLE        = 3'd0,  // waiting for start_i
                     S_LOAD_ACTUAL = 3'd1,  // load Actual (phase 1)
                     S_STORE_RL    = 3'd2,  // store ReadLocked := the Actual just loaded
                     S_SELECTED    = 3'd3,  // phase 1 over: waiting for stream_i or skip_i
                     S_LOAD_WORD   = 3'd4,  // load word k of buffer ReadLocked
                     S_HOLD_WORD   = 3'd5,  // word k loaded, not yet taken by the consumer
                     S_WAIT_PULL   = 3'd6,  // PULL: word k is next, waiting for word_ready_i
                     S_LOAD_SLOT   = 3'd7;  // four-slot: load the control word again, pick b

    reg [2:0]             state_q;
    reg [ADDR_WIDTH-1:0]  adr_q;
    reg [WORDS_WIDTH-1:0] words_q;
    reg [WORDS_WIDTH-1:0] k_q;          // word index in phase 2
    reg                   four_q;       // the four-slot kind
    reg [2:0]             act_q;        // the Actual last loaded: the next ReadLocked store
    reg [2:0]             rl_q;         // the ReadLocked copy (four-slot: L): a buffer, 0 unknown
    reg                   new_q;
    reg                   corrupt_q;
    reg                   cut_q;
    reg                   done_q;
    reg                   retry_q;      // the clock after a failed access: cyc low
    reg [COUNT_WIDTH-1:0] fails_q;
    reg [31:0]            word_q;       // a loaded word the consumer has not taken yet

    // The request follows the state: cyc = stb in an access state except in
    // the clock after a failed access; we in the ReadLocked store; sel the
    // ReadLocked lane there, all four lanes in phase 2 and S_LOAD_SLOT
    // (state_q[2]) and in a four-slot Actual load, else the Actual lane.
    wire       phase2     = state_q[2];
    wire       slot_ld    = state_q == S_LOAD_SLOT;
    wire       stb        = (state_q == S_LOAD_ACTUAL || state_q == S_STORE_RL || state_q == S_LOAD_WORD ||
                             slot_ld) && !retry_q;
    wire       we         = state_q == S_STORE_RL;
    wire [3:0] sel        = (phase2 || four_q) && !we ? 4'hF : we ? SEL_RL : SEL_ACT;

    wire [7:0] act_byte   = wb_dat_i[ACT_BIT +: 8];
    // Actual names a buffer: 1..3, four-slot 1..4.
    wire       act_valid  = act_byte[7:3] == 5'd0 && act_byte[2:0] != 3'd0 &&
                            (four_q ? act_byte[2:0] <= 3'd4 : !act_byte[2]);
    wire       rl_known   = rl_q != 3'd0;
    // Four-slot, the first load: c = buf(pair(A), Slot[pair(A)]) of this word,
    // the newest complete buffer of Actual's pair.
    wire       pair_n     = act_byte[2] | (act_byte[1] & act_byte[0]);
    wire [2:0] cur_b      = {1'b0, pair_n, pair_n ? wb_dat_i[SLOT1_BIT] : wb_dat_i[SLOT0_BIT]} + 3'd1;
    // Old: three-buffer, Actual is the copy; four-slot, c is L (with act_valid:
    // the copy is known and equal).
    wire       act_match  = four_q ? cur_b == rl_q : act_byte[2:0] == rl_q;
    // Four-slot, S_LOAD_SLOT: b = buf(pair(A), Slot[pair(A)]) = 1 + 2p + s.
    wire       pair_a     = act_q[2] | (act_q[1] & act_q[0]);   // (A - 1) >> 1 for A = 1..4
    wire       slot_a     = pair_a ? wb_dat_i[SLOT1_BIT] : wb_dat_i[SLOT0_BIT];
    wire [2:0] pick_b     = {1'b0, pair_a, slot_a} + 3'd1;
    wire [WORDS_WIDTH-1:0] k_inc = k_q + 1'b1;
    wire       last_word  = k_inc == words_q;     // k = W - 1, without a subtractor
    wire       end_phase1 = (state_q == S_LOAD_ACTUAL && wb_ack_i && act_valid && act_match) ||
                            (slot_ld && wb_ack_i);
    wire       word_ack   = state_q == S_LOAD_WORD && wb_ack_i;
    wire       hold       = state_q == S_HOLD_WORD;
    wire       taken      = (word_ack || hold) && word_ready_i;

    // Next address: adr + 1 + m, one adder.  In phase 1 and S_SELECTED adr_q
    // is the control word (base + CTRL_WORD), so the first word of buffer
    // ReadLocked, base + BUF_WORD_I + (rl - 1) * W, is adr + 1 + m with
    // m = (rl - 1) * W = 0, W, 2W or (four-slot) 3W (no multiplier, no base
    // register; the buffer is b itself in the ack clock of S_LOAD_SLOT); in
    // phase 2 m = 0: the next word.  W as an address offset (widened, then
    // cut to ADDR_WIDTH bits: a channel never reaches past the port's address
    // space).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [ADDR_WIDTH+WORDS_WIDTH-1:0] w_wide = {{ADDR_WIDTH{1'b0}}, words_q};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [ADDR_WIDTH-1:0] w_ext   = w_wide[ADDR_WIDTH-1:0];
    wire [1:0]            rd_buf  = slot_ld ? pick_b[1:0] : rl_q[1:0];
    wire [1:0]            rd_m1   = rd_buf - 2'd1;               // b - 1 (b = 1..4: 4 is 2'b00)
    wire                  m_w     = (!phase2 || slot_ld) && rd_m1[0];
    wire                  m_2w    = (!phase2 || slot_ld) && rd_m1[1];
    wire [ADDR_WIDTH-1:0] m       = ({ADDR_WIDTH{m_w}} & w_ext) + ({ADDR_WIDTH{m_2w}} & (w_ext << 1));
    wire [ADDR_WIDTH-1:0] adr_inc = adr_q + m + 1'b1;

    // The next step (no err in this clock): the state nst; due: an access
    // begins (or is repeated) from the next clock on, or a held word is past
    // the deadline check, so may_access_i low cuts the Import off here; fin:
    // the Import ends (done) if not cut off.
    reg [2:0] nst;
    reg       due, fin;
    always @* begin
        nst = state_q;
        due = 1'b0;
        fin = 1'b0;
        if (retry_q) due = 1'b1;                         // the failed access again
        else case (state_q)
            S_IDLE: if (start_i) begin
                nst = S_LOAD_ACTUAL;
                due = 1'b1;
            end
            S_LOAD_ACTUAL, S_LOAD_SLOT: if (wb_ack_i) begin
                if (!slot_ld && !act_valid) fin = 1'b1;    // names no buffer: read nothing
                else if (!slot_ld && !act_match) begin     // ReadLocked := Actual
                    nst = S_STORE_RL;
                    due = 1'b1;
                end else if (skip_i && !stream_i) fin = 1'b1;
                else if (stream_i) begin
                    nst = PULL != 0 ? S_WAIT_PULL : S_LOAD_WORD;
                    due = PULL == 0;
                end else nst = S_SELECTED;
            end
            S_STORE_RL: if (wb_ack_i) begin
                nst = four_q ? S_LOAD_SLOT : S_LOAD_ACTUAL;
                due = 1'b1;
            end
            S_SELECTED: if (stream_i) begin
                nst = PULL != 0 ? S_WAIT_PULL : S_LOAD_WORD;
                due = PULL == 0;
            end else if (skip_i) fin = 1'b1;
            S_LOAD_WORD, S_HOLD_WORD: if (word_ack || hold) begin
                if (!taken) begin                          // the consumer is not ready
                    nst = S_HOLD_WORD;
                    due = hold;                            // abandoned, or past the deadline
                    fin = hold && skip_i;
                end else if (last_word) fin = 1'b1;
                else begin
                    nst = PULL != 0 ? S_WAIT_PULL : S_LOAD_WORD;
                    due = PULL == 0;
                end
            end
            S_WAIT_PULL: begin
                due = 1'b1;
                if (skip_i) fin = 1'b1;
                else if (word_ready_i) nst = S_LOAD_WORD;
            end
            default: nst = S_IDLE;
        endcase
    end
    wire cut_now = due && !may_access_i;
    // Cut off with ReadLocked stored (or maybe stored) and not confirmed: forget the copy.
    wire forget  = state_q == S_STORE_RL || (state_q == S_LOAD_ACTUAL && new_q && !end_phase1) ||
                   (slot_ld && !end_phase1);

    always @(posedge clk_i) begin
        done_q <= 1'b0;
        if (rst_i) begin
            state_q    <= S_IDLE;
            rl_q       <= 3'd0;
            four_q     <= 1'b0;
            new_q      <= 1'b0;
            corrupt_q  <= 1'b0;
            cut_q      <= 1'b0;
            fails_q    <= {COUNT_WIDTH{1'b0}};
            retry_q    <= 1'b0;
        end else begin
            // A failed access: count it, drop cyc for a clock.  (Wishbone: no
            // ack with err, none without a request, so nothing below moves in
            // that clock or in the retry clock but the state's deadline check.)
            retry_q <= wb_err_i && stb;
            if (wb_err_i && stb && ~&fails_q) fails_q <= fails_q + 1'b1;
            if (state_q == S_IDLE && start_i) begin
                words_q    <= words_i;
                four_q     <= four_i;
                rl_q       <= rl_known_i ? rl_i : 3'd0;
                new_q      <= 1'b0;
                corrupt_q  <= 1'b0;
                cut_q      <= 1'b0;
                fails_q    <= {COUNT_WIDTH{1'b0}};
                adr_q      <= base_i + CTRL_WORD;
            end
            if (state_q == S_LOAD_ACTUAL && wb_ack_i) begin
                act_q <= act_byte[2:0];
                if (!act_valid) corrupt_q <= 1'b1;
                else if (!act_match) new_q <= 1'b1;
            end
            if (state_q == S_STORE_RL && wb_ack_i && !four_q) begin
                rl_q       <= act_q;
            end
            if (slot_ld && wb_ack_i) rl_q <= pick_b;       // four-slot: L := b
            if (selected_o && stream_i) begin          // phase 2 from word 0
                adr_q <= adr_inc;
                k_q   <= {WORDS_WIDTH{1'b0}};
            end
            if (word_ack) word_q <= wb_dat_i;
            if (taken && !last_word) begin             // the next word
                adr_q <= adr_inc;
                k_q   <= k_inc;
            end
            if (cut_now) begin
                state_q <= S_IDLE;
                cut_q   <= 1'b1;
                done_q  <= 1'b1;
                if (forget) rl_q <= 3'd0;
            end else if (fin) begin
                state_q <= S_IDLE;
                done_q  <= 1'b1;
            end else state_q <= nst;
        end
    end

    assign idle_o       = state_q == S_IDLE;
    assign selected_o   = end_phase1 || state_q == S_SELECTED;
    assign word_o       = hold ? word_q : wb_dat_i;
    assign word_valid_o = word_ack || hold;
    assign word_index_o = k_q;
    assign done_o       = done_q;
    assign new_o        = new_q;
    assign corrupt_o    = corrupt_q;
    assign cut_o        = cut_q;
    assign fails_o      = fails_q;
    assign rl_known_o   = rl_known;
    assign rl_o         = rl_q;
    assign wb_cyc_o     = stb;
    assign wb_stb_o     = stb;
    assign wb_we_o      = we;
    assign wb_adr_o     = adr_q;
    assign wb_sel_o     = sel;
    assign wb_dat_o     = {29'd0, act_q} << RL_BIT;

endmodule

`default_nettype wire
