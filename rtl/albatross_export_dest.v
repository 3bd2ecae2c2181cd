// albatross_export_dest -- the Export engine's per-destination datapath
// (albatross_export): combinational, from the engine's registers and the
// word just loaded.  It holds no state; albatross_export owns every register
// and the order of the steps.
// Rules:
//   * Current destination: d_i selects its fields (base, picked buffer, Actual
//     copy, tried buffer) from the DESTS-wide vectors; an unknown copy reads
//     as 0 (excludes no buffer).  d_bit_o / d_mask3_o are d_i as a mask over
//     1-bit and 3-bit fields (a part-select at 3*d would be a barrel shifter).
//   * Order: destinations are visited in index order.  leave_o: d_i leaves
//     the Export in this clock, dropped (drop_i) or found published by the
//     read-back (landed_o); need_o is need_i without d_i then.  next_o is the
//     lowest destination above d_i in need_i (has_next_o), first_o the lowest
//     in need_o; first_in_o the lowest in start_need_i (any_in_o: there is
//     one), with its start_known_i bit (known_in_o).
//   * Landed: a load of d's control word (read_act_i) whose Actual names
//     tried_i's buffer of d (not 0) shows that the failed Actual store of the
//     previous Export landed.
//   * Control bytes (dat_i): Actual and ReadLocked name a buffer when they
//     are 1..3, four-slot 1..4 (act_valid_o, rl_valid_o).  Pick, three-buffer
//     (figure 4's For loop): the last of Buffer1..3 that is neither d's
//     Actual copy nor ReadLocked (a ReadLocked naming no buffer locks none).
//     Four-slot: p = 1 - pair(ReadLocked) (ReadLocked naming no buffer:
//     1 - pair(Actual), neither: 1), s = 1 - Slot_p, the buffer 1 + 2p + s,
//     pair(x) = (x - 1) >> 1.
//   * Address (adr_o, word address): ctrl_i, the control word at base +
//     CTRL_WORD; else word k of d's buffer b at base + BUF_WORD + (b - 1) * S
//     + k, S = W + TAKEN_AT (no multiplier: (b - 1) * S is 0, S, 2S or 3S).
//     k_i is k + 1 for a value word; taken_i selects the taken_at word (k = W).
`default_nettype none

module albatross_export_dest #(
    parameter ADDR_WIDTH  = 10, // word-address bits of the port
    parameter WORDS_WIDTH = 12, // bits of words_i, k_i
    parameter TAKEN_AT    = 0,  // 1: taken_at stored after the value (stride W + 1)
    parameter DESTS       = 1   // destination channels, 1..4
) (
    // the engine's registers
    input  wire [1:0]                  d_i,            // current destination
    input  wire [DESTS-1:0]            need_i,         // destinations still taking part
    input  wire [DESTS*ADDR_WIDTH-1:0] base_i,         // d at [d*ADDR_WIDTH +: ADDR_WIDTH]
    input  wire [3*DESTS-1:0]          buf_i,          // picked buffers, d at [3d +: 3]
    input  wire [DESTS-1:0]            known_i,        // Actual copy known, ...
    input  wire [2*DESTS-1:0]          act_i,          // ... and its buffer, d at [2d +: 2]
    input  wire [3*DESTS-1:0]          tried_i,        // buffer of d's failed Actual store (0: none)
    input  wire                        four_i,         // four-slot destinations
    input  wire [WORDS_WIDTH-1:0]      words_i,        // W
    input  wire [WORDS_WIDTH-1:0]      k_i,            // value word k stored now: k + 1
    // this clock
    input  wire                        drop_i,         // d is dropped now
    input  wire                        read_act_i,     // acked load of d's control word (Actual read back)
    input  wire                        ctrl_i,         // the access is to the control word
    input  wire                        taken_i,        // the access stores taken_at
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [31:0]                 dat_i,          // the word loaded (only the control bytes are read)
    /* verilator lint_on UNUSEDSIGNAL */
    input  wire [DESTS-1:0]            start_need_i,   // at start: the destinations named
    input  wire [DESTS-1:0]            start_known_i,  // ... and their Actual copies known
    // the current destination
    output wire [DESTS-1:0]            d_bit_o,
    output wire [3*DESTS-1:0]          d_mask3_o,
    output wire [2:0]                  buf_o,          // its picked buffer
    output wire [ADDR_WIDTH-1:0]       adr_o,          // address of the access
    output wire                        landed_o,
    output wire                        leave_o,
    // order
    output wire [DESTS-1:0]            need_o,         // need_i without d_i if it leaves
    output wire                        has_next_o,
    output wire [1:0]                  next_o,
    output wire                        known_next_o,   // next_o's Actual copy is known
    output wire [1:0]                  first_o,
    output wire                        any_in_o,
    output wire [1:0]                  first_in_o,
    output wire                        known_in_o,
    // the control word loaded
    output wire                        act_valid_o,
    output wire [1:0]                  act_buf_o,      // Actual's low bits (three-buffer: the buffer)
    output wire                        rl_valid_o,
    output wire [2:0]                  pick_o          // the buffer picked for d
);

`include "albatross_contract.vh"

    localparam integer          CTRL_WORD_I = ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES;
    localparam integer          BUF_WORD_I  = ALB_CH_OFF_BUFFERS / ALB_CH_WORD_BYTES;
    localparam [ADDR_WIDTH-1:0] CTRL_WORD   = CTRL_WORD_I[ADDR_WIDTH-1:0];
    localparam [ADDR_WIDTH-1:0] BUF_WORD    = BUF_WORD_I[ADDR_WIDTH-1:0];
    localparam                  ACT_BIT     = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam                  RL_BIT      = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [1:0]            BUFFER1     = ALB_CH_BUFFER1[1:0];
    localparam [1:0]            BUFFER2     = BUFFER1 + 2'd1;
    localparam [1:0]            BUFFER3     = ALB_CH_BUFFER_LAST[1:0];
    localparam integer          TAKEN_WORDS = TAKEN_AT ? ALB_CH_TAKEN_AT_WORDS : 0;
    localparam                  SLOT0_BIT   = 8 * (ALB_CH_OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam                  SLOT1_BIT   = 8 * (ALB_CH_OFF_SLOT1 % ALB_CH_WORD_BYTES);

    wire [DESTS-1:0] d_bit0 = {{(DESTS-1){1'b0}}, 1'b1} << d_i;

    // The current destination's fields.
    reg [ADDR_WIDTH-1:0] base_d;
    reg [2:0]            buf_d;
    reg [1:0]            copy_d;               // its Actual copy, 0 when unknown
    reg [2:0]            tried_d;              // its tried buffer
    reg                  known_d;
    reg [DESTS-1:0]      need_m;               // need_i without d_i if it leaves now
    reg                  has_next;             // a destination after d_i takes part
    reg [1:0]            next_d;
    reg [1:0]            first_d;              // the first destination that takes part
    reg [DESTS-1:0]      d_bit;                // d_i as a mask
    reg                  known_next;           // next_d's Actual copy is known
    reg                  any_in;               // at start: start_need_i names a destination,
    reg [1:0]            first_in;             // the first one,
    reg                  known_in;             // and its Actual copy is known
    integer i;
    always @* begin
        base_d   = base_i[0 +: ADDR_WIDTH];
        buf_d    = buf_i[2:0];
        copy_d   = act_i[1:0];
        known_d  = known_i[0];
        tried_d  = tried_i[2:0];
        need_m   = need_i & ~(leave_o ? d_bit0 : {DESTS{1'b0}});
        has_next = 1'b0;
        next_d   = 2'd0;
        first_d  = 2'd0;
        known_next = 1'b0;
        d_bit    = {DESTS{1'b0}};
        any_in   = |start_need_i;
        first_in = 2'd0;
        known_in = start_known_i[0];
        for (i = DESTS - 1; i >= 0; i = i - 1) begin
            if (d_i == i[1:0]) begin
                d_bit[i] = 1'b1;
                base_d  = base_i[i*ADDR_WIDTH +: ADDR_WIDTH];
                buf_d   = buf_i[3*i +: 3];
                copy_d  = act_i[2*i +: 2];
                tried_d = tried_i[3*i +: 3];
                known_d = known_i[i];
            end
            if (need_i[i] && i[1:0] > d_i) begin
                has_next   = 1'b1;
                next_d     = i[1:0];
                known_next = known_i[i];
            end
            if (need_m[i]) first_d = i[1:0];
            if (start_need_i[i]) begin
                first_in = i[1:0];
                known_in = start_known_i[i];
            end
        end
        if (!known_d) copy_d = 2'd0;
    end

    genvar g;
    generate
        for (g = 0; g < DESTS; g = g + 1) begin : g_mask3
            assign d_mask3_o[3*g +: 3] = {3{d_bit[g]}};
        end
    endgenerate

    wire [7:0] act_byte  = dat_i[ACT_BIT +: 8];
    wire [7:0] rl_byte   = dat_i[RL_BIT +: 8];
    // A control byte names a buffer: 1..3, four-slot 1..4.
    wire       act_valid = act_byte[7:3] == 5'd0 && act_byte[2:0] != 3'd0 &&
                           (four_i ? act_byte[2:0] <= 3'd4 : !act_byte[2]);
    wire       rl_valid  = rl_byte[7:3] == 5'd0 && rl_byte[2:0] != 3'd0 &&
                           (four_i ? rl_byte[2:0] <= 3'd4 : !rl_byte[2]);
    wire [1:0] rl_lock   = rl_valid ? rl_byte[1:0] : 2'd0;
    // Figure 4: the last of Buffer1..3 that is neither Actual nor ReadLocked.
    wire [1:0] pick3     = (copy_d != BUFFER3 && rl_lock != BUFFER3) ? BUFFER3 :
                           (copy_d != BUFFER2 && rl_lock != BUFFER2) ? BUFFER2 : BUFFER1;
    // Four-slot: p = 1 - pair(ReadLocked) (else 1 - pair(Actual)), s = 1 - Slot_p,
    // the buffer 1 + 2p + s; pair(x) = (x - 1) >> 1 for x = 1..4.
    wire       rl_pair   = rl_byte[2] | (rl_byte[1] & rl_byte[0]);
    wire       act_pair  = act_byte[2] | (act_byte[1] & act_byte[0]);
    wire       pick_p    = rl_valid ? !rl_pair : act_valid ? !act_pair : 1'b1;
    wire       pick_s    = !(pick_p ? dat_i[SLOT1_BIT] : dat_i[SLOT0_BIT]);
    wire [2:0] pick4     = {1'b0, pick_p, pick_s} + 3'd1;
    assign landed_o = read_act_i && act_valid && act_byte[2:0] == tried_d && tried_d != 3'd0;
    assign leave_o  = drop_i || landed_o;

    // Address: word k of d's buffer is stored when k_i = k + 1, taken_at (word
    // W) at S - 1 = W: the -1 goes into the constant.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [ADDR_WIDTH+WORDS_WIDTH-1:0] w_wide = {{ADDR_WIDTH{1'b0}}, words_i};
    wire [ADDR_WIDTH+WORDS_WIDTH-1:0] k_wide = {{ADDR_WIDTH{1'b0}}, k_i};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [ADDR_WIDTH-1:0] w_ext   = w_wide[ADDR_WIDTH-1:0];
    wire [ADDR_WIDTH-1:0] stride  = w_ext + TAKEN_WORDS[ADDR_WIDTH-1:0];
    wire [ADDR_WIDTH-1:0] buf_off = buf_d == 3'd1 ? {ADDR_WIDTH{1'b0}} : buf_d == 3'd2 ? stride :
                                    buf_d == 3'd3 ? (stride << 1) : (stride << 1) + stride;
    wire [ADDR_WIDTH-1:0] word_k1 = taken_i ? stride : k_wide[ADDR_WIDTH-1:0];  // k + 1
    assign adr_o = base_d + (ctrl_i ? CTRL_WORD : BUF_WORD - 1'b1 + buf_off + word_k1);

    assign d_bit_o      = d_bit;
    assign buf_o        = buf_d;
    assign need_o       = need_m;
    assign has_next_o   = has_next;
    assign next_o       = next_d;
    assign known_next_o = known_next;
    assign first_o      = first_d;
    assign any_in_o     = any_in;
    assign first_in_o   = first_in;
    assign known_in_o   = known_in;
    assign act_valid_o  = act_valid;
    assign act_buf_o    = act_byte[1:0];
    assign rl_valid_o   = rl_valid;
    assign pick_o       = four_i ? pick4 : {1'b0, pick3};

endmodule

`default_nettype wire
