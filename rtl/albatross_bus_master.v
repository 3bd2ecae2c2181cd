// albatross_bus_master -- the controller's one master port on the system bus
// (Wishbone B4 classic, address {board[3:0], word}), shared by REQS
// requesters (in the controller: the transfer datapath and the sequencer's
// poll; in the hardware endpoints' proofs: the Import and Export engines).
// The owner field is as wide as a requester index needs (1 bit for REQS 2).
// Rules:
//   * Requesters are Wishbone B4 classic masters on a word address plus a
//     board field; the master adds the board field (m_adr_o = {board, word}).
//   * The system bus obeys Wishbone classic whatever the requesters do
//     (HOLD_FIELDS 1), or as long as each owner keeps its fields
//     (HOLD_FIELDS 0, below).  An access (the bus request m_*) starts with
//     the owner's fields, passed through in the clock it is raised (no idle
//     bus clock is added); with HOLD_FIELDS 1, from its second clock on,
//     m_we_o, m_adr_o, m_sel_o and m_dat_o come from a register holding the
//     first clock's values, until ack, err or the timeout ends the access,
//     so an owner that changes its fields in the middle of an access cannot
//     change the slave's request.  An owner that drops cyc before the
//     answer abandons the access: m_cyc_o/m_stb_o drop in that clock (a
//     Wishbone abort), the owner loses the bus, and another requester gets
//     it at the earliest in the next clock.  Between two accesses there is
//     therefore either an answer (ack/err) or at least one clock with cyc
//     low: a requester raising cyc in the clock in which the owner drops it
//     never inherits the owner's access.
//   * Arbitration: at most one requester is expected to hold cyc at a time
//     (the word stream between the engines guarantees it).  The master makes
//     it explicit and safe: a free bus goes to the lowest-indexed requester
//     holding cyc (a requester that was waiting included), which keeps it
//     until it drops cyc; any other requester's cyc waits (it sees neither
//     ack nor err) and overlap_o goes high for good (a design error that a
//     test or proof can watch for).  ack and err go only to the owner, and
//     only in a clock in which it holds cyc.
//   * HOLD_FIELDS 0 (the controller): m_we_o, m_adr_o, m_sel_o and m_dat_o
//     are always the owner's r_we_i, {r_board_i, r_adr_i}, r_sel_i and
//     r_dat_i, nothing held; the requesters keep them stable from an
//     access's first clock until its answer themselves (the controller's
//     do: formal/ctrl proves Wishbone classic at the controller's port for
//     the datapath, fields and store data included, and formal/sequencer's
//     poll_when that the poll's board and address are entry 0's source
//     while it polls).
//   * Timeout: an access that sees neither ack nor err in TIMEOUT clocks of
//     cyc fails: the owner gets err in the TIMEOUT-th clock, and the request
//     is dropped at the slave.
//   * Every failed access (err, or the timeout) drops cyc/stb for the next
//     clock, so the slave sees the retry as a new request; fail_o is high in
//     the failure clock and fails_o counts failures (16-bit, saturating).
//   * Reset (synchronous) clears the owner, the pending access, the timeout
//     and the counters (not the held fields: they are used only while an
//     access is pending, and never with HOLD_FIELDS 0); cyc stays low in the clock after a reset clock.
`default_nettype none

module albatross_bus_master #(
    parameter ADDR_WIDTH  = 10, // word-address bits of a board RAM
    parameter BOARD_BITS  = 4,  // bits of the board field (high address bits)
    parameter REQS        = 3,  // requesters, 1..4
    parameter TIMEOUT     = 8,  // clocks of cyc without ack/err before an access fails, >= 2
    parameter HOLD_FIELDS = 1   // 1: we, adr, sel, data held from an access's second clock; 0: passed through (the requesters keep them)
) (
    input  wire                           clk_i,
    input  wire                           rst_i,       // synchronous, active high
    // requesters: requester r at [r*width +: width]
    input  wire [REQS-1:0]                r_cyc_i,     // cyc = stb for every requester
    input  wire [REQS-1:0]                r_we_i,
    input  wire [REQS*ADDR_WIDTH-1:0]     r_adr_i,     // word address
    input  wire [REQS*BOARD_BITS-1:0]     r_board_i,
    input  wire [REQS*4-1:0]              r_sel_i,
    input  wire [REQS*32-1:0]             r_dat_i,
    output wire [31:0]                    r_dat_o,     // read data, to every requester
    output wire [REQS-1:0]                r_ack_o,
    output wire [REQS-1:0]                r_err_o,     // err from the slave, or the timeout
    // the system bus
    output wire                           m_cyc_o,
    output wire                           m_stb_o,
    output wire                           m_we_o,
    output wire [BOARD_BITS+ADDR_WIDTH-1:0] m_adr_o,
    output wire [3:0]                     m_sel_o,
    output wire [31:0]                    m_dat_o,
    input  wire [31:0]                    m_dat_i,
    input  wire                           m_ack_i,
    input  wire                           m_err_i,
    // status
    output wire                           fail_o,      // a failed access, this clock
    output wire [15:0]                    fails_o,     // failed accesses since reset (saturating)
    output wire                           overlap_o    // two requesters held cyc at once (sticky)
);

    localparam TMO_BITS = (TIMEOUT > 1) ? $clog2(TIMEOUT) : 1;
    localparam integer        TMO_LAST_I = TIMEOUT - 1;
    localparam [TMO_BITS-1:0] TMO_LAST   = TMO_LAST_I[TMO_BITS-1:0];
    localparam OWN_BITS = (REQS > 2) ? 2 : 1;   // bits of a requester index (the owner field)

    generate
        if (REQS < 1 || REQS > 4 || TIMEOUT < 2 || BOARD_BITS < 1) begin : g_param_check
            albatross_bus_master_parameter_out_of_range u_error ();
        end
    endgenerate

    localparam FW = 1 + BOARD_BITS + ADDR_WIDTH + 4 + 32;   // we, adr, sel, dat

    reg                 busy_q;      // owner_q holds the bus
    reg                 pend_q;      // an access is pending: on the bus in the last clock, unanswered
    reg [FW-1:0]        held_q;      // the bus fields of the last clock {we, adr, sel, dat}
    reg [OWN_BITS-1:0]  owner_q;
    reg                 gap_q;       // the clock after a failure or a reset: cyc low
    reg [TMO_BITS-1:0]  tmo_q;       // clocks of the current access without an answer
    reg [15:0]          fails_q;
    reg                 overlap_q;

    // The owner in this clock: the holder, or the first requester with cyc.
    reg [OWN_BITS-1:0] first;
    reg [2:0]          n_req;
    integer r;
    always @* begin
        first = {OWN_BITS{1'b0}};
        n_req = 3'd0;
        for (r = REQS - 1; r >= 0; r = r - 1) begin
            if (r_cyc_i[r]) first = r[OWN_BITS-1:0];
            n_req = n_req + {2'd0, r_cyc_i[r]};
        end
    end
    // A pending access keeps its owner; it ends (an abort) if the owner drops cyc.
    wire [OWN_BITS-1:0] owner = (pend_q || (busy_q && r_cyc_i[owner_q])) ? owner_q : first;
    wire                cyc   = r_cyc_i[owner] && !gap_q;
    // The bus fields: the owner's in an access's first clock, then held
    // (HOLD_FIELDS 0: always the owner's).
    wire [FW-1:0]       live  = {r_we_i[owner],
                                 r_board_i[owner*BOARD_BITS +: BOARD_BITS], r_adr_i[owner*ADDR_WIDTH +: ADDR_WIDTH],
                                 r_sel_i[owner*4 +: 4], r_dat_i[owner*32 +: 32]};
    wire [FW-1:0]       field = (HOLD_FIELDS != 0 && pend_q) ? held_q : live;
    wire                tmo   = cyc && !m_ack_i && !m_err_i && tmo_q == TMO_LAST;
    wire                fail  = cyc && !m_ack_i && (m_err_i || tmo);
    wire                ack   = cyc && m_ack_i;

    always @(posedge clk_i) begin
        if (rst_i) begin
            busy_q    <= 1'b0;
            pend_q    <= 1'b0;
            owner_q   <= {OWN_BITS{1'b0}};
            gap_q     <= 1'b1;   // cyc stays low in the clock after reset
            tmo_q     <= {TMO_BITS{1'b0}};
            fails_q   <= 16'd0;
            overlap_q <= 1'b0;
        end else begin
            busy_q  <= r_cyc_i[owner];
            pend_q  <= cyc && !m_ack_i && !fail;
            owner_q <= owner;
            gap_q   <= fail;
            if (!cyc || m_ack_i || m_err_i || tmo) tmo_q <= {TMO_BITS{1'b0}};
            else                                   tmo_q <= tmo_q + 1'b1;
            if (fail && fails_q != 16'hFFFF) fails_q <= fails_q + 16'd1;
            if (n_req > 3'd1) overlap_q <= 1'b1;
        end
    end

    always @(posedge clk_i) held_q <= field;   // data only: used while pend_q (HOLD_FIELDS 0: never)

    assign m_cyc_o   = cyc;
    assign m_stb_o   = cyc;
    assign m_we_o    = field[FW-1];
    assign m_adr_o   = field[36 +: BOARD_BITS + ADDR_WIDTH];
    assign m_sel_o   = field[32 +: 4];
    assign m_dat_o   = field[31:0];
    assign r_dat_o   = m_dat_i;
    assign r_ack_o   = {{(REQS-1){1'b0}}, ack} << owner;
    assign r_err_o   = {{(REQS-1){1'b0}}, fail} << owner;
    assign fail_o    = fail;
    assign fails_o   = fails_q;
    assign overlap_o = overlap_q;

endmodule

`default_nettype wire
