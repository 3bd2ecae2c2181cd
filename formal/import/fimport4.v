// fimport4 -- proof harness of albatross_import as the consumer of the
// four-slot kind (four_i = 1; Simpson's four-slot
// mechanism on single-writer bytes; formal/import/import.sby tasks four*,
// docs/verification.md "Four-slot engines").
//
// The engine (PULL = 1, the controller's) runs Import after Import on ONE
// channel at a symbolic base (anyconst) with a symbolic W = 1..2 (anyconst):
// the control word holds Actual (byte 0), ReadLocked (byte 1), Slot0 (byte
// 2) and Slot1 (byte 3), then Buffer1..Buffer4 of W words.  The engine keeps
// its copy L itself (rl_known_o/rl_o fed back to rl_known_i/rl_i, as
// albatross_import_endpoint does), so every state is reachable from reset.
// Rules of the environment:
//   * Reset in the first clock only; the RAM starts as the compiler's image:
//     Actual = ReadLocked = 1, Slot0 = Slot1 = 0.
//   * The slave answers any request with ack or err (free, never both, none
//     without a request), after any wait.  A store answered with err may or
//     may not land (free).
//   * The producer is the four-slot Export with free timing, one atomic byte
//     access a clock (p_go free): begin (load ReadLocked R, pick p = 1 -
//     pair(R), s = 1 - Slot_p, the buffer WB = 1 + 2p + s), write WB during
//     every clock until it stores Slot_p := s, then (a later clock) Actual :=
//     WB.  start_i, stream_i, skip_i, word_ready_i, may_access_i are free.
// Properties (labels; "word load" = a request with we = 0 at a buffer word):
//   fs_store_rl       every store is ReadLocked := the Actual loaded by this
//                     Import (control word, ReadLocked lane only, a buffer 1..4);
//   fs_in_channel     every access lies inside the channel (control word, or a
//                     word of Buffer1..4);
//   fs_no_torn        no word load of the buffer the producer is writing
//                     (mutual exclusion);
//   fs_load_chosen    every word load is of the buffer the protocol names: L
//                     when the first load returned 1 + 2 pair(A) + Slot_pair(A)
//                     = L (Old), else
//                     1 + 2 pair(A) + Slot_pair(A) as the second load returned it;
//   fs_fresh          ... a buffer that holds the value Actual named at the
//                     Import's start, or one completed since (never older);
//   fs_old_same       Old only when buffer L holds the value read last (the
//                     producer has not begun to rewrite it since);
//   fs_new_exact      New (with L known at start) only when the buffer read is
//                     another one than L or L was rewritten: never one value
//                     New twice;
//   fs_count          an Import with no err and not cut off makes exactly 1
//                     (Old) or 3 (New) control accesses, and at most W word
//                     loads (corrupt: 1, no load); covers show all W;
//   fs_wait_free      whatever the producer does (err and cut-off included),
//                     at most 3 control accesses of an Import are acked;
//   fs_count_words    ... and exactly W word loads when the last word was taken;
//   fs_no_idle        from its first access to selected_o (or its end) the
//                     Import keeps a request on the bus but in the clock after
//                     an err: its control accesses are back to back;
//   fs_copy           after an Import that was not cut off with a word read,
//                     rl_o is the buffer read.
// Covers: Old, New, a New whose buffer differs from the Actual it announced
// (the producer completed inside the Import), a complete streamed Import.
`default_nettype none

module fimport4 #(
    parameter ADDR_WIDTH  = 4,  // word-address bits of the port
    parameter WORDS_WIDTH = 2,  // bits of words_i (W = 1..2)
    parameter PULL        = 1   // the engine's PULL (1 the controller's, 0 the endpoint's)
) (
    input  wire                   clk_i,
    input  wire                   rst_i,
    input  wire                   start_i,
    input  wire                   may_access_i,
    input  wire                   stream_i,
    input  wire                   skip_i,
    input  wire                   word_ready_i,
    input  wire                   ack_i,
    input  wire                   err_i,
    input  wire                   land_i,       // a store answered with err lands
    input  wire                   p_go_i        // the producer takes its next step
);

`include "albatross_contract.vh"

    localparam AW = ADDR_WIDTH;
    localparam WW = WORDS_WIDTH;
    (* anyconst *) reg [AW-1:0] f_base;
    (* anyconst *) reg [WW-1:0] f_w;

    wire          idle, selected, word_valid, done, new_v, corrupt, cut, rl_known;
    wire [31:0]   word;
    wire [WW-1:0] word_index;
    wire [1:0]    fails;
    wire [2:0]    rl;
    wire          cyc, stb, we;
    wire [AW-1:0] adr;
    wire [3:0]    sel;
    wire [31:0]   wdat;
    reg  [31:0]   rdat;

    albatross_import #(.ADDR_WIDTH(AW), .WORDS_WIDTH(WW), .COUNT_WIDTH(2), .PULL(PULL)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(start_i), .four_i(1'b1), .base_i(f_base), .words_i(f_w), .rl_known_i(rl_known), .rl_i(rl),
        .may_access_i(may_access_i), .idle_o(idle),
        .selected_o(selected), .stream_i(stream_i), .skip_i(skip_i),
        .word_o(word), .word_valid_o(word_valid), .word_ready_i(word_ready_i), .word_index_o(word_index),
        .done_o(done), .new_o(new_v), .corrupt_o(corrupt), .cut_o(cut), .fails_o(fails),
        .rl_known_o(rl_known), .rl_o(rl),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_sel_o(sel),
        .wb_dat_o(wdat), .wb_dat_i(rdat), .wb_ack_i(ack_i), .wb_err_i(err_i)
    );

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);
    always @* assume(f_w != {WW{1'b0}} && f_w <= 2);
    // the channel (1 + 4W words) fits the port
    always @* assume({1'b0, f_base} + 5'd1 + {f_w, 2'b00} <= 5'd16);
    always @* assume(!(ack_i && err_i) && ((ack_i || err_i) ? (cyc && stb) : 1'b1));

    // ------------------------------------------------------------ the RAM
    reg [2:0] m_act  = 3'd1;      // Actual (bytes hold 1..4; the engine reads all 8 bits)
    reg [2:0] m_rl   = 3'd1;      // ReadLocked
    reg       m_s0   = 1'b0;      // Slot0
    reg       m_s1   = 1'b0;      // Slot1
    /* the data words are free: only addresses matter here */
    (* anyseq *) reg [31:0] f_data;
    wire [AW-1:0] off     = adr - f_base;
    wire          is_ctrl = off == {AW{1'b0}};
    wire [AW-1:0] boff    = off - 1'b1;                 // word offset in the buffers
    wire [2:0]    abuf    = (f_w == 2'd1 ? boff[2:0] : {1'b0, boff[2:1]}) + 3'd1;   // its buffer 1..4
    wire [AW:0]   ch_end  = {1'b0, f_w, 2'b00};         // 4W: last buffer word offset
    wire          in_ch   = {1'b0, off} <= ch_end;
    always @* begin
        rdat = f_data;
        if (is_ctrl) rdat = {7'd0, m_s1, 7'd0, m_s0, 5'd0, m_rl, 5'd0, m_act};
    end
    wire req      = cyc && stb;
    wire ctrl_ld  = req && !we && is_ctrl;
    wire word_ld  = req && !we && !is_ctrl;

    // ------------------------------------------------------------ the producer
    reg [1:0] p_ph = 2'd0;        // 0 idle, 1 writing WB, 2 Slot stored, Actual not yet
    reg       p_p  = 1'b0, p_s = 1'b0;
    wire [2:0] p_wb    = {1'b0, p_p, p_s} + 3'd1;
    wire       rl_pair = m_rl[2] | (m_rl[1] & m_rl[0]);
    wire       p_new   = !rl_pair;
    wire       dut_rl  = !rst_i && req && we && (ack_i || (err_i && land_i));   // the engine's store lands now
    always @(posedge clk_i) begin
        if (dut_rl) m_rl <= wdat[10:8];
        if (p_go_i) case (p_ph)
            2'd0: begin p_p <= p_new; p_s <= !(p_new ? m_s1 : m_s0); p_ph <= 2'd1; end
            2'd1: begin if (p_p) m_s1 <= p_s; else m_s0 <= p_s; p_ph <= 2'd2; end
            default: begin m_act <= p_wb; p_ph <= 2'd0; end
        endcase
    end

    // ------------------------------------------------------------ the Import's history
    reg        h_run = 1'b0;      // an Import runs (start taken)
    reg [2:0]  h_l;               // L at start (0 unknown)
    reg [2:0]  h_a;               // Actual of the first load
    reg        h_a_ok;            // ... taken
    reg [2:0]  h_b;               // the buffer the protocol names (0: not yet)
    reg        h_err;             // an err in this Import
    reg [2:0]  h_nctrl;           // control accesses acked
    reg [2:0]  h_nword;           // word loads acked
    reg [7:0]  h_old;             // buffer b holds a value older than Actual at start
    reg [7:0]  h_dirty = 8'd0;    // buffer b was begun by the producer since the engine chose it last
    reg        h_read;            // a word was loaded in this Import
    reg        h_last;            // the last word (W - 1) was taken
    reg        h_sel;             // selected_o was seen (phase 1 over)
    reg        h_err1 = 1'b0;     // an access failed in the previous clock
    wire       a_pair  = h_a[2] | (h_a[1] & h_a[0]);
    wire [2:0] slot_b  = {1'b0, a_pair, a_pair ? m_s1 : m_s0} + 3'd1;
    wire       start   = start_i && idle;
    wire       n_pair  = m_act[2] | (m_act[1] & m_act[0]);
    wire [2:0] cur_c   = {1'b0, n_pair, n_pair ? m_s1 : m_s0} + 3'd1;   // newest complete of Actual's pair
    integer    bi;
    always @(posedge clk_i) begin
        if (p_go_i && p_ph == 2'd0) h_dirty[{1'b0, p_new, !(p_new ? m_s1 : m_s0)} + 3'd1] <= 1'b1;
        if (p_go_i && p_ph == 2'd1) h_old[p_wb] <= 1'b0;                    // completed: fresh
        if (done) h_run <= 1'b0;                     // (a start may follow in the done clock)
        if (start) begin
            h_run   <= 1'b1;
            h_l     <= rl_known ? rl : 3'd0;
            h_a_ok  <= 1'b0;
            h_b     <= 3'd0;
            h_err   <= 1'b0;
            h_nctrl <= 3'd0;
            h_nword <= 3'd0;
            h_read  <= 1'b0;
            h_last  <= 1'b0;
            h_sel   <= 1'b0;
            for (bi = 1; bi <= 4; bi = bi + 1)
                h_old[bi] <= !(bi[2:0] == m_act || (p_ph == 2'd2 && bi[2:0] == p_wb) ||
                               (p_go_i && p_ph == 2'd1 && bi[2:0] == p_wb));
        end
        if (h_run && req && err_i) h_err <= 1'b1;
        h_err1 <= req && err_i;
        if (h_run && selected) h_sel <= 1'b1;
        if (h_run && word_valid && word_ready_i && word_index == f_w - 1'b1) h_last <= 1'b1;
        if (h_run && req && ack_i && is_ctrl) h_nctrl <= h_nctrl + 3'd1;
        if (h_run && word_ld && ack_i) begin h_nword <= h_nword + 3'd1; h_read <= 1'b1; end
        if (h_run && ctrl_ld && ack_i && !h_a_ok) begin
            h_a_ok <= 1'b1;
            h_a    <= m_act;
            if (cur_c == h_l) h_b <= h_l;
        end
        if (h_run && ctrl_ld && ack_i && h_a_ok) begin
            h_b <= slot_b;
            h_dirty[slot_b] <= 1'b0;
        end
        if (rst_i) begin h_run <= 1'b0; h_dirty <= 8'd0; end
    end

    // ------------------------------------------------------------ properties
    wire chk = !init_q && !rst_i;
    always @* if (chk) begin
        if (req && we) fs_store_rl: assert(is_ctrl && sel == 4'b0010 && h_a_ok && wdat[10:8] == h_a &&
                                           h_a != 3'd0 && h_a <= 3'd4 && wdat[31:11] == 21'd0 && wdat[7:0] == 8'd0);
        if (req) fs_in_channel: assert(in_ch && h_run);
        if (word_ld) begin
            fs_no_torn:     assert(!(p_ph == 2'd1 && abuf == p_wb));
            fs_load_chosen: assert(h_b != 3'd0 && abuf == h_b);
            fs_fresh:       assert(!h_old[abuf]);
        end
        // Old decided at the first load: buffer L unchanged since it was chosen
        if (h_run && ctrl_ld && ack_i && !h_a_ok && cur_c == h_l && h_l != 3'd0)
            fs_old_same: assert(!h_dirty[h_l]);
        if (h_run && ctrl_ld && ack_i && h_a_ok && h_l != 3'd0)
            fs_new_exact: assert(slot_b != h_l || h_dirty[h_l]);
        if (done && !h_err && !cut)
            fs_count: assert(h_nctrl == (corrupt ? 3'd1 : new_v ? 3'd3 : 3'd1) &&
                             (corrupt ? h_nword == 3'd0 : h_nword <= {1'b0, f_w}));
        if (done && !cut && h_read) fs_copy: assert(rl_known && rl == h_b);
        if (h_run) fs_wait_free: assert(h_nctrl <= 3'd3);
        if (done && !h_err && !cut && h_last) fs_count_words: assert(h_nword == {1'b0, f_w});
        // phase 1 has no idle bus clock: 1 or 3 back-to-back control accesses
        if (h_run && !h_sel && !done && !h_err1) fs_no_idle: assert(req);
    end
    reg h_streamed;   // every word was loaded in this Import (count check)
    always @* h_streamed = h_nword == {1'b0, f_w};

    always @* if (chk) begin
        cover_old:  cover(done && !cut && !new_v && h_read && h_streamed);
        cover_new:  cover(done && !cut && new_v && h_read && h_streamed && !h_err);
        cover_diff: cover(done && !cut && new_v && h_read && h_b != h_a);
    end
`endif

endmodule

`default_nettype wire
