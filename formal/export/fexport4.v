// fexport4 -- proof harness of albatross_export as the producer of the
// four-slot kind (four_i = 1; formal/export/export.sby
// tasks four*, docs/verification.md "Four-slot engines").
//
// The engine (TAKEN_AT = 1, DROP = 1, the controller's; DESTS = 2, in
// lockstep) runs Export after Export to TWO destination channels at symbolic
// bases (anyconst, apart) with a symbolic W = 1..2 (anyconst), stride S = W +
// 1, each destination taking part or not (need_i free at start): the control
// word holds Actual (byte 0), ReadLocked (byte 1), Slot0 (byte 2), Slot1
// (byte 3), then Buffer1..Buffer4.  The engine's per-destination state
// (act_known/act/tried) is fed back from its outputs (as the controller's
// state RAM does), so every state is reachable from reset.
// Rules of the environment:
//   * Reset in the first clock only; the RAM starts as the compiler's image
//     (Actual = ReadLocked = 1, Slot0 = Slot1 = 0).
//   * The slave answers any request with ack or err (free, never both, none
//     without a request), after any wait; a store answered with err may or
//     may not land (free).  start_i, may_access_i, word_valid_i are free.
//   * Each destination's consumer is the four-slot Import with free timing,
//     one atomic access a clock (c_go_i[d] free): load the control word: Actual A, c = 1 +
//     2 pair(A) + Slot_pair(A); if c is its L, read L (Old); else store
//     ReadLocked := A (a later clock), load the control word again (a later
//     clock), read b = 1 + 2 pair(A) + Slot_pair(A), L := b.  It reads its
//     buffer for any number of clocks.
// Properties (labels):
//   fs_no_write_read  no store to a word of the buffer the consumer is reading
//                     (mutual exclusion);
//   fs_read_complete  the consumer only ever starts reading a buffer whose
//                     last write by the engine was completed by its Slot store
//                     (or never written): publish only complete buffers;
//   fs_other_pair     every buffer store is in the pair other than the one the
//                     ReadLocked of the engine's control-word load names;
//   fs_pick           the buffer is 1 + 2p + s, p = 1 - pair(ReadLocked), s = 1
//                     - Slot_p of that load;
//   fs_slot_store     a control store to a slot byte stores s into Slot_p of the
//                     picked buffer, after all W + 1 words of it were stored (acked);
//   fs_actual_store   a store of Actual names the picked buffer, after its Slot
//                     store was acked in this Export (Slot before Actual);
//   fs_ctrl_lanes     a control load reads all four lanes; a control store
//                     selects one lane, a slot byte 0/1 or Actual 1..4;
//   fs_in_channel     every access lies in the channel of dest_o, inside an Export;
//   fs_count          an Export with no err, no cut-off and no tried buffer at
//                     its start makes exactly ND * (W + 4) accesses (per
//                     destination: load, W words, taken_at, Slot, Actual: the
//                     three-buffer count plus one byte store) and publishes
//                     to every destination in need.
// Covers: a complete Export, two Exports, the consumer reading a buffer
// completed after its announcement.
`default_nettype none

module fexport4 #(
    parameter ADDR_WIDTH = 5   // word-address bits
) (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        start_i,
    input  wire [1:0]  need_i,
    input  wire [31:0] taken_at_i,
    input  wire        may_access_i,
    input  wire [31:0] word_i,
    input  wire        word_valid_i,
    input  wire        ack_i,
    input  wire        err_i,
    input  wire        land_i,     // a store answered with err lands
    input  wire [1:0]  c_go_i      // consumer d takes its next step
);

`include "albatross_contract.vh"

    localparam AW = ADDR_WIDTH;
    localparam DESTS = 2;
    (* anyconst *) reg [DESTS*AW-1:0] f_base;
    (* anyconst *) reg [1:0]          f_w;

    wire          idle, ready, done, cut;
    wire [1:0]    windex;
    wire [1:0]    published, corrupt, known, dest;
    wire          fails;
    wire [3:0]    act;
    wire [5:0]    tried;
    wire          cyc, stb, we;
    wire [AW-1:0] adr;
    wire [3:0]    sel;
    wire [31:0]   wdat;
    reg  [31:0]   rdat;

    // The drop run K (ROM H2): any constant 0..3 (0 and 1 read as 2).
    (* anyconst *) reg [7:0] f_drop_run;
    always @* small_k: assume(f_drop_run <= 8'd3);
    albatross_export #(.ADDR_WIDTH(AW), .WORDS_WIDTH(2), .COUNT_WIDTH(1), .TAKEN_AT(1),
                       .DESTS(DESTS), .DROP(1)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .drop_run_i(f_drop_run),
        .start_i(start_i), .four_i(1'b1), .base_i(f_base), .need_i(need_i), .words_i(f_w),
        .taken_at_i(taken_at_i), .act_known_i(known), .act_i(act), .tried_i(tried),
        .may_access_i(may_access_i), .idle_o(idle),
        .word_i(word_i), .word_valid_i(word_valid_i), .word_ready_o(ready), .word_index_o(windex),
        .done_o(done), .published_o(published), .corrupt_o(corrupt), .cut_o(cut), .fails_o(fails),
        .act_known_o(known), .act_o(act), .tried_o(tried), .dest_o(dest),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_sel_o(sel),
        .wb_dat_o(wdat), .wb_dat_i(rdat), .wb_ack_i(ack_i), .wb_err_i(err_i)
    );

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);
    always @* assume(f_w != 2'd0 && f_w <= 2'd2);
    wire [2:0] f_s = {1'b0, f_w} + 3'd1;                       // stride W + 1
    wire [AW:0] ch_w = {{(AW-4){1'b0}}, f_s, 2'b00} + 1'b1;    // 1 + 4S words a channel
    wire [AW:0] b0 = {1'b0, f_base[0 +: AW]}, b1 = {1'b0, f_base[AW +: AW]};
    // both channels fit the port and do not overlap
    always @* assume(b0 + ch_w <= (1 << AW) && b1 + ch_w <= (1 << AW) && (b0 + ch_w <= b1 || b1 + ch_w <= b0));
    always @* assume(!(ack_i && err_i) && ((ack_i || err_i) ? (cyc && stb) : 1'b1));

    wire req     = cyc && stb && !rst_i;
    wire lands   = req && we && (ack_i || (err_i && land_i));
    wire chk     = !init_q && !rst_i;
    wire start   = start_i && idle;

    // ------------------------------------------------------------ the Export's history (shared)
    reg        h_run = 1'b0;
    reg        h_err;
    reg [1:0]  h_need;          // destinations in need at start
    reg [1:0]  h_tried;         // ... with a tried buffer at start
    reg [4:0]  h_acks;
    always @(posedge clk_i) begin
        if (done) h_run <= 1'b0;
        if (start) begin
            h_run <= 1'b1; h_err <= 1'b0; h_acks <= 5'd0; h_need <= need_i;
            h_tried <= {tried[5:3] != 3'd0, tried[2:0] != 3'd0};
        end
        if (h_run && req && err_i) h_err <= 1'b1;
        if (h_run && req && ack_i) h_acks <= h_acks + 5'd1;
        if (rst_i) h_run <= 1'b0;
    end

    wire [1:0]  in_chan;        // the access lies in channel d
    wire [63:0] rd_d;           // channel d's control word at [32d +: 32]
    always @* rdat = in_chan[1] ? rd_d[63:32] : rd_d[31:0];

    // per destination: the property holds (1) in this clock; asserted after the generate
    wire [1:0] v_in_channel, v_no_write_read, v_other_pair, v_pick, v_read_complete, v_ctrl_lanes,
               v_ctrl_lanes_st, v_slot_store, v_actual_store, c_fresh;
    genvar g;
    generate for (g = 0; g < DESTS; g = g + 1) begin : g_d
        // ---------------------------------------------------------- channel d's RAM
        reg [2:0] m_act = 3'd1, m_rl = 3'd1;
        reg       m_s0 = 1'b0, m_s1 = 1'b0;
        wire [AW-1:0] off     = adr - f_base[g*AW +: AW];
        wire          in_ch   = {1'b0, off} < ch_w;
        wire          is_ctrl = in_ch && off == {AW{1'b0}};
        wire [AW-1:0] boff    = off - 1'b1;
        wire [2:0]    abuf    = f_s == 3'd2 ? {1'b0, boff[2:1]} + 3'd1 :
                                (boff < 3 ? 3'd1 : boff < 6 ? 3'd2 : boff < 9 ? 3'd3 : 3'd4);
        assign in_chan[g] = in_ch;
        assign rd_d[32*g +: 32] = {7'd0, m_s1, 7'd0, m_s0, 5'd0, m_rl, 5'd0, m_act};
        wire ctrl_st = req && we && is_ctrl;
        wire buf_st  = req && we && in_ch && !is_ctrl;
        wire ctrl_ld = req && !we && is_ctrl;

        // ---------------------------------------------------------- its consumer
        reg [1:0] c_ph = 2'd0;     // 0 idle, 1 loaded (store ReadLocked next), 2 stored (load next), 3 reading
        reg [2:0] c_a, c_b;
        reg [2:0] c_l = 3'd0;      // its L (0: none)
        wire       ca_pair = m_act[2] | (m_act[1] & m_act[0]);
        wire [2:0] c_cur   = {1'b0, ca_pair, ca_pair ? m_s1 : m_s0} + 3'd1;
        wire       cp      = c_a[2] | (c_a[1] & c_a[0]);
        wire [2:0] c_pick  = {1'b0, cp, cp ? m_s1 : m_s0} + 3'd1;
        reg  [7:0] partial = 8'd0; // buffer b: the engine began writing it and has not stored its Slot since
        wire       c_start_read = c_go_i[g] && ((c_ph == 2'd0 && c_cur == c_l) || c_ph == 2'd2);
        wire [2:0] c_next_b     = c_ph == 2'd0 ? c_l : c_pick;

        // ---------------------------------------------------------- the Export's history at d
        reg        h_ld;            // the control word was loaded (acked)
        reg [2:0]  h_rl;            // ... its ReadLocked
        reg [2:0]  h_b;             // ... the buffer it names (fs_pick)
        reg [2:0]  h_nst;           // buffer stores acked
        reg        h_slot;          // the Slot store acked
        wire       r_pair = m_rl[2] | (m_rl[1] & m_rl[0]);
        wire       r_ok   = m_rl != 3'd0 && m_rl <= 3'd4;
        wire       e_p    = r_ok ? !r_pair : !ca_pair;
        wire [2:0] e_b    = {1'b0, e_p, !(e_p ? m_s1 : m_s0)} + 3'd1;

        always @(posedge clk_i) begin
            if (c_go_i[g]) case (c_ph)
                2'd0: if (c_cur == c_l) begin c_b <= c_l; c_ph <= 2'd3; end
                      else begin c_a <= m_act; c_ph <= 2'd1; end
                2'd1: begin m_rl <= c_a; c_ph <= 2'd2; end
                2'd2: begin c_b <= c_pick; c_l <= c_pick; c_ph <= 2'd3; end
                default: c_ph <= 2'd0;
            endcase
            // the engine's stores (its ReadLocked is never stored: fs_ctrl_lanes_st)
            if (lands && is_ctrl && sel == 4'b0001) m_act <= wdat[2:0];
            if (lands && is_ctrl && sel == 4'b0100) m_s0  <= wdat[16];
            if (lands && is_ctrl && sel == 4'b1000) m_s1  <= wdat[24];
            if (buf_st) partial[abuf] <= 1'b1;                           // (begun, landed or not)
            if (lands && is_ctrl && sel[3:2] != 2'b00) partial[h_b] <= 1'b0;
            if (start) begin h_ld <= 1'b0; h_nst <= 3'd0; h_slot <= 1'b0; end
            if (h_run && ctrl_ld && ack_i) begin h_ld <= 1'b1; h_rl <= m_rl; h_b <= e_b; end
            if (h_run && buf_st && ack_i) h_nst <= h_nst + 3'd1;
            if (h_run && ctrl_st && ack_i && sel[3:2] != 2'b00) h_slot <= 1'b1;
        end

        // ---------------------------------------------------------- properties at d (asserted below)
        wire [1:0] hbm1 = h_b[1:0] - 2'd1;
        assign v_in_channel[g]  = !(req && in_ch) || (h_run && dest == g && h_need[g]);
        assign v_no_write_read[g] = !buf_st || !(c_ph == 2'd3 && abuf == c_b);
        assign v_other_pair[g]  = !buf_st || (h_ld && (abuf[2] | (abuf[1] & abuf[0])) != (h_rl[2] | (h_rl[1] & h_rl[0])) &&
                                             h_rl != 3'd0 && h_rl <= 3'd4);
        assign v_pick[g]        = !buf_st || abuf == h_b;
        assign v_read_complete[g] = !c_start_read || !partial[c_next_b] || c_next_b == 3'd0;
        assign v_ctrl_lanes[g]  = !(req && !we && in_ch) || (is_ctrl && sel == 4'hF);
        assign v_ctrl_lanes_st[g] = !ctrl_st ||
                                    (sel == 4'b0001 ? wdat[31:3] == 29'd0 && wdat[2:0] != 3'd0 && wdat[2:0] <= 3'd4 :
                                     sel == 4'b0100 ? wdat[31:17] == 15'd0 && wdat[15:0] == 16'd0 :
                                     sel == 4'b1000 ? wdat[31:25] == 7'd0 && wdat[23:0] == 24'd0 : 1'b0);
        assign v_slot_store[g]  = !(ctrl_st && sel[3:2] != 2'b00) ||
                                  (h_ld && (sel == (hbm1[1] ? 4'b1000 : 4'b0100)) &&
                                   (hbm1[1] ? wdat[24] : wdat[16]) == hbm1[0] && h_nst == f_s);
        assign v_actual_store[g] = !(ctrl_st && sel == 4'b0001) || (h_ld && wdat[2:0] == h_b && h_slot && h_nst == f_s);
        assign c_fresh[g]       = c_start_read && c_ph == 2'd2 && c_pick != c_a;
    end endgenerate

    // ------------------------------------------------------------ shared properties
    wire [2:0] nd = {2'b00, h_need[0]} + {2'b00, h_need[1]};
    wire [4:0] per = {3'b000, f_w} + 5'd4;
    always @* if (chk) begin
        fs_in_channel:    assert(&v_in_channel && (!req || |in_chan));
        fs_no_write_read: assert(&v_no_write_read);
        fs_other_pair:    assert(&v_other_pair);
        fs_pick:          assert(&v_pick);
        fs_read_complete: assert(&v_read_complete);
        fs_ctrl_lanes:    assert(&v_ctrl_lanes);
        fs_ctrl_lanes_st: assert(&v_ctrl_lanes_st);
        fs_slot_store:    assert(&v_slot_store);
        fs_actual_store:  assert(&v_actual_store);
        if (done && h_run && !h_err && h_tried == 2'b00 && !cut)
            fs_count: assert(h_acks == (nd == 3'd0 ? 5'd0 : nd == 3'd1 ? per : per + per) && published == h_need);
    end
    reg [1:0] n_exports = 2'd0;
    always @(posedge clk_i) if (chk && done && published != 2'b00 && n_exports != 2'd3) n_exports <= n_exports + 2'd1;
    always @* if (chk) begin
        cover_one:  cover(done && published == 2'b11 && !h_err);
        cover_two:  cover(done && published != 2'b00 && n_exports == 2'd1);
        cover_fresh: cover(|c_fresh);
    end
`endif

endmodule

`default_nettype wire
