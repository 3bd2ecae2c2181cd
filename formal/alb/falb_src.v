// falb_src -- property checker of one source channel of the ALBATROSS
// controller, watching the controller's system bus at the slave side
// (docs/verification.md "The controller on its own RTL").  Written for
// ALBATROSS in the style of wb2axip's property sets; reusable by any harness
// whose device under test is the consumer of a source channel (the
// controller, its transfer datapath, an Import engine).
//
// The channel (rtl/albatross_contract.toml; docs/four_slot.md) sits on board
// BOARD at word base_i with W = words_i value words (stride W): control word
// at base_i (byte 0 Actual, 1 ReadLocked, 2 Slot0, 3 Slot1), buffer b (1..3,
// four-slot 1..4) at base_i + 1 + (b - 1) W.  This module keeps the control
// word (the load data it returns on ctrl_o) and runs a free producer on it
// (op_i each clock, any timing):
//   three-buffer (paper figure 4): 1 = begin: load ReadLocked and pick the
//     buffer WB it writes (wb_i, any buffer that is neither Actual nor that
//     ReadLocked), 2 = publish: Actual := WB.  It WRITES WB from begin to
//     publish.
//   four-slot (docs/four_slot.md "Export"): 1 = begin: load the control word,
//     p = 1 - pair(ReadLocked), s = 1 - Slot_p, WB = buf(p, s); it writes WB
//     until 2 = complete: Slot_p := s; 3 = publish: Actual := WB.
// The initial control word is any valid one, the producer idle or writing
// (with a WB its rules allow).  A store lands when acked or (land_i) in any
// clock of its request without ack.
// Properties (labels):
//   src_in_channel  every access to BOARD lies in the channel;
//   src_store_rl    the only store is of the ReadLocked byte (sel selects
//                   that lane only), with a buffer 1..3 / 1..4;
//   src_no_torn     no load of a word of the buffer the producer writes;
//   src_wait_free   four-slot: at most two acked control-word loads in a
//                   slot (the Import is wait-free: no loop on Actual);
//   src_fresh       actuality (the paper's fourth proof point): every buffer
//                   word loaded (acked) in a slot is of a buffer holding the
//                   value the control word named when the slot began
//                   (slot_start_i; four-slot: 1 + 2 pair(Actual) +
//                   Slot[pair(Actual)], or a value completed and not yet
//                   published) or one completed since, not yet overwritten
//                   (fresh_q): an Import that starts after the producer
//                   completed a value returns it or a newer one, New or Old.
//                   A load of the buffer the producer is writing is
//                   src_no_torn's, not this one's.
// The watched value (for the destinations' dst_new_once): the first
// publication (four-slot: completion) with watch_i; carry_o marks an acked
// load of a word of the buffer that holds it (until the producer begins to
// overwrite that buffer).
// With PROTO = 0 (the harness then returns free load data) src_no_torn and
// src_fresh, which need the producer's control word, are not checked.
// Outputs for covers: rl_store_o (a ReadLocked store acked), word_load_o (a
// buffer word load acked).
`default_nettype none

module falb_src #(
    parameter AW    = 4,    // word-address bits of a board RAM
    parameter WW    = 2,    // bits of W
    parameter BB    = 4,    // board bits of the bus address
    parameter PROTO = 1,    // 1: check the protocol rules; 0: the access shapes only (load data free)
    parameter BOARD = 0     // this channel's board
) (
    input  wire              clk_i,
    input  wire              rst_i,
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
    input  wire [1:0]        op_i,          // the producer's action
    input  wire [2:0]        wb_i,          // three-buffer: the buffer a begin picks
    input  wire              slot_start_i,  // a slot begins (for src_wait_free)
    input  wire              watch_i,       // watch the value this publication (four-slot: completion) writes
    output wire              carry_o,       // a word of the watched value is loaded (acked)
    output wire [31:0]       ctrl_o,        // the control word (load data)
    output wire              hit_o,         // a request to this channel's board
    output wire              rl_store_o,
    output wire              word_load_o
);
    localparam [BB-1:0] BRD = BOARD;

    reg  [2:0] act_q, rl_q, wb_q;
    reg  [1:0] slot_q;
    reg        busy_q, comp_q;
    reg  [4:1] hold_q;                     // buffer b holds the watched value
    reg        wset_q;                     // the watched value is chosen
    reg  [1:0] nld_q;                      // four-slot: control loads acked in this slot
    assign ctrl_o = {7'd0, slot_q[1], 7'd0, slot_q[0], 5'd0, rl_q, 5'd0, act_q};

    wire          req   = cyc_i && stb_i;
    wire [AW-1:0] wadr  = adr_i[AW-1:0];
    assign hit_o        = req && adr_i[BB+AW-1:AW] == BRD;
    wire [AW:0]   off   = {1'b0, wadr} - {1'b0, base_i};
    wire [AW:0]   w     = {{(AW-WW+1){1'b0}}, words_i};
    wire [2:0]    nbuf  = four_i ? 3'd4 : 3'd3;
    wire [AW+2:0] span  = {2'b00, w} * nbuf;
    wire          ctrl  = off == {(AW+1){1'b0}};
    wire          inb   = !off[AW] && off != 0 && {2'b00, off} <= span;
    wire [AW:0]   o1    = off - 1'b1;
    wire [2:0]    b     = o1 < w ? 3'd1 : o1 < w + w ? 3'd2 : o1 < w + w + w ? 3'd3 : 3'd4;
    wire          st    = hit_o && we_i;
    wire          lands = st && (ack_i || land_i) && !rst_i;
    wire [7:0]    byte1 = wdat_i[15:8];
    assign rl_store_o  = st && ctrl && ack_i;
    assign word_load_o = hit_o && !we_i && inb && ack_i;
    assign carry_o     = word_load_o && hold_q[b];
    wire   ld_ctrl     = hit_o && !we_i && ctrl;

    // four-slot begin: the pair other than ReadLocked's, the slot not completed last
    wire       fp  = rl_q == 3'd1 || rl_q == 3'd2;                  // 1 - pair(ReadLocked)
    wire       fs  = !slot_q[fp];
    wire [2:0] fwb = 3'd1 + {fp, 1'b0} + {2'b00, fs};

    wire [2:0] wm1 = wb_q - 3'd1;                                   // WB = buf(p, s): p = wm1[1], s = wm1[0]
    (* anyconst *) reg [2:0] i_act, i_rl, i_wb;
    (* anyconst *) reg [1:0] i_slot;
    (* anyconst *) reg       i_busy;
    wire       ip  = i_rl == 3'd1 || i_rl == 3'd2;                  // four-slot: pair 1 - pair(i_rl)
    wire [2:0] iwb = 3'd1 + {ip, 1'b0} + {2'b00, !i_slot[ip]};
    always @(posedge clk_i) begin
        if (rst_i) begin
            act_q  <= i_act;
            rl_q   <= i_rl;
            slot_q <= four_i ? i_slot : 2'b00;
            busy_q <= i_busy;
            wb_q   <= four_i ? iwb : i_wb;
            comp_q <= 1'b0;
            hold_q <= 4'd0;
            wset_q <= 1'b0;
            nld_q  <= 2'd0;
        end else begin
            if (slot_start_i) nld_q <= 2'd0;
            else if (ld_ctrl && ack_i && nld_q != 2'd3) nld_q <= nld_q + 2'd1;
            // the watched value: chosen at a publication (four-slot: completion), gone when overwritten
            if (op_i == 2'd1 && !busy_q) hold_q[four_i ? fwb : wb_i] <= 1'b0;
            if (op_i == 2'd2 && busy_q && !comp_q && watch_i && !wset_q) begin
                hold_q[wb_q] <= 1'b1;
                wset_q       <= 1'b1;
            end
            case (op_i)
                2'd1: if (!busy_q) begin
                          busy_q <= 1'b1;
                          comp_q <= 1'b0;
                          wb_q   <= four_i ? fwb : wb_i;
                      end
                2'd2: if (busy_q) begin
                          if (four_i) begin
                              if (!comp_q) begin slot_q[wm1[1]] <= wm1[0]; comp_q <= 1'b1; end
                          end else begin
                              act_q <= wb_q; busy_q <= 1'b0;
                          end
                      end
                2'd3: if (four_i && busy_q && comp_q) begin act_q <= wb_q; busy_q <= 1'b0; end
                default: ;
            endcase
            if (lands && ctrl && sel_i[1]) rl_q <= byte1[2:0];
        end
    end
    wire writing = busy_q && !comp_q;

    // Freshness: fresh_q[b], buffer b holds the value named at the slot's
    // start or one completed since (a begin takes its buffer out).  Before
    // the first slot every buffer counts.
    wire       cp   = act_q == 3'd3 || act_q == 3'd4;               // pair(Actual)
    wire [2:0] cur  = four_i ? 3'd1 + {cp, 1'b0} + {2'b00, slot_q[cp]} : act_q;
    wire [4:1] pend = four_i && busy_q && comp_q ? onehot(wb_q) : 4'd0;
    wire [4:1] f_in = slot_start_i ? onehot(cur) | pend : fresh_q;
    wire [4:1] f_cm = op_i == 2'd2 && busy_q && !comp_q ? onehot(wb_q) : 4'd0;      // completes WB
    wire [4:1] f_bg = op_i == 2'd1 && !busy_q ? onehot(four_i ? fwb : wb_i) : 4'd0; // begins to write
    reg  [4:1] fresh_q;
    always @(posedge clk_i)
        if (rst_i) fresh_q <= 4'hF;
        else fresh_q <= (f_in | f_cm) & ~f_bg;
    function [4:1] onehot;
        input [2:0] x;
        onehot = {x == 3'd4, x == 3'd3, x == 3'd2, x == 3'd1};
    endfunction

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;
    always @* begin
        assume(words_i != {WW{1'b0}});
        assume({1'b0, base_i} + span + 1'b1 <= (1 << AW));
        assume(i_act >= 3'd1 && i_act <= nbuf && i_rl >= 3'd1 && i_rl <= nbuf);
        if (!four_i) assume(i_wb >= 3'd1 && i_wb <= 3'd3 && i_wb != i_act && i_wb != i_rl);
        if (!four_i && op_i == 2'd1 && !busy_q && !rst_i)
            assume(wb_i >= 3'd1 && wb_i <= 3'd3 && wb_i != act_q && wb_i != rl_q);
    end
    always @* begin
        if (!init_q && !rst_i) begin
            src_in_channel: assert(!hit_o || ctrl || inb);
            src_store_rl:   assert(!st || (ctrl && sel_i == 4'b0010 && byte1[7:3] == 5'd0 &&
                                           byte1[2:0] >= 3'd1 && byte1[2:0] <= nbuf));
            src_no_torn:    assert(PROTO == 0 || !(hit_o && !we_i && inb && writing && b == wb_q));
            src_wait_free:  assert(!(four_i && ld_ctrl) || nld_q < 2'd2);
            src_fresh:      assert(PROTO == 0 || !(word_load_o && !fresh_q[b] && !(writing && b == wb_q)));
        end
    end
`endif
endmodule

`default_nettype wire
