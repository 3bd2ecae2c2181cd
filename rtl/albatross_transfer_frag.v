// albatross_transfer_frag -- the word index and the progress of the
// transfer datapath (albatross_transfer): which word of the value a slot
// takes next, and whether and where the value goes on after the slot
// (values carried over several runs, HAS_FRAGMENTS).
// Rules:
//   * k_o, the index of the next word to take: 0 from go_i (an Import
//     takes no word, so a first run's Export starts at word 0), the
//     progress st_prog_i from go_i of a run that goes on with a value
//     (cont_o), + 1 per word taken (take_i);
//     lastf_o: k_o = W (read where a word's stores end: the value's last
//     word is stored).  Reset: 0.
//   * A COPY whose entry has frag_on_i (E7.frag != 0) may carry its value
//     over several runs: a run stores words from its first until the
//     value's last or until its slot is cut off by the deadline.  The
//     channel's state keeps whether a value goes on (st_on_i) and its
//     progress p (st_prog_i): the first word not yet stored to every
//     destination still in the value.  cont_o (at go_i): st_on_i, a COPY
//     that is not a REQUEST, and a destination of the entry still in the
//     value (need_any_i).
//   * wend_i: the stores of the word k_o - 1 have ended (every destination
//     still in the value has it).  Unless it is the value's last word
//     (lastf_o), the progress so far is k_o: kept, with a mark that a word
//     ended in this slot (go_i clears the mark).  The last word is not
//     counted: a value cut off in its publication goes on from word W - 1,
//     whose load and stores lead to the publication again.
//   * After the slot (with done): mid_o, the value goes on: a destination
//     is still in it and not published (need_any_q_i), none of those has
//     had a Slot or Actual store begun in the slot (safe_i: a begun one may
//     have landed, which only the control load of a fresh Import can
//     tell), and the slot either went on with it (cont_q_i: cut before its
//     end, with or without a word stored) or began it on an entry with
//     frag_on_i and stored a word other than the last to all (a first run
//     cut before that leaves no value going on: the next run Imports
//     afresh).  on_wr_o: the flag is written (value mid_o) where it may
//     change: mid_o, or a run that went on with a value (which ends unless
//     mid_o).  prog_wr_o: the progress is written (prog_o, the last kept)
//     where a value goes on and a word was counted in this slot; else the
//     state keeps it (a run cut before resumes at the same word).
//   * frag_on_i comes from the ROM two clocks after go_i; it is read only
//     with the mark (a word ended: later).
//   * HAS_FRAGMENTS 0: cont_o, mid_o, on_wr_o and prog_wr_o are 0 (every
//     value whole: one run).
`default_nettype none

module albatross_transfer_frag #(
    parameter HAS_FRAGMENTS = 1   // 1: a COPY's value may go over several runs (frag_on_i); 0: frag_on_i is ignored
) (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        go_i,           // one clock: the slot's transfer starts
    input  wire        copy_i,         // kind COPY
    input  wire        request_i,      // a REQUEST COPY (never over several runs)
    input  wire [11:0] words_i,        // W
    input  wire        frag_on_i,      // E7.frag != 0, valid from 2 clocks after go_i
    input  wire        st_on_i,        // the channel's state: a value goes on (valid at go_i)
    input  wire [11:0] st_prog_i,      // ... its progress: the first word not stored to all
    input  wire        need_any_i,     // at go_i: a destination of the entry is still in the value
    input  wire        take_i,         // a word is taken: k + 1
    input  wire        wend_i,         // the stores of word k - 1 have ended
    input  wire        cont_q_i,       // the slot goes on with a value (cont_o registered at go_i)
    input  wire        safe_i,         // no Slot or Actual store begun for a destination still in the value
    input  wire        need_any_q_i,   // a destination is still in the value now, not published
    output wire        cont_o,         // at go_i: the slot goes on with a value
    output wire [11:0] k_o,            // the index of the next word to take
    output wire        lastf_o,        // k_o = W: with wend, the value's last word is stored
    output wire        mid_o,          // after the slot: the value goes on (the flag's value)
    output wire        on_wr_o,        // the flag is written
    output wire [11:0] prog_o,         // the progress after the slot
    output wire        prog_wr_o       // prog_o is written (else the state keeps it)
);

    localparam FR = HAS_FRAGMENTS != 0;

    reg  [11:0] k_q;
    reg  [11:0] kdone_q;              // k at the last wend: the words stored to all
    reg         wdone_q;              // a word's stores ended in this slot

    wire        cont  = FR && copy_i && !request_i && st_on_i && need_any_i;
    wire        lastf = k_q == words_i;
    wire        mid   = FR && safe_i && need_any_q_i && (cont_q_i || (copy_i && !request_i && frag_on_i && wdone_q));

    always @(posedge clk_i) if (rst_i) k_q <= 12'd0; else if (go_i && cont) k_q <= st_prog_i; else if (go_i) k_q <= 12'd0; else if (take_i) k_q <= k_q + 12'd1;
    // (reset: 0, the progress the state RAM's clearing writes)
    always @(posedge clk_i) if (rst_i) kdone_q <= 12'd0; else if (wend_i && !lastf) kdone_q <= k_q;
    always @(posedge clk_i) if (rst_i || go_i) wdone_q <= 1'b0; else if (wend_i && !lastf) wdone_q <= 1'b1;

    assign cont_o    = cont;
    assign k_o       = k_q;
    assign lastf_o   = lastf;
    assign mid_o     = mid;
    assign on_wr_o   = FR && (mid || cont_q_i);
    assign prog_o    = kdone_q;
    assign prog_wr_o = mid && wdone_q;

endmodule

`default_nettype wire
