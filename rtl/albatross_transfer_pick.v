// albatross_transfer_pick -- the control-word decode of the transfer
// datapath (albatross_transfer): what a load of a control word (the
// source's or a destination's Actual, ReadLocked and Slot bytes at the
// contract's lane offsets) says, and the buffer picks made from it.
// Purely combinational, on the read data of the load (dat_i).
// Rules:
//   * A control byte is valid when it names a buffer: 1..3, four-slot 1..4.
//     0 is "not started" (a zeroed RAM: no error, a_zero_o/r_zero_o); any
//     other value is corrupt.  pair(x) = (x - 1) >> 1 for x = 1..4.
//   * Source (the Import): c = 1 + 2 pair(A) + Slot[pair(A)] of this
//     load; a_match_o: the load shows the copy rl_i again (four-slot: c = L;
//     three-buffer: A = the copy); pick_l_o (four-slot, the second load) is
//     L = 1 + 2 pair(ald_i) + Slot[pair(ald_i)], from the Actual stored.
//   * Destination (the Export, on its control-word load): three-buffer, the
//     last of 1..3 that is neither Actual nor ReadLocked (a byte that names
//     no buffer counts as none); four-slot, p = 1 - pair(ReadLocked) (not
//     started: p = 1; not valid: 1 - pair(Actual), or p = 1), s = 1 - Slot_p,
//     buffer 1 + 2p + s.
//   * Destination, four-slot: t_done_o, the Slot byte of pair(tried_i) names
//     tried_i's slot (tried_i 1..4: the buffer of an earlier Export's Slot
//     store whose Actual store may not have been made; 0 none: no match).
//     Only the producer writes the Slot bytes, and that Export chose the slot
//     the byte did not name: a match shows its Slot store landed.
`default_nettype none

module albatross_transfer_pick (
    input  wire [31:0] dat_i,          // the control word loaded
    input  wire        four_i,         // the four-slot kind
    input  wire [2:0]  ald_i,          // the source Actual loaded first (four-slot pick of L)
    input  wire [2:0]  rl_i,           // the ReadLocked copy / four-slot L (0 unknown)
    input  wire [2:0]  tried_i,        // destination: the buffer of its Slot / Actual store tried (0 none)
    output wire [2:0]  a_byte_o,       // the Actual byte's buffer bits
    output wire        a_valid_o,      // Actual names a buffer
    output wire        a_zero_o,       // Actual is 0 (not started)
    output wire        r_valid_o,      // ReadLocked names a buffer
    output wire        r_zero_o,       // ReadLocked is 0 (not started)
    output wire        a_match_o,      // source: the load shows the copy again (Old)
    output wire [2:0]  pick_l_o,       // source, four-slot: L from the second load
    output wire [2:0]  pick_o,         // destination: the buffer to write
    output wire        t_done_o        // destination, four-slot: the Slot byte names tried_i (its Slot store landed)
);

`include "albatross_contract.vh"

    localparam ACT_BIT = 8 * (ALB_CH_OFF_ACTUAL % ALB_CH_WORD_BYTES);
    localparam RL_BIT  = 8 * (ALB_CH_OFF_READLOCKED % ALB_CH_WORD_BYTES);
    localparam S0_BIT  = 8 * (ALB_CH_OFF_SLOT0 % ALB_CH_WORD_BYTES);
    localparam S1_BIT  = 8 * (ALB_CH_OFF_SLOT1 % ALB_CH_WORD_BYTES);
    localparam [7:0] NOT_STARTED = ALB_CH_NOT_STARTED;

    generate
        if (ALB_CH_OFF_ACTUAL / ALB_CH_WORD_BYTES != 0 || ALB_CH_OFF_READLOCKED / ALB_CH_WORD_BYTES != 0 ||
            ALB_CH_OFF_SLOT0 / ALB_CH_WORD_BYTES != 0 || ALB_CH_OFF_SLOT1 / ALB_CH_WORD_BYTES != 0 ||
            ALB_CH_OFF_BUFFERS != ALB_CH_WORD_BYTES || ALB_CH_WORD_BYTES != 4 || ALB_CH_BUFFER1 != 1 ||
            ALB_CH_BUFFER_LAST != 3 || ALB_CH_TAKEN_AT_WORDS != 1 || ALB_CH_NOT_STARTED != 0)
        begin : g_contract_check
            albatross_transfer_pick_contract_mismatch u_error ();
        end
    endgenerate

    // The control word just loaded.
    wire [7:0] a_byte   = dat_i[ACT_BIT +: 8];
    wire [7:0] r_byte   = dat_i[RL_BIT +: 8];
    wire       a_valid  = a_byte[7:3] == 5'd0 && a_byte[2:0] != 3'd0 && (four_i ? a_byte[2:0] <= 3'd4 : !a_byte[2]);
    wire       r_valid  = r_byte[7:3] == 5'd0 && r_byte[2:0] != 3'd0 && (four_i ? r_byte[2:0] <= 3'd4 : !r_byte[2]);
    // Not started (0, a zeroed RAM): no error.  Actual: nothing published
    // (Import: nothing new; Export: no buffer to avoid); ReadLocked: Buffer1.
    wire       a_zero   = a_byte == NOT_STARTED;
    wire       r_zero   = r_byte == NOT_STARTED;
    wire       a_pair   = a_byte[2] | (a_byte[1] & a_byte[0]);      // (x - 1) >> 1 for x = 1..4
    wire       r_pair   = r_byte[2] | (r_byte[1] & r_byte[0]);
    // Source, four-slot: c = 1 + 2 pair(A) + Slot[pair(A)] of this load equals
    // L (1..4 = 1 + 2p + s) exactly when pair(A) = p and Slot[p] = s, so the
    // match is decoded by L's value (a register): no adder, and no multiplexer
    // chosen by the loaded A, follows the load (L 0, unknown: no match).
    // pick_l: L from the Actual stored (the second load).
    wire       c_is_l   = (rl_i == 3'd1 && !a_pair && !dat_i[S0_BIT]) || (rl_i == 3'd2 && !a_pair && dat_i[S0_BIT]) ||
                          (rl_i == 3'd3 && a_pair && !dat_i[S1_BIT]) || (rl_i == 3'd4 && a_pair && dat_i[S1_BIT]);
    wire       p_ald    = ald_i[2] | (ald_i[1] & ald_i[0]);
    wire [2:0] pick_l   = {1'b0, p_ald, p_ald ? dat_i[S1_BIT] : dat_i[S0_BIT]} + 3'd1;
    wire       a_match  = four_i ? c_is_l : a_byte[2:0] == rl_i;
    // Destination pick.
    wire [1:0] r_lock   = r_valid ? r_byte[1:0] : 2'd0;
    wire [1:0] a_pub    = a_valid ? a_byte[1:0] : 2'd0;
    wire [1:0] pick3    = (a_pub != 2'd3 && r_lock != 2'd3) ? 2'd3 : (a_pub != 2'd2 && r_lock != 2'd2) ? 2'd2 : 2'd1;
    wire       pk_p     = r_valid ? !r_pair : r_zero ? 1'b1 : a_valid ? !a_pair : 1'b1;
    wire       pk_s     = !(pk_p ? dat_i[S1_BIT] : dat_i[S0_BIT]);
    wire [2:0] pick     = four_i ? {1'b0, pk_p, pk_s} + 3'd1 : {1'b0, pick3};
    // Destination, four-slot: Slot[pair(tried)] = slot(tried), decoded by
    // tried's value (a register) as c_is_l above.
    wire       t_done   = four_i && ((tried_i == 3'd1 && !dat_i[S0_BIT]) || (tried_i == 3'd2 && dat_i[S0_BIT]) ||
                                     (tried_i == 3'd3 && !dat_i[S1_BIT]) || (tried_i == 3'd4 && dat_i[S1_BIT]));

    assign a_byte_o  = a_byte[2:0];
    assign a_valid_o = a_valid;
    assign a_zero_o  = a_zero;
    assign r_valid_o = r_valid;
    assign r_zero_o  = r_zero;
    assign a_match_o = a_match;
    assign pick_l_o  = pick_l;
    assign pick_o    = pick;
    assign t_done_o  = t_done;

endmodule

`default_nettype wire
