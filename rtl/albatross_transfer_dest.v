// albatross_transfer_dest -- the per-destination registers of the transfer
// datapath (albatross_transfer): for each of the 4 destinations of an entry
// the buffer the Export picked for it and the buffer tried (of its failed
// Actual store; four-slot, of its Slot store); and the view of the current
// destination d_i (a multiplexer per field).
// Rules:
//   * start_i loads every destination's buffer tried from the state RAM
//     (st_tried_i; cleared if fresh_i: a new value has no failed store).
//   * Otherwise only destination d_i changes, on the enables of its events
//     (the transfer's state machine makes them): set_tried_i (its Actual
//     store failed, or its four-slot Slot store is on the bus: the buffer
//     tried is its picked buffer); clr_tried_i (clears
//     the buffer tried); set_buf_i (the picked buffer becomes pick_i).  When
//     several are high in one clock the later in this list wins.
//   * ld_buf_i (a fragment after a value's first) loads every
//     destination's picked buffer from st_buf_i (the first fragment's picks).
//   * Timing: registered, in the clock after the enables; reset clears the
//     buffers tried (the picks are data).
`default_nettype none

module albatross_transfer_dest (
    input  wire        clk_i,
    input  wire        rst_i,          // synchronous, active high
    input  wire        start_i,        // load all destinations from the state RAM
    input  wire        ld_buf_i,       // load the picked buffers from st_buf_i
    input  wire [11:0] st_buf_i,       // the picked buffers, d at [3d +: 3]
    input  wire [11:0] st_tried_i,     // buffers tried (failed Actual, four-slot Slot stores), d at [3d +: 3]
    input  wire        fresh_i,        // with start_i: no buffer tried
    input  wire [1:0]  d_i,            // the current destination
    input  wire        set_tried_i,    // d's buffer tried := its picked buffer
    input  wire        clr_tried_i,    // d: no buffer tried
    input  wire        set_buf_i,      // d's picked buffer := pick_i
    input  wire [2:0]  pick_i,
    output wire [2:0]  buf_d_o,        // d's picked buffer
    output wire [2:0]  tried_d_o,      // d's buffer tried (0 none)
    output wire [11:0] tried_o,        // the buffers tried, d at [3d +: 3]
    output wire [11:0] buf_o           // the picked buffers, d at [3d +: 3]
);

    reg  [11:0] buf_q, tried_q;
    wire [3:0]  d_bit = 4'b0001 << d_i;
    genvar      g;

    generate
        for (g = 0; g < 4; g = g + 1) begin : g_dest
            always @(posedge clk_i) begin
                if (rst_i) begin
                    tried_q[3*g +: 3]  <= 3'd0;
                end else if (start_i) begin
                    tried_q[3*g +: 3]  <= fresh_i ? 3'd0 : st_tried_i[3*g +: 3];
                    if (ld_buf_i) buf_q[3*g +: 3] <= st_buf_i[3*g +: 3];
                end else if (d_bit[g]) begin
                    if (set_tried_i) tried_q[3*g +: 3] <= buf_d_o;
                    if (clr_tried_i) tried_q[3*g +: 3] <= 3'd0;
                    if (set_buf_i) buf_q[3*g +: 3] <= pick_i;
                end
            end
        end
    endgenerate

    assign buf_d_o   = d_i[1] ? (d_i[0] ? buf_q[9 +: 3] : buf_q[6 +: 3]) : (d_i[0] ? buf_q[3 +: 3] : buf_q[0 +: 3]);
    assign tried_d_o = d_i[1] ? (d_i[0] ? tried_q[9 +: 3] : tried_q[6 +: 3]) : (d_i[0] ? tried_q[3 +: 3] : tried_q[0 +: 3]);
    assign tried_o   = tried_q;
    assign buf_o     = buf_q;

endmodule

`default_nettype wire
