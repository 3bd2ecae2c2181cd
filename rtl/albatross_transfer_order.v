// albatross_transfer_order -- the order of the destinations of the transfer
// datapath (albatross_transfer): which destination its next access goes
// to.  Purely combinational.
// Rules:
//   * The destinations are served in index order.  need_q_i holds those
//     still in the value (in need) in this clock, d_i the current one;
//     leave_i: d leaves in this clock (dropped, its store landed, published
//     by S_DST_PUB); need_m_o is need_q_i without d when it leaves.
//   * next_d_o: the lowest destination above d_i in need_q_i (has_next_o:
//     there is one); first_d_o: the lowest in need_m_o (the next word's
//     first store, taken_at, Slot, Actual); first_in_o: the lowest in a
//     starting need (start_need_i: an Export's first control load; 3 when
//     none of 0..2 is in it).
//   * left_any_o = need_m_o != 0, written so that the read data (through
//     leave_i) meets one gate, not a mask and a 4-input OR: others in need,
//     or d in need and staying.
`default_nettype none

module albatross_transfer_order (
    input  wire [3:0] need_q_i,        // the destinations in need
    input  wire [1:0] d_i,             // the current destination
    input  wire       leave_i,         // d leaves need in this clock
    input  wire [2:0] start_need_i,    // the need an Export starts with (destinations 0..2; none: 3)
    output wire [3:0] need_m_o,        // need_q_i without d if it leaves
    output wire       left_any_o,      // need_m_o != 0
    output wire       has_next_o,      // a destination above d in need
    output wire [1:0] next_d_o,        // the lowest destination above d in need
    output wire [1:0] first_d_o,       // the lowest destination in need_m_o
    output wire [1:0] first_in_o       // the lowest destination in start_need_i
);

    wire [3:0] d_bit  = 4'b0001 << d_i;
    wire [3:0] need_m = need_q_i & ~(leave_i ? d_bit : 4'd0);
    wire [3:0] above  = need_q_i & ~((d_bit << 1) - 4'd1);

    assign need_m_o   = need_m;
    assign left_any_o = (|(need_q_i & ~d_bit)) || ((|(need_q_i & d_bit)) && !leave_i);
    assign has_next_o = above != 4'd0;
    assign next_d_o   = above[0] ? 2'd0 : above[1] ? 2'd1 : above[2] ? 2'd2 : 2'd3;
    assign first_d_o  = need_m[0] ? 2'd0 : need_m[1] ? 2'd1 : need_m[2] ? 2'd2 : 2'd3;
    assign first_in_o = start_need_i[0] ? 2'd0 : start_need_i[1] ? 2'd1 : start_need_i[2] ? 2'd2 : 2'd3;

endmodule

`default_nettype wire
