// albatross_export -- the Export engine: the producer's side of the
// three-buffer protocol (the paper, section 3.1, figure 4) in hardware, on one Wishbone
// B4 classic master port, to DESTS destination channels in lockstep.  It
// takes the value as a word stream and never holds more than one word; it
// keeps no per-channel state beyond the transfer (each destination's copy of
// Actual comes in with start_i and goes out on act_known_o/act_o), so a
// controller can run many channels through one engine and
// albatross_export_endpoint can keep one channel in registers.  With four_i
// at start every destination is of the four-slot kind
// (rtl/albatross_contract.toml [layout.four_slot]).  This module holds the
// registers and the order of the steps; albatross_export_dest (its rules) the
// current destination's fields, the visiting order, the pick, the address.
// Rules:
//   * Four-slot (four_i), for the destinations d in need_i: 1. per d: load
//     the control word (all four lanes; the Actual copy is not used): R =
//     ReadLocked, p = 1 - pair(R) (R outside 1..4: 1 - pair(Actual), and
//     corrupt_o[d]; an Actual outside 1..4 also sets corrupt_o[d]), s = 1 -
//     bit 0 of Slot_p (byte 2 + p), the picked buffer 1 + 2p + s; an Actual
//     equal to tried_i[d] != 0 is the landed read-back below; 2., 3. as
//     below; 4. per d: store the byte Slot_p := s; 5. per d: store Actual :=
//     the picked buffer.  Undisturbed: ND * (W + TAKEN_AT + 3) accesses, one
//     byte store per destination more than the three-buffer kind with known
//     copies.  Buffers (1..4) at base + 1 + (b - 1) * S.  Failures, drop,
//     tried (3 bits, 1..4) and cut-off as below; a Slot store that landed
//     while its Actual store was never made (a drop or a cut-off) leaves a
//     complete value that a consumer may read: a caller must not give that
//     value to a later Export again (a consumer could take it as New twice).
//     albatross_export_endpoint never drops nor cuts off (every value is
//     new); the controller's datapath (albatross_transfer) stores only
//     Actual in such a case.
//   * Access order, for the destinations d set in need_i, in index order:
//     1. per d: if its Actual copy is unknown, load Actual (read back; one
//        that names no buffer sets corrupt_o[d] and excludes no buffer); then
//        load ReadLocked (one that names no buffer sets corrupt_o[d] and
//        locks nothing); pick the last buffer of 1..3 that is neither the
//        Actual copy nor that ReadLocked (figure 4's For loop);
//     2. per word k = 0..W-1: take word k from the stream, store it to word k
//        of each d's picked buffer;
//     3. TAKEN_AT = 1: store taken_at_i (sampled at start) after the value of
//        each d (word W of the buffer; the buffer stride is then W + 1);
//     4. per d: store Actual := its picked buffer: published_o[d].
//     A buffer is published only after its last word was stored (and acked),
//     and the buffer ReadLocked named at step 1 is never written.
//   * Accesses: one at a time; cyc = stb from request to ack.  With no fault
//     and a stream that offers every word when asked (word_valid_i), the
//     next access is on the bus in the clock after the previous ack: no idle
//     bus clock inside an Export.  Undisturbed, an Export to ND destinations
//     takes ND * (W + TAKEN_AT + 2) accesses, plus 1 per unknown Actual copy;
//     with albatross_dpram each is 2 clocks back to back.  Control accesses
//     select their byte lane only (sel), word stores all four.
//   * Word stream: word_ready_o is high in a clock where the engine takes
//     word word_index_o: the ack clock of the access before it (the last
//     ReadLocked load, or the last store of the previous word) or, if
//     word_valid_i was low then, every clock until it is high.  The word's
//     first store is on the bus in the next clock.
//   * Failures: an access answered with err counts in fails_o; cyc/stb drop
//     for one clock, and in that clock may_access_i decides: the same access
//     again in the next clock, or the cut-off.  DROP = 1: a destination one
//     of whose accesses fails K = drop_run_i times in a row (K below 2 reads
//     as 2; the compiler plans K from the fault hypothesis, ROM H2)
//     is dropped for the rest of the Export (in the clock after the K-th
//     failure the engine goes on as if the access had been acked, without its
//     effect), so a dead board never blocks the others; failures that are not
//     K in a row (an ack between them) never drop a destination.  A failed store
//     of Actual makes d's copy unknown and remembers the buffer it tried
//     (tried_o[2d +: 2], 0 = none); the next Export's read-back of Actual
//     (tried_i) then shows whether it landed: if so the value counts as
//     published at d (published_o[d]) and is not written again.
//     may_access_i gates every access: an access begins in the clock
//     after an edge where it is 1; an access due at an edge where it is 0
//     ends the Export there with cut_o.  A destination whose store of Actual
//     failed and was not repeated gets an unknown copy (act_known_o[d] = 0):
//     the store may have landed, and the next Export reads Actual back.
//   * Timing: start_i is taken when idle_o; the first access is on the bus in
//     the next clock.  done_o is high for one clock after the last ack (or
//     the cut-off edge); published_o, corrupt_o, cut_o, fails_o and the
//     state outputs hold until the next start.  Reset clears control state
//     (every copy becomes unknown), never a data register.
`default_nettype none

module albatross_export #(
    parameter ADDR_WIDTH  = 10, // word-address bits of the port (wb_adr_o)
    parameter WORDS_WIDTH = 12, // bits of words_i: W from 1 to 2**WORDS_WIDTH - 1
    parameter COUNT_WIDTH = 8,  // bits of fails_o (saturating)
    parameter TAKEN_AT    = 0,  // 1: store taken_at_i after the value (stride W + 1)
    parameter DESTS       = 1,  // destination channels in lockstep, 1..4
    parameter DROP        = 0   // 1: drop a destination after drop_run_i failed attempts of one access in a row
) (
    input  wire                    clk_i,
    input  wire                    rst_i,        // synchronous, active high
    // command and the destinations' state
    input  wire                    start_i,      // begin an Export (taken when idle_o)
    input  wire [7:0]              drop_run_i,   // K (DROP = 1; below 2: 2), held while an Export runs
    input  wire                    four_i,       // the destinations are of the four-slot kind (sampled at start)
    input  wire [DESTS*ADDR_WIDTH-1:0] base_i,   // destination d's base at [d*ADDR_WIDTH +: ADDR_WIDTH]
    input  wire [DESTS-1:0]        need_i,       // destinations that take this value
    input  wire [WORDS_WIDTH-1:0]  words_i,      // W, the value's words (>= 1)
    input  wire [31:0]             taken_at_i,   // TAKEN_AT = 1: the word stored after the value
    input  wire [DESTS-1:0]        act_known_i,  // destination d's Actual copy is known ...
    input  wire [2*DESTS-1:0]      act_i,        // ... and is this buffer (1..3), at [2d +: 2]
    input  wire [3*DESTS-1:0]      tried_i,      // buffer of d's failed Actual store (0: none), at [3d +: 3]
    input  wire                    may_access_i, // 1: an access may begin (deadline); tie 1 if none
    output wire                    idle_o,       // no Export under way: start_i is taken
    // the value, one word per take
    input  wire [31:0]             word_i,
    input  wire                    word_valid_i,
    output wire                    word_ready_o,
    output wire [WORDS_WIDTH-1:0]  word_index_o, // index of the word taken next, 0..W-1
    // results
    output wire                    done_o,       // one clock: the Export is over
    output wire [DESTS-1:0]        published_o,  // Actual stored: the value is published at d
    output wire [DESTS-1:0]        corrupt_o,    // d's Actual or ReadLocked named no buffer
    output wire                    cut_o,        // ended by may_access_i
    output wire [COUNT_WIDTH-1:0]  fails_o,      // accesses answered with err in this Export
    output wire [DESTS-1:0]        act_known_o,  // the copies after the Export (live)
    output wire [2*DESTS-1:0]      act_o,
    output wire [3*DESTS-1:0]      tried_o,
    output wire [1:0]              dest_o,       // destination of the current access
    // Wishbone B4 classic master
    output wire                    wb_cyc_o,
    output wire                    wb_stb_o,
    output wire                    wb_we_o,
    output wire [ADDR_WIDTH-1:0]   wb_adr_o,     // word address
    output wire [3:0]              wb_sel_o,
    output wire [31:0]             wb_dat_o,
    input  wire [31:0]             wb_dat_i,     // only the control bytes are read
    input  wire                    wb_ack_i,
    input  wire                    wb_err_i
);

`include "albatross_contract.vh"

    // Channel layout: the control bytes and slot bytes in one word
    // (albatross_export_dest has the buffers' addresses).
    localparam integer          CTRL_WORD_I = ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES;
    localparam                  ACT_BIT     = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_ACT     = 4'b0001 << (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_RL      = 4'b0001 << (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    // Four-slot: the slot bytes Slot0, Slot1 (rtl/albatross_contract.toml
    // [layout.four_slot]).
    localparam integer          OFF_SLOT0   = ALB_CH_OFF_SLOT0;
    localparam integer          OFF_SLOT1   = ALB_CH_OFF_SLOT1;
    localparam                  SLOT0_BIT   = 8 * (OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam                  SLOT1_BIT   = 8 * (OFF_SLOT1 % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_SLOT0   = 4'b0001 << (OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam [3:0]            SEL_SLOT1   = 4'b0001 << (OFF_SLOT1 % ALB_CH_WORD_BYTES);

    // The engine relies on: both control bytes in one word, three buffers
    // numbered 1..3 (2 bits), one taken_at word.
    generate
        if (ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES != ALB_CH_OFF_READLOCKED / ALB_CH_WORD_BYTES ||
            ALB_CH_BUFFER1 != 1 || ALB_CH_BUFFER_LAST != 3 || ALB_CH_BUFFERS != 3 ||
            OFF_SLOT0 / ALB_CH_WORD_BYTES != CTRL_WORD_I || OFF_SLOT1 / ALB_CH_WORD_BYTES != CTRL_WORD_I ||
            ALB_CH_WORD_BYTES != 4 || ALB_CH_TAKEN_AT_WORDS != 1 || ADDR_WIDTH < 2 ||
            WORDS_WIDTH < 1 || COUNT_WIDTH < 1 || DESTS < 1 || DESTS > 4 ||
            (TAKEN_AT != 0 && TAKEN_AT != 1)) begin : g_contract_check
            albatross_export_contract_mismatch u_error ();
        end
    endgenerate

    // States.
    localparam [2:0] S_IDLE         = 3'd0,  // waiting for start_i
                     S_LOAD_ACTUAL  = 3'd1,  // read back destination d's Actual (copy unknown)
                     S_LOAD_RL      = 3'd2,  // load destination d's ReadLocked, pick its buffer
                     S_WAIT_WORD    = 3'd3,  // waiting for word word_index_o of the stream
                     S_STORE_WORD   = 3'd4,  // store word take_k_q - 1 to destination d
                     S_STORE_TAKEN  = 3'd5,  // store taken_at to destination d
                     S_STORE_ACTUAL = 3'd6,  // store destination d's Actual := its buffer
                     S_STORE_SLOT   = 3'd7;  // four-slot: store destination d's Slot_p := s

    (* fsm_encoding = "none" *)         // binary as written: 5 LUT4 fewer than yosys's one-hot recode
    reg [2:0]                  state_q;
    reg                        stb_q;          // cyc = stb: an access is on the bus
    reg                        four_q;         // four-slot destinations
    reg [1:0]                  d_q;            // current destination
    reg [DESTS*ADDR_WIDTH-1:0] base_q;
    reg [DESTS-1:0]            need_q;
    reg [WORDS_WIDTH-1:0]      words_q;
    reg [WORDS_WIDTH-1:0]      take_k_q;       // index of the next word to take (S_STORE_WORD: 1 + the word stored)
    reg [31:0]                 word_q;         // the word being stored
    reg [31:0]                 taken_q;
    reg [DESTS-1:0]            act_known_q;
    reg [2*DESTS-1:0]          act_q;
    reg [3*DESTS-1:0]          buf_q;          // d's picked buffer
    reg [DESTS-1:0]            published_q;
    reg [DESTS-1:0]            corrupt_q;
    reg                        cut_q;
    reg                        done_q;
    reg [COUNT_WIDTH-1:0]      fails_q;
    reg [3*DESTS-1:0]          tried_q;
    reg [7:0]                  run_q;          // failed attempts of the present access in a row
    reg                        retry_q;        // the clock after a failed access: cyc low
    reg                        drop_q;         // ... and its destination is dropped

    // The per-destination datapath (rtl/albatross_export_dest.v).
    wire                  leave;                // d_q leaves the Export now: dropped or found published
    wire                  landed;               // ... found published by the read-back
    wire [DESTS-1:0]      d_bit;                // d_q as a mask
    wire [3*DESTS-1:0]    d_mask3;              // d_q's 3-bit fields as a mask
    wire [2:0]            buf_d;                // d_q's picked buffer
    wire [ADDR_WIDTH-1:0] adr;                  // word address of the current access
    wire [DESTS-1:0]      need_m;               // need_q without d_q if it leaves now
    wire                  has_next, known_next; // a destination after d_q takes part: next_d, its copy known
    wire [1:0]            next_d, first_d;      // first_d: the first destination that takes part
    wire                  any_in, known_in;     // at start: need_i names a destination: first_in, its copy known
    wire [1:0]            first_in;
    wire                  act_valid, rl_valid;  // the loaded Actual / ReadLocked names a buffer
    wire [1:0]            act_buf;              // the loaded Actual's buffer
    wire [2:0]            pick;                 // the buffer picked for d_q
    wire                  ack       = wb_ack_i && stb_q;
    wire                  drop_now  = retry_q && drop_q;
    // The drop rule: this failure is the K-th of the access in a row.
    wire [8:0]            run_inc   = {1'b0, run_q} + 9'd1;
    wire [8:0]            drop_k    = drop_run_i < 8'd2 ? 9'd2 : {1'b0, drop_run_i};
    wire                  ctrl      = state_q == S_LOAD_ACTUAL || state_q == S_LOAD_RL || state_q == S_STORE_ACTUAL ||
                                      state_q == S_STORE_SLOT;
    albatross_export_dest #(.ADDR_WIDTH(ADDR_WIDTH), .WORDS_WIDTH(WORDS_WIDTH), .TAKEN_AT(TAKEN_AT),
                            .DESTS(DESTS)) u_dest (
        .d_i(d_q), .need_i(need_q), .base_i(base_q), .buf_i(buf_q), .known_i(act_known_q), .act_i(act_q),
        .tried_i(tried_q), .four_i(four_q), .words_i(words_q), .k_i(take_k_q), .drop_i(drop_now),
        .read_act_i(ack && (state_q == S_LOAD_ACTUAL || (four_q && state_q == S_LOAD_RL))),
        .ctrl_i(ctrl), .taken_i(state_q == S_STORE_TAKEN), .dat_i(wb_dat_i),
        .start_need_i(need_i), .start_known_i(act_known_i),
        .d_bit_o(d_bit), .d_mask3_o(d_mask3), .buf_o(buf_d), .adr_o(adr), .landed_o(landed), .leave_o(leave),
        .need_o(need_m), .has_next_o(has_next), .next_o(next_d), .known_next_o(known_next), .first_o(first_d),
        .any_in_o(any_in), .first_in_o(first_in), .known_in_o(known_in),
        .act_valid_o(act_valid), .act_buf_o(act_buf), .rl_valid_o(rl_valid), .pick_o(pick));

    // Four-slot, S_STORE_SLOT: d's p and s from its buffer (b - 1 = {p, s}).
    wire [1:0] buf_m1    = buf_d[1:0] - 2'd1;
    // In S_STORE_WORD the last word is being stored when every word was taken.
    wire       last_word = take_k_q == words_q;
    wire       ctrl_ld   = state_q == S_LOAD_ACTUAL || state_q == S_LOAD_RL;
    wire       adv       = ack || drop_now;             // go on to the next access
    wire       ctrl_end  = adv && (state_q == S_LOAD_RL || (state_q == S_LOAD_ACTUAL && leave));
    // After the value (and taken_at): the slot bytes (four-slot), then Actual.
    wire [2:0] after_data = four_q ? S_STORE_SLOT : S_STORE_ACTUAL;
    // The clock where the engine takes a word from the stream.
    wire       want_word = state_q == S_WAIT_WORD ||
                           (!has_next && need_m != {DESTS{1'b0}} &&
                            (ctrl_end || (adv && state_q == S_STORE_WORD && !last_word)));

    // Put the next access (state s, destination d) on the bus, or end the
    // Export here if no access may begin.
    task begin_access;
        input [2:0] s;
        input [1:0] d;
        begin
            d_q <= d;
            if (may_access_i) begin
                state_q <= s;
                stb_q   <= 1'b1;
            end else begin
                state_q <= S_IDLE;
                stb_q   <= 1'b0;
                cut_q   <= 1'b1;
                done_q  <= 1'b1;
            end
        end
    endtask

    always @(posedge clk_i) begin
        done_q <= 1'b0;
        if (rst_i) begin
            state_q     <= S_IDLE;
            stb_q       <= 1'b0;
            four_q      <= 1'b0;
            d_q         <= 2'd0;
            need_q      <= {DESTS{1'b0}};
            act_known_q <= {DESTS{1'b0}};
            published_q <= {DESTS{1'b0}};
            corrupt_q   <= {DESTS{1'b0}};
            cut_q       <= 1'b0;
            fails_q     <= {COUNT_WIDTH{1'b0}};
            tried_q     <= {3*DESTS{1'b0}};
            retry_q     <= 1'b0;
            drop_q      <= 1'b0;
            run_q       <= 8'd0;
        end else if (wb_err_i && stb_q) begin
            // A failed access: count it, drop cyc for a clock.  The store of
            // Actual may have landed: the copy is unknown, the buffer tried.
            if (~&fails_q) fails_q <= fails_q + 1'b1;
            stb_q   <= 1'b0;
            retry_q <= 1'b1;
            drop_q  <= DROP != 0 && run_inc >= drop_k;
            if (!run_inc[8]) run_q <= run_inc[7:0];
            if (state_q == S_STORE_ACTUAL) begin
                act_known_q <= act_known_q & ~d_bit;
                tried_q <= (tried_q & ~d_mask3) | ({DESTS{buf_d}} & d_mask3);
            end
        end else if (retry_q && !drop_q) begin
            // The same access again if one may begin, else the cut-off.
            retry_q <= 1'b0;
            if (may_access_i) stb_q <= 1'b1;
            else begin
                state_q <= S_IDLE;
                cut_q   <= 1'b1;
                done_q  <= 1'b1;
            end
        end else begin
            retry_q <= 1'b0;
            need_q  <= need_m;
            case (state_q)
                S_IDLE: if (start_i) begin
                    base_q      <= base_i;
                    four_q      <= four_i;
                    need_q      <= need_i;
                    words_q     <= words_i;
                    taken_q     <= taken_at_i;
                    act_known_q <= act_known_i;
                    act_q       <= act_i;
                    tried_q     <= tried_i;
                    run_q       <= 8'd0;
                    drop_q      <= 1'b0;
                    published_q <= {DESTS{1'b0}};
                    corrupt_q   <= {DESTS{1'b0}};
                    cut_q       <= 1'b0;
                    fails_q     <= {COUNT_WIDTH{1'b0}};
                    take_k_q    <= {WORDS_WIDTH{1'b0}};
                    if (!any_in) done_q <= 1'b1;          // no destination: nothing to do
                    else begin_access(known_in || four_i ? S_LOAD_RL : S_LOAD_ACTUAL, first_in);
                end
                S_LOAD_ACTUAL: if (adv) begin
                    if (ack) tried_q <= tried_q & ~d_mask3;          // read back
                    if (ack && act_valid) begin
                        act_q[2*d_q +: 2]  <= act_buf;
                        act_known_q <= act_known_q | d_bit;
                    end else if (ack) begin
                        corrupt_q   <= corrupt_q | d_bit;
                    end
                    if (landed) published_q <= published_q | d_bit;  // the failed store had landed
                end
                S_LOAD_RL: if (adv) begin
                    buf_q <= (buf_q & ~d_mask3) | ({DESTS{pick}} & d_mask3);
                    if (ack && (!rl_valid || (four_q && !act_valid))) corrupt_q <= corrupt_q | d_bit;
                    if (ack && four_q) tried_q <= tried_q & ~d_mask3; // read back
                    if (landed) published_q <= published_q | d_bit;  // the failed store had landed
                end
                S_STORE_ACTUAL: if (adv) begin
                    if (ack) begin
                        act_q[2*d_q +: 2]   <= buf_d[1:0];  // (four-slot: not used)
                        act_known_q         <= act_known_q | d_bit;
                        published_q         <= published_q | d_bit;
                        tried_q             <= tried_q & ~d_mask3;
                    end
                end
                default: ;
            endcase
            // The next access after this one (adv is 0 in S_IDLE and S_WAIT_WORD):
            // Actual read back, then ReadLocked, of d; else the same step for the
            // next destination (a load: LR if its copy is known, else LA); else
            // the next step (after the last word, taken_at, then Actual), or end.
            if (adv) begin
                run_q <= 8'd0;                              // the next access: a new run
                if (need_m == {DESTS{1'b0}}) begin          // the last destination left
                    stb_q   <= 1'b0;
                    state_q <= S_IDLE;
                    done_q  <= 1'b1;
                end else if (state_q == S_LOAD_ACTUAL && !leave) begin_access(S_LOAD_RL, d_q);
                else if (has_next) begin_access(ctrl_ld ? (known_next || four_q ? S_LOAD_RL : S_LOAD_ACTUAL) : state_q, next_d);
                else if (state_q == S_STORE_WORD) begin
                    if (last_word) begin_access(TAKEN_AT ? S_STORE_TAKEN : after_data, first_d);
                end else if (state_q == S_STORE_TAKEN) begin_access(after_data, first_d);
                else if (state_q == S_STORE_SLOT) begin_access(S_STORE_ACTUAL, first_d);
                else if (state_q == S_STORE_ACTUAL) begin
                    stb_q   <= 1'b0;
                    state_q <= S_IDLE;
                    done_q  <= 1'b1;
                end
            end
            // The word stream (exclusive with the next-access decision above).
            if (want_word && word_valid_i) begin          // take a word: store it to the first d
                word_q    <= word_i;
                take_k_q  <= take_k_q + 1'b1;
                begin_access(S_STORE_WORD, first_d);
            end else if (want_word && state_q == S_WAIT_WORD && !may_access_i) begin
                state_q <= S_IDLE;                        // no store could follow: cut off
                cut_q   <= 1'b1;
                done_q  <= 1'b1;
            end else if (want_word) begin                 // wait for it, bus idle
                state_q <= S_WAIT_WORD;
                stb_q   <= 1'b0;
            end
        end
    end

    assign idle_o       = state_q == S_IDLE;
    assign word_ready_o = want_word;
    assign word_index_o = take_k_q;
    assign done_o       = done_q;
    assign published_o  = published_q;
    assign corrupt_o    = corrupt_q;
    assign cut_o        = cut_q;
    assign fails_o      = fails_q;
    assign act_known_o  = act_known_q;
    assign act_o        = act_q;
    assign tried_o      = tried_q;
    assign dest_o       = d_q;
    assign wb_cyc_o     = stb_q;
    assign wb_stb_o     = stb_q;
    assign wb_we_o      = state_q == S_STORE_WORD || state_q == S_STORE_TAKEN || state_q == S_STORE_ACTUAL ||
                          state_q == S_STORE_SLOT;
    assign wb_adr_o     = adr;
    assign wb_sel_o     = state_q == S_LOAD_ACTUAL || state_q == S_STORE_ACTUAL ? SEL_ACT :
                          state_q == S_LOAD_RL ? (four_q ? 4'hF : SEL_RL) :
                          state_q == S_STORE_SLOT ? (buf_m1[1] ? SEL_SLOT1 : SEL_SLOT0) : 4'hF;
    assign wb_dat_o     = state_q == S_STORE_WORD  ? word_q :
                          state_q == S_STORE_TAKEN ? taken_q :
                          state_q == S_STORE_SLOT  ? ({31'd0, buf_m1[0]} << (buf_m1[1] ? SLOT1_BIT : SLOT0_BIT)) :
                          ({29'd0, buf_d} << ACT_BIT);

endmodule

`default_nettype wire
