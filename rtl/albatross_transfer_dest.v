// albatross_transfer_dest -- the per-destination registers of the transfer
// datapath (albatross_transfer_fsm): for each of the 4 destinations of an
// entry its buffer, the one the Export picked for it, which is also its
// buffer tried (that of its Actual store, which may have landed; four-slot,
// of its Slot store); and the view of the current destination d_i (a
// multiplexer).
// Rules:
//   * start_i loads every destination's buffer from the state RAM
//     (st_tried_i: the buffer of a store of the value made before, or the
//     buffer picked by the value's first fragment; cleared if fresh_i: a new
//     value has no store and no pick).
//   * Otherwise only destination d_i changes, on the enables of its events
//     (the transfer's state machine makes them): set_pick_i (its control
//     load picked pick_i); clr_i (its Actual store is answered: nothing
//     tried).
//   * One register serves as the picked buffer and the buffer tried: from
//     its control load to its Actual store's answer a destination's stores
//     go to the buffer picked, and a store it tried (Actual, four-slot Slot)
//     is to that buffer.  A buffer tried that no store reached is harmless:
//     the next control load finds it named neither by Actual nor (four-slot)
//     by its Slot byte, as only those stores could make it so.
//   * Timing: registered, in the clock after the enables; reset clears the
//     buffers.
`default_nettype none

module albatross_transfer_dest (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        start_i,        // load all destinations from the state RAM
    input  wire [11:0] st_tried_i,     // the buffers tried or picked, d at [3d +: 3]
    input  wire        fresh_i,        // with start_i: no buffer
    input  wire [1:0]  d_i,            // the current destination
    input  wire        set_pick_i,     // d's buffer := pick_i
    input  wire        clr_i,          // d: no buffer tried
    input  wire [2:0]  pick_i,
    output wire [2:0]  tried_d_o,      // d's buffer (picked, tried; 0 none)
    output wire [11:0] tried_o         // the buffers, d at [3d +: 3]
);

    reg  [11:0] tried_q;
    wire [3:0]  d_bit = 4'b0001 << d_i;
    genvar      g;

    generate
        for (g = 0; g < 4; g = g + 1) begin : g_dest
            always @(posedge clk_i) begin
                if (rst_i) tried_q[3*g +: 3] <= 3'd0;
                else if (start_i) tried_q[3*g +: 3] <= fresh_i ? 3'd0 : st_tried_i[3*g +: 3];
                else if (d_bit[g]) begin
                    if (clr_i) tried_q[3*g +: 3] <= 3'd0;
                    if (set_pick_i) tried_q[3*g +: 3] <= pick_i;
                end
            end
        end
    endgenerate

    assign tried_d_o = d_i[1] ? (d_i[0] ? tried_q[9 +: 3] : tried_q[6 +: 3]) : (d_i[0] ? tried_q[3 +: 3] : tried_q[0 +: 3]);
    assign tried_o   = tried_q;

endmodule

`default_nettype wire
