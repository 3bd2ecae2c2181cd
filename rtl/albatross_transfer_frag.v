// albatross_transfer_frag -- the word index and the fragment's range of the
// transfer datapath (albatross_transfer): which word of the value a slot
// takes next, where the slot's words end, and the channel's progress after
// the slot (values in fragments, HAS_FRAGMENTS).
// Rules:
//   * k_o, the index of the next word to take: 0 from go_i and when an
//     Export starts (start_i), the progress st_prog_i from go_i of a later
//     fragment (cont_o), + 1 per word taken (take_i); reset: 0, the
//     progress the state RAM's clearing writes.
//   * A COPY with frag_i = F != 0 words per fragment carries words
//     [p, min(p + F, W)) of the value in a slot, p the channel's progress
//     (st_prog_i, a word offset; 0: the value's first fragment).  cont_o (at
//     go_i): the slot goes on with a value, p a word of it (0, or W after a
//     value's last fragment: none; only a fragmented value leaves a
//     progress: frag_i is not needed yet, it comes from the ROM after go_i)
//     and a destination of the entry still in it (need_any_i).  last_wd_o
//     (read where a word store ends, from 2 clocks after go_i): the slot's
//     words end, its F-th word taken (a count of the slot's words, so at
//     p + F) or word W - 1; lastf_o: at W, the value is whole.
//   * After the slot (with done): mid_o, the value goes on (a fragment not
//     the last done, fdone_i, or a later fragment, cont_q_i, cut before its
//     publication began, pubph_i, with a destination still in it,
//     need_any_q_i).  prog_o = k_o is written (prog_wr_o) only where it
//     changes: a fragment not the last done (its end), or a later
//     fragment's publication begun (W: none, the next run Imports afresh).
//     A fragment cut off keeps p (it runs again from the same word); a
//     first fragment cut off leaves p none.
//   * HAS_FRAGMENTS 0: cont_o, mid_o and prog_wr_o are 0, last_wd_o is
//     lastf_o (every value whole).
`default_nettype none

module albatross_transfer_frag #(
    parameter HAS_FRAGMENTS = 1   // 1: a COPY's value may go in fragments (frag_i); 0: frag_i is ignored
) (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        go_i,           // one clock: the slot's transfer starts
    input  wire        copy_i,         // kind COPY
    input  wire        request_i,      // a REQUEST COPY (never fragmented)
    input  wire [11:0] words_i,        // W
    input  wire [11:0] frag_i,         // words per fragment (E7.frag; 0: one fragment), valid from 2 clocks after go_i
    input  wire [11:0] st_prog_i,      // the channel's progress (state RAM, valid at go_i)
    input  wire        need_any_i,     // at go_i: a destination of the entry is still in the value
    input  wire        start_i,        // an Export starts: k := 0
    input  wire        take_i,         // a word is taken: k + 1
    input  wire        cont_q_i,       // the slot goes on with a value (cont_o registered at go_i)
    input  wire        fdone_i,        // a fragment not the last stored all its words
    input  wire        pubph_i,        // the publication (taken_at, Slot, Actual stores) has begun
    input  wire        need_any_q_i,   // a destination is still in the value now
    output wire        cont_o,         // at go_i: a fragment after the first
    output wire [11:0] k_o,            // the index of the next word to take
    output wire        last_wd_o,      // at a word store's end: the slot's words end
    output wire        lastf_o,        // with last_wd_o: the value's last word is taken
    output wire        mid_o,          // after the slot: the value goes on
    output wire [11:0] prog_o,         // the progress after the slot
    output wire        prog_wr_o       // prog_o changed (else the state keeps it)
);

    reg  [11:0] k_q;
    reg  [11:0] n_q;                  // the words taken in this slot

    wire        cont     = HAS_FRAGMENTS != 0 && copy_i && !request_i && st_prog_i != 12'd0 && st_prog_i < words_i &&
                           need_any_i;
    // A fragment ends when it has taken F words (n_q, from 1 after the first
    // take; F = 0: never, n_q <= W < 2^12), or at W.
    wire        fr_on    = HAS_FRAGMENTS != 0 && copy_i && !request_i;
    wire        lastf    = k_q == words_i;                          // (at last_wd: the value's last word is taken)
    wire        last_wd  = lastf || (fr_on && n_q == frag_i);

    // (reset: 0, the progress the state RAM's clearing writes)
    always @(posedge clk_i) if (rst_i) k_q <= 12'd0; else if (go_i && cont) k_q <= st_prog_i; else if (start_i || go_i) k_q <= 12'd0; else if (take_i) k_q <= k_q + 12'd1;
    always @(posedge clk_i) if (go_i) n_q <= 12'd0; else if (take_i) n_q <= n_q + 12'd1;

    assign cont_o    = cont;
    assign k_o       = k_q;
    assign last_wd_o = last_wd;
    assign lastf_o   = lastf;
    assign mid_o     = HAS_FRAGMENTS != 0 && (fdone_i || (cont_q_i && !pubph_i && need_any_q_i));
    assign prog_o    = k_q;                             // (after the last fragment: W, no word of the value)
    assign prog_wr_o = HAS_FRAGMENTS != 0 && (fdone_i || (cont_q_i && pubph_i));

endmodule

`default_nettype wire
