// albatross_transfer_access -- the bus access of the transfer datapath
// (albatross_transfer) in its current state: address, board, write enable,
// byte lanes and write data.  Purely combinational; the state comes in as
// one strobe per access kind (at most one high; none: no access, the source
// side is addressed with offset 0).
// Rules:
//   * Word k of buffer b on a board RAM is at base + 1 + (b - 1) * S + k,
//     with S = W for the source (Import, buffer rl_i, 4 as 0) and S = W + 1
//     for a destination d (buffer buf_i, base d of dst_base_i): a
//     destination buffer holds the W value words then taken_at.  The
//     control accesses (Actual, ReadLocked, Slot bytes) are at base (the
//     control word); their byte lanes come from the contract offsets.
//   * Write data, one OR of masked terms: the ReadLocked store writes ald_i
//     into its lane; a word store writes word_i (TIME: slot_time_i); the
//     taken_at store writes taken_i (COPY) or slot_time_i (TIME, STATUS); the
//     four-slot Slot store writes bit s of buffer {p, s} into Slot p's lane;
//     the Actual store writes buf_i into the Actual lane.
//   * The four-slot source Actual load and every destination control load
//     take the whole control word (sel 4'hF; the destination load reads
//     Actual and ReadLocked together); word accesses take 4'hF.  The
//     destination control load is the access with no strobe of its own.
`default_nettype none

module albatross_transfer_access #(
    parameter ADDR_WIDTH = 10  // word-address bits of a board RAM
) (
    // the state (one strobe per access kind; dst_i: a destination access)
    input  wire                    dst_i,          // the access is to destination d_i (else the source)
    input  wire                    src_act_i,      // load the source's Actual (four-slot: control word)
    input  wire                    src_rl_i,       // store the source's ReadLocked
    input  wire                    src_word_i,     // load source word k
    input  wire                    dst_word_i,     // store word k - 1 to d
    input  wire                    dst_tkn_i,      // store taken_at to d
    input  wire                    dst_slot_i,     // four-slot: store d's Slot byte
    input  wire                    dst_fin_i,      // store d's Actual
    // the entry and the transfer's registers
    input  wire                    copy_i,         // kind COPY
    input  wire                    time_kind_i,    // kind TIME
    input  wire                    four_i,         // the four-slot kind
    input  wire [11:0]             words_i,        // W
    input  wire [11:0]             k_i,            // the word index
    input  wire [1:0]              d_i,            // the current destination
    input  wire [1:0]              rl_i,           // the source buffer (ReadLocked copy, 4 as 0)
    input  wire [2:0]              buf_i,          // d's picked buffer
    input  wire [2:0]              ald_i,          // the source Actual last loaded (ReadLocked store)
    input  wire [3:0]              src_board_i,
    input  wire [ADDR_WIDTH-1:0]   src_base_i,
    input  wire [15:0]             dst_board_i,    // d at [4d +: 4]
    input  wire [4*ADDR_WIDTH-1:0] dst_base_i,     // d at [d*ADDR_WIDTH +: ADDR_WIDTH]
    input  wire [31:0]             word_i,         // the word the destination stores write
    input  wire [31:0]             slot_time_i,    // TIME's value, TIME's and STATUS's taken_at
    input  wire [31:0]             taken_i,        // COPY's taken_at
    // the access
    output wire                    we_o,
    output wire [ADDR_WIDTH-1:0]   adr_o,
    output wire [3:0]              board_o,
    output wire [3:0]              sel_o,
    output wire [31:0]             dat_o
);

`include "albatross_contract.vh"

    localparam AW      = ADDR_WIDTH;
    localparam ACT_BIT = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam RL_BIT  = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam S0_BIT  = 8 * (ALB_CH_OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam S1_BIT  = 8 * (ALB_CH_OFF_SLOT1 % ALB_CH_WORD_BYTES);
    localparam [3:0] SEL_ACT = 4'b0001 << (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam [3:0] SEL_RL  = 4'b0001 << (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam [3:0] SEL_S0  = 4'b0001 << (ALB_CH_OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam [3:0] SEL_S1  = 4'b0001 << (ALB_CH_OFF_SLOT1 % ALB_CH_WORD_BYTES);

    wire          src    = !dst_i;
    wire          datacc = src_word_i || dst_word_i || dst_tkn_i;
    wire          t_val  = (dst_word_i && time_kind_i && !copy_i) || (dst_tkn_i && !copy_i);   // TIME's value, TIME's and STATUS's taken_at
    wire [AW-1:0] base_d = d_i[1] ? (d_i[0] ? dst_base_i[3*AW +: AW] : dst_base_i[2*AW +: AW])
                                  : (d_i[0] ? dst_base_i[AW +: AW] : dst_base_i[0 +: AW]);
    // Word k of buffer b: base + 1 + (b - 1) * S + k, S = W (source) or W + 1.
    // With b - 1 = 2 h + l and S = W + dst: (b - 1) * S = l W + h 2W + l dst
    // + 2 h dst, so the address is four wide terms (base, k, l W, h 2W; the
    // data accesses' offset: the others are 0 for a control access) and the
    // one-bit terms 1 (cin), l dst, h dst, h dst, which go in as the three
    // adders' carries in and bit 0 of 2W (free): three adders, no W + dst.
    wire [1:0]    b      = src ? rl_i : buf_i[1:0];   // 1..4 (4 as 0)
    wire [1:0]    bm1    = b - 2'd1;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [AW+11:0] w_wide = {{AW{1'b0}}, words_i};
    wire [AW+11:0] k_wide = {{AW{1'b0}}, k_i};
    /* verilator lint_on UNUSEDSIGNAL */
    wire          g_l    = datacc && bm1[0];
    wire          g_h    = datacc && bm1[1];
    wire          e_h    = g_h && dst_i;          // h dst
    wire [AW-1:0] base   = src ? src_base_i : base_d;
    wire [AW-1:0] lw     = {AW{g_l}} & w_wide[AW-1:0];                          // l W
    wire [AW-1:0] hw     = {{(AW-1){g_h}} & w_wide[AW-2:0], g_l && dst_i};      // h 2W + l dst
    // base + k + 1 (the carry in: word k of the source, or taken_at) beside
    // l W + h 2W + l dst + h dst, then their sum + h dst: two carry chains deep.
    wire          cin    = src_word_i || dst_tkn_i;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [AW:0]   base_k = {base, cin} + {{AW{datacc}} & k_wide[AW-1:0], cin};   // bit 0 (unused): makes the carry in
    wire [AW:0]   m      = {lw, e_h} + {hw, e_h};
    wire [AW:0]   sum    = {base_k[AW:1], e_h} + {m[AW:1], e_h};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [1:0]    dbm1   = buf_i[1:0] - 2'd1;         // four-slot: {p, s} of d's buffer

    assign we_o    = src_rl_i || dst_word_i || dst_tkn_i || dst_slot_i || dst_fin_i;
    assign adr_o   = sum[AW:1];
    assign board_o = src ? src_board_i : dst_board_i[4*d_i +: 4];
    assign sel_o   = src_act_i ? (four_i ? 4'hF : SEL_ACT) :
                     src_rl_i ? SEL_RL :
                     dst_fin_i ? SEL_ACT :
                     dst_slot_i ? (dbm1[1] ? SEL_S1 : SEL_S0) : 4'hF;
    assign dat_o   = ({32{src_rl_i}} & ({29'd0, ald_i} << RL_BIT)) |
                     ({32{dst_word_i && !t_val}} & word_i) | ({32{t_val}} & slot_time_i) | ({32{dst_tkn_i && copy_i}} & taken_i) |
                     ({32{dst_slot_i}} & ({31'd0, dbm1[0]} << (dbm1[1] ? S1_BIT : S0_BIT))) |
                     ({32{dst_fin_i}} & ({29'd0, buf_i} << ACT_BIT));

endmodule

`default_nettype wire
