// falb_slot -- property checker of the ALBATROSS controller's slot timing,
// deadline, retries and drop rule, watching its system bus (Wishbone B4
// classic) and the two slot signals of its sequencer (docs/verification.md
// "The controller on its own RTL").  Reusable by any harness whose device
// under test runs transfers in slots (the controller, its transfer
// datapath).
// The slot signals are the sequencer's contract (rtl/albatross_sequencer.v,
// proved separately by formal/sequencer): go_i is high in the clock before a
// slot's first access may be on the bus (S + FETCH_CYCLES - 1); may_i
// (may_access) is high in a clock c when an access put on the bus in c + 1
// ends before the slot's deadline even if it times out.
// An access is a request (cyc & stb) from the clock it begins to the clock of
// its ack or err, or to its last clock when the master withdraws it after
// TIMEOUT clocks without an answer.  A failed access is one answered with err
// or withdrawn.  A destination is one of the ND boards on dst_board_i; K =
// drop_run_i, read as 2 below 2 (ROM H2).  The run of a destination is its
// failed accesses since the last ack of an access at it in this slot.
// Properties (labels):
//   slot_first     in the clock after go_i (with may_i), an access is on the bus;
//   slot_gated     an access begins only in a clock after one with may_i high
//                  (so, with the sequencer's may_access, none runs past its
//                  deadline);
//   slot_timeout   a request lasts at most TIMEOUT clocks;
//   retry_gap      the clock after a failed access has no request;
//   retry_same     after a failed access, with may_i high in that gap clock,
//                  the next clock repeats the access (we, address, sel, store
//                  data) unless it was a destination's K-th failure in a row;
//   drop_k         a destination whose run reached K gets no access for the
//                  rest of the slot.
// So a destination is dropped only after K failures in a row of one access
// (before that each failure is retried at once) and stays dropped.
// Outputs for covers: fail_o (a failed access ended in the last clock),
// retry_o (a retry begins), dropped_o (per destination).
`default_nettype none

module falb_slot #(
    parameter AW      = 8,   // bits of the bus address (board and word)
    parameter BB      = 4,   // board bits (the high bits of the address)
    parameter ND      = 2,   // destination boards watched, 1..4
    parameter TIMEOUT = 3    // the controller's TIMEOUT
) (
    input  wire             clk_i,
    input  wire             rst_i,
    input  wire             go_i,
    input  wire             may_i,
    input  wire [7:0]       drop_run_i,
    input  wire [ND*BB-1:0] dst_board_i,
    input  wire             cyc_i,
    input  wire             stb_i,
    input  wire             we_i,
    input  wire [AW-1:0]    adr_i,
    input  wire [3:0]       sel_i,
    input  wire [31:0]      wdat_i,
    input  wire             ack_i,
    input  wire             err_i,
    output wire             fail_o,
    output wire             retry_o,
    output wire [ND-1:0]    dropped_o
);
    wire       req  = cyc_i && stb_i;
    wire [7:0] k    = drop_run_i < 8'd2 ? 8'd2 : drop_run_i;

    reg          pend_q, errd_q, due_q, go_q, may_q, init_q = 1'b1;
    reg  [5:0]   cnt_q;
    reg          l_we;
    reg [AW-1:0] l_adr;
    reg  [3:0]   l_sel;
    reg [31:0]   l_dat;
    reg  [7:0]   run_q [0:ND-1];
    reg [ND-1:0] drop_q;
    wire         cont  = pend_q && req;
    wire         begin_ = req && !cont;
    assign fail_o  = errd_q || (pend_q && !req);
    wire [BB-1:0] l_brd = l_adr[AW-1:AW-BB];
    wire [BB-1:0] brd   = adr_i[AW-1:AW-BB];
    reg  [ND-1:0] l_dst, c_dst;
    integer d, e;
    always @* begin
        for (d = 0; d < ND; d = d + 1) begin
            l_dst[d] = l_brd == dst_board_i[BB*d +: BB];
            c_dst[d] = brd == dst_board_i[BB*d +: BB];
        end
    end
    // the failed access was a destination's K-th failure in a row
    reg kth;
    always @* begin
        kth = 1'b0;
        for (d = 0; d < ND; d = d + 1)
            if (l_dst[d] && run_q[d] + 8'd1 >= k) kth = 1'b1;
    end
    assign retry_o   = begin_ && due_q;
    assign dropped_o = drop_q;

    always @(posedge clk_i) begin
        init_q <= 1'b0;
        go_q   <= go_i;
        may_q  <= may_i;
        pend_q <= req && !ack_i && !err_i && !rst_i;
        errd_q <= req && err_i && !rst_i;
        cnt_q  <= (req && !ack_i && !err_i) ? (cont ? cnt_q + 6'd1 : 6'd1) : 6'd0;
        if (req) begin
            l_we  <= we_i;
            l_adr <= adr_i;
            l_sel <= sel_i;
            l_dat <= wdat_i;
        end
        due_q <= fail_o && may_i && !kth;
        if (rst_i || go_i) begin
            drop_q <= {ND{1'b0}};
            for (e = 0; e < ND; e = e + 1) run_q[e] <= 8'd0;
        end else begin
            for (e = 0; e < ND; e = e + 1) begin
                if (req && ack_i && c_dst[e]) run_q[e] <= 8'd0;
                if (fail_o && l_dst[e]) begin
                    if (run_q[e] != 8'hFF) run_q[e] <= run_q[e] + 8'd1;
                    if (run_q[e] + 8'd1 >= k) drop_q[e] <= 1'b1;
                end
            end
        end
        if (rst_i) begin
            pend_q <= 1'b0;
            errd_q <= 1'b0;
            due_q  <= 1'b0;
            go_q   <= 1'b0;
            may_q  <= 1'b0;
        end
    end

`ifdef FORMAL
    always @* begin
        if (!init_q && !rst_i) begin
            slot_first:   assert(!(go_q && may_q) || req);
            slot_gated:   assert(!begin_ || may_q);
            slot_timeout: assert(!req || !cont || cnt_q < TIMEOUT);
            retry_gap:    assert(!fail_o || !req);
            retry_same:   assert(!due_q || (begin_ && we_i == l_we && adr_i == l_adr && sel_i == l_sel &&
                                            (!we_i || wdat_i == l_dat)));
            drop_k:       assert(!(req && |(c_dst & drop_q)));
        end
    end
`endif
endmodule

`default_nettype wire
