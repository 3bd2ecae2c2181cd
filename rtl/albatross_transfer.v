// albatross_transfer -- the controller's one transfer datapath: a single
// state machine that runs, on one Wishbone B4 classic requester port, the
// consumer's Import of the source (the paper's figure 3; four-slot kind: Simpson's
// mechanism on single-writer bytes) and the producer's Export (figure 4) to
// up to 4 destinations, streaming the value word by word (one source load,
// then one store per destination).  It replaces separate Import and Export
// engines: one state register, one address adder, one write-data OR.  This
// module composes its parts and states the datapath's contract at its ports.
// Rules:
//   * Fields come from the sequencer's entry registers (held for the slot):
//     kind, four, W, places.  Per-channel state comes in from the state RAM
//     (st_*_i) at go_i and goes out on the *_o write-back ports, valid in
//     the done_o clock.  No per-channel state is kept here between slots.
//   * The Import (COPY), a REQUEST's mode request, the Export, failures,
//     the drop run, the cut-off and the timing: albatross_transfer_fsm
//     states them (one state machine).
//   * Values over several runs ("fragments"; HAS_FRAGMENTS; a COPY whose
//     entry has frag_on_i, E7.frag != 0; albatross_transfer_frag has the
//     word index and the progress): a run stores the value's words from
//     its first until the value's last or until the deadline cuts the slot
//     off; the channel's state says whether a value goes on (st_on_i) and
//     its progress p (st_prog_i), the first word not yet stored to every
//     destination still in it.  A first run: the Import and the
//     destinations' control loads and picks as above, then words from 0.
//     A run that goes on (cont): no Import and no control load: words from
//     p; the source buffer is the held one (st_rl_i, whose ReadLocked the
//     first run stored and nothing changes until the value ends), the
//     destinations are those still in the value (st_need_i) and their
//     buffers are the picked ones (st_tried_i: a destination's buffer
//     picked is its buffer tried, tried_o).  A run cut off before the
//     publication began, with a destination still in the value (and, for a
//     first run, a word stored to all): the value goes on (on_o, on_wr_o;
//     prog_o, prog_wr_o where a word's stores ended in the slot), need_o =
//     the destinations still in it (a dropped one stays out of it), no
//     Slot or Actual store (nothing published).  After the last word:
//     taken_at, (Slot,) Actual as above.  A run cut off in the
//     publication: the destinations published leave the value; if none of
//     the others had a Slot or Actual store begun, the value goes on for
//     them from word W - 1 (its load, stores and the publication again);
//     else it ends (those not published stay in need: the next run Imports
//     afresh and its control loads see a landed or complete store; an Old
//     value is sent again from word 0).  A value with no destination left
//     ends.  aband_o: the destinations abandoned in this slot (not
//     published; when the value goes on, those dropped in it: the others
//     are still in the value, not in need).
// Parts: albatross_transfer_fsm (the state machine; it holds
// albatross_transfer_pick, the control-word decode and the buffer picks,
// albatross_transfer_dest, the per-destination registers, and
// albatross_transfer_order, the destinations' order),
// albatross_transfer_frag (the word index, the fragment's range, the
// progress), albatross_transfer_access (address, lanes and write data of the
// access).
`default_nettype none

module albatross_transfer #(
    parameter ADDR_WIDTH    = 10, // word-address bits of a board RAM
    parameter HAS_FRAGMENTS = 1   // 1: a COPY's value may go over several runs (frag_on_i); 0: frag_on_i is ignored
) (
    input  wire                    clk_i,
    input  wire                    rst_i,          // synchronous, active high
    // the entry (sequencer registers, held for the slot)
    input  wire                    go_i,           // one clock: start the slot's transfer
    input  wire                    copy_i,         // kind COPY
    input  wire                    time_kind_i,    // kind TIME (else STATUS, when not COPY)
    input  wire                    four_i,         // the four-slot kind
    input  wire                    request_i,      // a REQUEST COPY: its New value is a mode request
    input  wire [3:0]              active_i,       // the destinations of the entry
    input  wire [11:0]             words_i,        // W
    input  wire                    frag_on_i,      // E7.frag != 0: the value may go over several runs; valid from 2 clocks after go_i
    input  wire [3:0]              src_board_i,
    input  wire [ADDR_WIDTH-1:0]   src_base_i,
    input  wire [15:0]             dst_board_i,    // d at [4d +: 4]
    input  wire [4*ADDR_WIDTH-1:0] dst_base_i,     // d at [d*ADDR_WIDTH +: ADDR_WIDTH]
    input  wire [31:0]             slot_time_i,    // TIME's value, TIME's and STATUS's taken_at
    input  wire                    may_access_i,   // an access begun next clock ends before the deadline
    input  wire [7:0]              drop_run_i,     // K (ROM H2)
    // the channel's state (state RAM, valid at go_i and through the slot)
    input  wire [2:0]              st_rl_i,        // ReadLocked copy / four-slot L (0 unknown)
    input  wire [3:0]              st_need_i,      // destinations that still need the current value
    input  wire [11:0]             st_tried_i,     // buffers tried: picked, Actual (four-slot: Slot) store made (0 none), d at [3d +: 3]
    input  wire [31:0]             st_taken_i,     // taken_at of the current value
    input  wire                    st_on_i,        // fragments: a value goes on
    input  wire [11:0]             st_prog_i,      // ... its progress: the first word not stored to every destination in it
    // STATUS words
    input  wire [31:0]             status_i,
    input  wire                    status_valid_i,
    output wire [11:0]             index_o,        // the word taken next
    // results, valid with done_o
    output wire                    done_o,         // one clock: the slot's transfer is over
    output wire                    imp_run_o,      // the Import ran in this slot (COPY)
    output wire                    exp_run_o,      // the Export ran
    output wire                    new_o,          // one clock: a New value is chosen now: store the global time as its taken_at
    output wire [2:0]              rl_o,           // the copy after the slot
    output wire [3:0]              need_o,         // destinations still in need after the Export
    output wire [11:0]             tried_o,
    output wire                    on_o,           // fragments: the value goes on after the slot
    output wire                    on_wr_o,        // ... on_o is written (else the state keeps it)
    output wire [11:0]             prog_o,         // fragments: the progress after the slot
    output wire                    prog_wr_o,      // ... prog_o is written (else the state keeps it)
    output wire [3:0]              aband_o,        // destinations abandoned in this slot (when the Export ran)
    output wire [2:0]              transfers_o,    // destinations published
    output wire [2:0]              corrupt_o,      // control bytes that named no buffer
    output wire                    mode_req_o,     // one clock: a mode request (REQUEST entries)
    output wire [3:0]              mode_req_mode_o,
    // requester port (cyc = stb)
    output wire                    cyc_o,
    output wire                    we_o,
    output wire [ADDR_WIDTH-1:0]   adr_o,
    output wire [3:0]              board_o,
    output wire [3:0]              sel_o,
    output wire [31:0]             dat_o,
    input  wire [31:0]             dat_i,
    input  wire                    ack_i,
    input  wire                    err_i
);

    localparam AW      = ADDR_WIDTH;
    generate
        if (AW < 3) begin : g_param_check
            albatross_transfer_parameter_out_of_range u_error ();
        end
    endgenerate

    // ------------------------------------------------------------ the state machine
    wire        cont, lastf, mid, take, cont_q, wend, safe, need_any;
    wire        dst, src_act, src_rl, src_word, dst_word, dst_tkn, dst_slot, dst_fin;
    wire [1:0]  d;
    wire [2:0]  ald, buf_d;
    wire [31:0] word;
    wire [11:0] k;
    albatross_transfer_fsm u_fsm (
        .clk_i(clk_i), .rst_i(rst_i), .go_i(go_i), .copy_i(copy_i), .time_kind_i(time_kind_i), .four_i(four_i),
        .request_i(request_i), .active_i(active_i), .may_access_i(may_access_i), .drop_run_i(drop_run_i),
        .st_rl_i(st_rl_i), .st_need_i(st_need_i), .st_tried_i(st_tried_i),
        .status_i(status_i), .status_valid_i(status_valid_i),
        .cont_i(cont), .lastf_i(lastf), .mid_i(mid),
        .take_o(take), .cont_q_o(cont_q), .wend_o(wend), .safe_o(safe), .need_any_o(need_any),
        .dst_o(dst), .src_act_o(src_act), .src_rl_o(src_rl), .src_word_o(src_word), .dst_word_o(dst_word),
        .dst_tkn_o(dst_tkn), .dst_slot_o(dst_slot), .dst_fin_o(dst_fin), .d_o(d), .ald_o(ald), .buf_d_o(buf_d),
        .word_o(word), .done_o(done_o), .imp_run_o(imp_run_o), .exp_run_o(exp_run_o), .new_o(new_o), .rl_o(rl_o),
        .need_o(need_o), .aband_o(aband_o), .tried_o(tried_o), .transfers_o(transfers_o),
        .corrupt_o(corrupt_o), .mode_req_o(mode_req_o), .mode_req_mode_o(mode_req_mode_o),
        .cyc_o(cyc_o), .dat_i(dat_i), .ack_i(ack_i), .err_i(err_i));

    // ------------------------------------------------------------ the word index and the progress
    albatross_transfer_frag #(.HAS_FRAGMENTS(HAS_FRAGMENTS)) u_frag (
        .clk_i(clk_i), .rst_i(rst_i), .go_i(go_i), .copy_i(copy_i), .request_i(request_i), .words_i(words_i),
        .frag_on_i(frag_on_i), .st_on_i(st_on_i), .st_prog_i(st_prog_i), .need_any_i((st_need_i & active_i) != 4'd0),
        .take_i(take), .wend_i(wend), .cont_q_i(cont_q), .safe_i(safe), .need_any_q_i(need_any),
        .cont_o(cont), .k_o(k), .lastf_o(lastf), .mid_o(mid), .on_wr_o(on_wr_o), .prog_o(prog_o), .prog_wr_o(prog_wr_o));
    assign on_o    = mid;
    assign index_o = k;

    // ------------------------------------------------------------ the access
    albatross_transfer_access #(.ADDR_WIDTH(AW)) u_access (
        .dst_i(dst), .src_act_i(src_act), .src_rl_i(src_rl), .src_word_i(src_word),
        .dst_word_i(dst_word), .dst_tkn_i(dst_tkn), .dst_slot_i(dst_slot),
        .dst_fin_i(dst_fin), .copy_i(copy_i), .time_kind_i(time_kind_i), .four_i(four_i),
        .words_i(words_i), .k_i(k), .d_i(d), .rl_i(rl_o[1:0]), .buf_i(buf_d), .ald_i(ald),
        .src_board_i(src_board_i), .src_base_i(src_base_i), .dst_board_i(dst_board_i), .dst_base_i(dst_base_i),
        .word_i(word), .slot_time_i(slot_time_i), .taken_i(st_taken_i),
        .we_o(we_o), .adr_o(adr_o), .board_o(board_o), .sel_o(sel_o), .dat_o(dat_o));

endmodule

`default_nettype wire
