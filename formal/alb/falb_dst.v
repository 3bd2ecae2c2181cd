// falb_dst -- property checker of one destination channel of the ALBATROSS
// controller, watching the controller's system bus at the slave side
// (docs/verification.md "The controller on its own RTL").  Written for
// ALBATROSS in the style of wb2axip's property sets; reusable by any harness
// whose device under test is the producer of destination channels (the
// controller, its transfer datapath, an Export engine).
//
// The channel (rtl/albatross_contract.toml; docs/four_slot.md) sits on board
// BOARD at word base_i with W = words_i value words and taken_at after them
// (buffer stride S = W + 1): control word at base_i (byte 0 Actual, 1
// ReadLocked, 2 Slot0, 3 Slot1), buffer b (1..3, four-slot 1..4) at base_i +
// 1 + (b - 1) S.  This module keeps the control word (the load data it
// returns on ctrl_o) and runs a free consumer on it (op_i each clock):
//   three-buffer (paper figure 3): 1 = load Actual (seen := Actual; when it
//     equals ReadLocked the consumer's lock on that buffer is CONFIRMED and it
//     reads that buffer until its next ReadLocked store), 2 = store
//     ReadLocked := seen (the lock ends);
//   four-slot (Simpson's reader, docs/four_slot.md "Import"): 1 = load the
//     control word (A := Actual; A = L: the reader HOLDS L again; else it must
//     announce), 2 = store ReadLocked := A, 3 = load it again and HOLD b =
//     buf(pair(A), Slot_pair(A)), L := b.  A hold lasts until its next 1.
// Each clock the consumer's action and the bus access see the state at the
// start of the clock (a serialisation of two byte-atomic accesses).  A store
// lands when acked, or (land_i) in any clock of its request without ack (an
// answer lost, or an err'd store that was performed).  The initial control
// word is any valid one (the RAM keeps it across a controller reset); the
// three-buffer consumer may start confirmed; the four-slot one starts idle.
// Properties (labels; "the Export" = the stores since slot_start_i):
//   dst_in_channel      every access to BOARD lies in the channel;
//   dst_loads           a load reads the control word only;
//   dst_ctrl_store      a control store writes one byte: Actual (a buffer
//                       1..3 / 1..4) or, four-slot, Slot_p (0 or 1);
//   dst_publish_complete a store of Actual := b requests only after every
//                       word of b (W value words and taken_at) was stored
//                       (acked) in the same Export; four-slot, or b is WHOLE:
//                       a Slot store of b landed after every word of b was
//                       stored in its Export, and no word of b has been
//                       requested since (a value completed by an earlier
//                       Export whose Actual store was not made, published
//                       now; PROTO = 0: no word of b stored in this Export);
//   dst_slot_complete   four-slot: Slot_p := s only after every word of
//                       buf(p, s) was stored (acked) in the same Export;
//   dst_no_held_write   no store request to a word of the buffer the
//                       consumer holds (confirmed lock / four-slot hold);
//   dst_slot_first      four-slot: Actual := b only after the Slot store that
//                       completes b was acked in the same Export, or b is
//                       WHOLE and Slot_pair(b) names it;
//   dst_no_actual_write three-buffer: no store to the buffer Actual names
//                       (the newest complete value);
//   dst_readback_needed three-buffer, WHOLE_LOAD = 0: Actual is loaded (read
//                       back) only while the producer cannot know it: before
//                       its first acked Actual store or read-back, or after
//                       an Actual store that was not acked;
//   dst_one_load        four-slot, or WHOLE_LOAD = 1: one acked control-word
//                       load per Export;
//   dst_new_once        the watched source value (carry_i: the slot's Import
//                       read it, falb_src) is published here at most once: a
//                       landed Actual store that changes Actual is a
//                       publication; and, four-slot, it is completed here at
//                       most once: a landed Slot store that changes its Slot
//                       byte is a completion (a four-slot consumer may read a
//                       complete value before it is published).  So a
//                       consumer never sees one value as New twice.
// With PROTO = 0 (the harness then returns free load data) only the access
// shapes are checked: dst_no_held_write, dst_no_actual_write,
// dst_readback_needed and dst_new_once need the consumer's control word.
// Outputs for covers and harness invariants: pub_o (an Actual store acked),
// held_o, act_o.
`default_nettype none

module falb_dst #(
    parameter AW    = 4,    // word-address bits of a board RAM
    parameter WW    = 2,    // bits of W (W = 1 .. 2**WW - 1, stride W + 1 <= 4)
    parameter BB    = 4,    // board bits of the bus address
    parameter PROTO = 1,    // 1: check the protocol rules; 0: the access shapes only (load data free)
    parameter WHOLE_LOAD = 0, // 1: both kinds load the whole control word once per Export (the controller); 0: three-buffer reads Actual back only when unknown (albatross_export)
    parameter BOARD = 1     // this channel's board
) (
    input  wire              clk_i,
    input  wire              rst_i,
    input  wire              slot_start_i,  // a slot begins: the Export's stores count from the next clock
    input  wire [AW-1:0]     base_i,        // held constant by the harness
    input  wire [WW-1:0]     words_i,       // W, held constant, >= 1
    input  wire              four_i,        // the channel is of the four-slot kind, held constant
    input  wire              cyc_i,
    input  wire              stb_i,
    input  wire              we_i,
    input  wire [BB+AW-1:0]  adr_i,
    input  wire [3:0]        sel_i,
    input  wire [31:0]       wdat_i,
    input  wire              ack_i,
    input  wire              land_i,        // a store without ack lands in this clock
    input  wire [1:0]        op_i,          // the consumer's action
    input  wire              carry_i,       // this slot carries the watched source value (falb_src)
    output wire [31:0]       ctrl_o,        // the control word (load data)
    output wire              hit_o,         // a request to this channel's board
    output wire              ctrl_hit_o,    // ... to its control word
    output wire              pub_o,         // an Actual store acked in this clock
    output wire [2:0]        held_o,        // the buffer the consumer holds (0: none)
    output wire [2:0]        act_o          // Actual
);
    localparam [BB-1:0] BRD = BOARD;

    reg  [2:0] act_q, rl_q, seen_q, l_q, held_q;
    reg  [1:0] slot_q;
    reg        conf_q, ann_q;              // three-buffer: lock confirmed; four-slot: announced
    reg        must_q;                     // four-slot: an announcement is due
    reg [15:0] done_q;                     // word k of buffer b stored in this Export: [4(b-1) + k]
    reg  [4:1] cmp_q;                      // four-slot: Slot store of buffer b acked in this Export
    reg        unk_q;                      // three-buffer: the producer's Actual copy may be unknown
    reg        ld_q;                       // four-slot: a control load acked in this Export
    reg  [1:0] news_q;                     // publications of the watched value (saturating)
    reg  [1:0] comps_q;                    // four-slot: completions of the watched value (saturating)
    reg  [4:1] whole_q;                    // four-slot: buffer b is WHOLE (dst_publish_complete)

    assign ctrl_o = {7'd0, slot_q[1], 7'd0, slot_q[0], 5'd0, rl_q, 5'd0, act_q};

    // ------------------------------------------------------------ the access
    wire          req   = cyc_i && stb_i;
    wire [AW-1:0] wadr  = adr_i[AW-1:0];
    assign hit_o        = req && adr_i[BB+AW-1:AW] == BRD;
    wire [AW:0]   off   = {1'b0, wadr} - {1'b0, base_i};       // negative: bit AW set
    wire [AW:0]   s     = {{(AW-WW+1){1'b0}}, words_i} + 1'b1;
    wire [2:0]    nbuf  = four_i ? 3'd4 : 3'd3;
    wire [AW+2:0] span  = {2'b00, s} * nbuf;                   // NB * S
    wire          ctrl  = off == {(AW+1){1'b0}};
    wire          inb   = !off[AW] && off != 0 && {2'b00, off} <= span;
    wire [AW:0]   o1    = off - 1'b1;
    wire [2:0]    b     = o1 < s ? 3'd1 : o1 < s + s ? 3'd2 : o1 < s + s + s ? 3'd3 : 3'd4;
    wire [AW:0]   k     = o1 - (b == 3'd1 ? 0 : b == 3'd2 ? s : b == 3'd3 ? s + s : s + s + s);
    wire [3:0]    kix   = {b[1:0] - 2'd1, k[1:0]};
    assign ctrl_hit_o   = hit_o && ctrl;
    wire          st    = hit_o && we_i;
    wire          lands = st && (ack_i || land_i) && !rst_i;
    wire [7:0]    byte0 = wdat_i[7:0];
    wire [7:0]    byte2 = wdat_i[23:16];
    wire [7:0]    byte3 = wdat_i[31:24];
    wire          st_act  = st && ctrl && sel_i == 4'b0001;
    wire          st_slot = st && ctrl && four_i && (sel_i == 4'b0100 || sel_i == 4'b1000);
    wire          slot_p  = sel_i[3];
    wire          slot_s  = slot_p ? byte3[0] : byte2[0];
    wire [2:0]    slot_b  = 3'd1 + {slot_p, 1'b0} + {2'b00, slot_s};
    assign pub_o        = st_act && ack_i;
    wire          ld_ctrl = hit_o && !we_i && ctrl;
    wire          publish = lands && st_act && byte0[2:0] != act_q;   // Actual changes: a publication
    wire          compl   = lands && st_slot && slot_s != slot_q[slot_p];  // four-slot: a Slot byte changes

    function full;                          // every word of buffer bb stored in this Export
        input [2:0]  bb;
        input [15:0] done;
        input [AW:0] ss;
        reg   [3:0]  want, got;
        begin
            want = ss >= 4 ? 4'hF : ss == 3 ? 4'h7 : ss == 2 ? 4'h3 : 4'h1;
            case (bb)
                3'd1:    got = done[3:0];
                3'd2:    got = done[7:4];
                3'd3:    got = done[11:8];
                default: got = done[15:12];
            endcase
            full = bb >= 3'd1 && bb <= 3'd4 && (got & want) == want;
        end
    endfunction
    function untouched;                     // no word of buffer bb stored in this Export
        input [2:0]  bb;
        input [15:0] done;
        case (bb)
            3'd1:    untouched = done[3:0] == 4'd0;
            3'd2:    untouched = done[7:4] == 4'd0;
            3'd3:    untouched = done[11:8] == 4'd0;
            default: untouched = done[15:12] == 4'd0;
        endcase
    endfunction

    // ------------------------------------------------------------ the consumer
    wire [2:0] am1  = seen_q - 3'd1;                                // four-slot pair(A) = am1[1]
    wire [2:0] b2   = 3'd1 + {am1[1], 1'b0} + {2'b00, slot_q[am1[1]]}; // buf(pair(A), Slot)
    assign held_o = four_i ? held_q : (conf_q ? rl_q : 3'd0);
    assign act_o  = act_q;

    (* anyconst *) reg [2:0] i_act, i_rl, i_seen;
    (* anyconst *) reg [1:0] i_slot;
    (* anyconst *) reg       i_conf;
    always @(posedge clk_i) begin
        if (rst_i) begin                    // the first clock: any valid control word
            act_q  <= i_act;
            rl_q   <= i_rl;
            slot_q <= four_i ? i_slot : 2'b00;
            seen_q <= i_seen;
            conf_q <= !four_i && i_conf;
            l_q    <= 3'd0;
            held_q <= 3'd0;
            must_q <= 1'b0;
            ann_q  <= 1'b0;
            done_q <= 16'd0;
            cmp_q  <= 4'd0;
            unk_q  <= 1'b1;
            ld_q   <= 1'b0;
            news_q <= 2'd0;
            comps_q <= 2'd0;
            whole_q <= 4'd0;
        end else begin
            if (four_i) begin
                case (op_i)
                    2'd1: if (!must_q && !ann_q) begin
                              seen_q <= act_q;
                              if (act_q == l_q) held_q <= l_q;
                              else begin held_q <= 3'd0; must_q <= 1'b1; end
                          end
                    2'd2: if (must_q) begin rl_q <= seen_q; must_q <= 1'b0; ann_q <= 1'b1; end
                    2'd3: if (ann_q) begin held_q <= b2; l_q <= b2; ann_q <= 1'b0; end
                    default: ;
                endcase
            end else begin
                case (op_i)
                    2'd1: begin seen_q <= act_q; if (act_q == rl_q) conf_q <= 1'b1; end
                    2'd2: begin rl_q <= seen_q; conf_q <= 1'b0; end
                    default: ;
                endcase
            end
            if (lands && st_act) act_q <= byte0[2:0];
            if (lands && st_slot) slot_q[slot_p] <= slot_s;
            if (slot_start_i) done_q <= 16'd0;
            else if (st && inb && ack_i) done_q[kix] <= 1'b1;
            if (slot_start_i) cmp_q <= 4'd0;
            else if (st_slot && ack_i) cmp_q[slot_b] <= 1'b1;
            if (slot_start_i) ld_q <= 1'b0;
            else if (ld_ctrl && ack_i) ld_q <= 1'b1;
            if (st_act && !ack_i) unk_q <= 1'b1;
            else if ((st_act || (ld_ctrl && sel_i[0])) && ack_i) unk_q <= 1'b0;
            if (publish && carry_i && news_q != 2'd3) news_q <= news_q + 2'd1;
            if (compl && carry_i && comps_q != 2'd3) comps_q <= comps_q + 2'd1;
            // WHOLE: set by a landed Slot store of a buffer stored whole in
            // this Export; cleared by any store request to a word of it.
            if (st && inb) whole_q[b] <= 1'b0;
            else if (lands && st_slot && full(slot_b, done_q, s)) whole_q[slot_b] <= 1'b1;
        end
    end

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    always @* begin
        assume(words_i != {WW{1'b0}});
        assume({1'b0, base_i} + span + 1'b1 <= (1 << AW));     // the channel fits the RAM (entry check)
        assume(i_act >= 3'd1 && i_act <= nbuf && i_rl >= 3'd1 && i_rl <= nbuf &&
               i_seen >= 3'd1 && i_seen <= nbuf);
    end
    wire valid_act = byte0[7:3] == 5'd0 && byte0[2:0] >= 3'd1 && byte0[2:0] <= nbuf;
    wire [7:0] sbyte = slot_p ? byte3 : byte2;
    // A four-slot late publication (Actual := b, b completed by an earlier
    // Export): b WHOLE and named by its Slot byte.  PROTO = 0: the loads
    // return free data, so the controller may take any buffer for complete;
    // only the shape is checked: no word of b stored in this Export.
    wire [2:0] am1b  = byte0[2:0] - 3'd1;                        // the Actual stored: {pair, slot}
    wire       late_ok = four_i && byte0[2:0] >= 3'd1 && byte0[2:0] <= 3'd4 &&
                         (PROTO == 0 ? untouched(byte0[2:0], done_q) : whole_q[byte0[2:0]] && slot_q[am1b[1]] == am1b[0]);
    always @* begin
        if (!init_q && !rst_i) begin
            dst_in_channel:       assert(!hit_o || ctrl || inb);
            dst_loads:            assert(!hit_o || we_i || ctrl);
            dst_ctrl_store:       assert(!(st && ctrl) || (st_act && valid_act) || (st_slot && sbyte[7:1] == 7'd0));
            dst_publish_complete: assert(!st_act || full(byte0[2:0], done_q, s) || late_ok);
            dst_slot_complete:    assert(!st_slot || full(slot_b, done_q, s));
            dst_no_held_write:    assert(PROTO == 0 || !(st && inb) || b != held_o);
            dst_slot_first:       assert(!(st_act && four_i) || cmp_q[byte0[2:0]] || late_ok);
            dst_no_actual_write:  assert(PROTO == 0 || !(st && inb && !four_i) || b != act_q);
            dst_readback_needed:  assert(PROTO == 0 || WHOLE_LOAD != 0 || !(ld_ctrl && !four_i && sel_i[0]) || unk_q);
            dst_one_load:         assert(!(ld_ctrl && (four_i || WHOLE_LOAD != 0)) || !ld_q);
            dst_new_once:         assert(PROTO == 0 || ((!(publish && carry_i) || news_q == 2'd0) &&
                                                        (!(compl && carry_i) || comps_q == 2'd0)));
        end
    end
`endif
endmodule

`default_nettype wire
