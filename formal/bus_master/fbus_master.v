// fbus_master -- proof harness of albatross_bus_master
// (formal/bus_master/bus_master.sby, docs/verification.md "Bus master (unbounded)").
//
// Every input is free, constrained only by the Wishbone property sets: each
// requester r_* is a Wishbone B4 classic master that obeys the rules
// (formal/wb/fwb_slave.v per requester, which asserts the bus master's answers
// to it, OPT_ABORT = 0, no answer bound since a waiting requester may wait for
// ever), and the system-bus slave answers as a classic slave may, or never
// (formal/wb/fwb_master.v on m_*, which asserts the master's requests; OPT_ABORT
// = 1 because a timeout withdraws a request without an answer, as Wishbone B4
// allows a master to; abort_tmo below says it happens only then).  Reset is high
// in the first clock only: the RTL's registers start unconstrained, so this is a
// reset from any state; a later reset would let a requester change its request
// in the reset clock, which m_* passes on combinationally and fwb_master's
// req_stable (not exempt in reset clocks) would flag.  One clock.
// REQS = 3, ADDR_WIDTH = 2, BOARD_BITS = 2, TIMEOUT = 5 (3 counter bits, so a
// timeout one clock late is representable).
// A reference model (f_*) states the rules of the RTL header:
//   owner   the owner of the last clock while it keeps cyc; else the lowest
//           index among the requesters with cyc now: from an idle bus, the
//           first to raise cyc (ties to the lowest index); when the owner drops
//           cyc while others wait, the lowest-indexed waiter (not the earliest:
//           the RTL header leaves that case open).  Reset: no owner.
//   wait    clocks the present m_* request has waited without ack/err
//           (f_wait_o of the m_* property set).
//   fail    m_cyc_o & !m_ack_i & (m_err_i | wait == TIMEOUT-1): an err, or the
//           TIMEOUT-th clock of an access without an answer.
// Properties (labels):
//   pass_now    m_cyc_o = m_stb_o = (owner has cyc) & !(a failure in the last
//               clock): a request passes in the clock it is raised, and a
//               failure drops cyc for exactly one clock.
//   fail_gap    in the clock after a failure m_cyc_o is low.
//   own_fields  with m_cyc_o, m_we_o, m_sel_o, m_dat_o are the owner's.
//   adr_owner   with m_cyc_o, m_adr_o = {owner's board, owner's word}.
//   own_silent  a requester other than the owner sees neither ack nor err.
//   ack_pass    the owner's ack = m_cyc_o & m_ack_i; r_dat_o = m_dat_i.
//   err_tmo     the owner's err = fail (exactly in the TIMEOUT-th clock).
//   tmo_bound   a request on m_* has waited at most TIMEOUT-1 clocks.
//   fail_flag   fail_o = fail.
//   fails_count fails_o = failures since reset, saturating at 16'hFFFF.
//   overlap     overlap_o is high from the clock after a clock in which two or
//               more requesters held cyc, until reset.
//   abort_tmo   a request pending on m_* disappears (no reset) only in the
//               clock after a failure (a timeout: it had no answer).
//   own_range   the model's owner is a requester (< REQS): its own invariant.
// Induction strengthening (white-box): with -DF_PROBE the script connects f_busy,
// f_owner, f_gap and f_tmo to the RTL's busy_q, owner_q, gap_q, tmo_q (Yosys has
// no hierarchical references: joined after flatten); inv_* tie them to the model.
`default_nettype none

module fbus_master #(
    parameter REQS       = 3,  // requesters
    parameter ADDR_WIDTH = 2,  // word-address bits
    parameter BOARD_BITS = 2,  // board-field bits
    parameter TIMEOUT    = 5   // clocks of cyc without ack/err before an access fails
) (
    input  wire                         clk_i,
    input  wire                         rst_i,
    input  wire [REQS-1:0]              r_cyc_i,
    input  wire [REQS-1:0]              r_we_i,
    input  wire [REQS*ADDR_WIDTH-1:0]   r_adr_i,
    input  wire [REQS*BOARD_BITS-1:0]   r_board_i,
    input  wire [REQS*4-1:0]            r_sel_i,
    input  wire [REQS*32-1:0]           r_dat_i,
    input  wire [31:0]                  m_dat_i,
    input  wire                         m_ack_i,
    input  wire                         m_err_i
);

    localparam AW = BOARD_BITS + ADDR_WIDTH;   // system-bus address bits

    wire [31:0]     r_dat_o;
    wire [REQS-1:0] r_ack_o, r_err_o;
    wire            m_cyc_o, m_stb_o, m_we_o;
    wire [AW-1:0]   m_adr_o;
    wire [3:0]      m_sel_o;
    wire [31:0]     m_dat_o;
    wire            fail_o, overlap_o;
    wire [15:0]     fails_o;

    albatross_bus_master #(.ADDR_WIDTH(ADDR_WIDTH), .BOARD_BITS(BOARD_BITS), .REQS(REQS),
                           .TIMEOUT(TIMEOUT)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .r_cyc_i(r_cyc_i), .r_we_i(r_we_i), .r_adr_i(r_adr_i), .r_board_i(r_board_i),
        .r_sel_i(r_sel_i), .r_dat_i(r_dat_i), .r_dat_o(r_dat_o), .r_ack_o(r_ack_o),
        .r_err_o(r_err_o),
        .m_cyc_o(m_cyc_o), .m_stb_o(m_stb_o), .m_we_o(m_we_o), .m_adr_o(m_adr_o),
        .m_sel_o(m_sel_o), .m_dat_o(m_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i),
        .m_err_i(m_err_i),
        .fail_o(fail_o), .fails_o(fails_o), .overlap_o(overlap_o)
    );

`ifdef FORMAL
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);

    // ------------------------------------------------ the Wishbone property sets
    wire       m_pv, m_out, m_rack;
    wire [3:0] m_wait;
    fwb_master #(.AW(AW), .DW(32), .OPT_ABORT(1)) wb_m (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(m_cyc_o), .stb_i(m_stb_o), .we_i(m_we_o),
        .adr_i(m_adr_o), .sel_i(m_sel_o), .wdat_i(m_dat_o), .rdat_i(m_dat_i),
        .ack_i(m_ack_i), .err_i(m_err_i),
        .f_past_valid_o(m_pv), .f_outstanding_o(m_out), .f_wait_o(m_wait), .f_read_ack_o(m_rack));

    genvar g;
    generate for (g = 0; g < REQS; g = g + 1) begin : req
        wire       pv, out, rack;
        wire [3:0] wt;
        fwb_slave #(.AW(AW), .DW(32)) wb (
            .clk_i(clk_i), .rst_i(rst_i), .cyc_i(r_cyc_i[g]), .stb_i(r_cyc_i[g]), .we_i(r_we_i[g]),
            .adr_i({r_board_i[g*BOARD_BITS +: BOARD_BITS], r_adr_i[g*ADDR_WIDTH +: ADDR_WIDTH]}),
            .sel_i(r_sel_i[g*4 +: 4]), .wdat_i(r_dat_i[g*32 +: 32]), .rdat_i(r_dat_o),
            .ack_i(r_ack_o[g]), .err_i(r_err_o[g]),
            .f_past_valid_o(pv), .f_outstanding_o(out), .f_wait_o(wt), .f_read_ack_o(rack));
    end endgenerate

    // ------------------------------------------------------- reference model
    wire [3:0] cyc4 = {{(4-REQS){1'b0}}, r_cyc_i};   // index 0..3 without running off the end
    reg  [1:0] f_first;      // lowest index with cyc (0 if none)
    reg  [2:0] f_n;          // requesters with cyc
    integer i;
    always @* begin
        f_first = 2'd0;
        f_n     = 3'd0;
        for (i = REQS - 1; i >= 0; i = i - 1) begin
            if (r_cyc_i[i]) f_first = i[1:0];
            f_n = f_n + {2'd0, r_cyc_i[i]};
        end
    end
    reg         f_hold_q  = 1'b0;   // a requester held cyc in the last clock
    reg  [1:0]  f_own_q   = 2'd0;   // the owner of the last clock
    reg         f_gap_q   = 1'b0;   // the last clock was a failure
    reg  [15:0] f_fails_q = 16'd0;
    reg         f_ov_q    = 1'b0;
    reg  [REQS-1:0] f_cyc_q = {REQS{1'b0}};   // r_cyc_i of the last clock (covers)
    reg         f_gap2_q  = 1'b0;   // the clock before the last was a failure (covers)
    wire [1:0]  f_own  = (f_hold_q && cyc4[f_own_q]) ? f_own_q : f_first;
    wire        m_req  = m_cyc_o && m_stb_o;
    wire        f_fail = m_req && !m_ack_i && (m_err_i || m_wait == TIMEOUT - 1);
    always @(posedge clk_i) begin
        if (rst_i) begin
            f_hold_q  <= 1'b0;
            f_own_q   <= 2'd0;
            f_gap_q   <= 1'b0;
            f_fails_q <= 16'd0;
            f_ov_q    <= 1'b0;
        end else begin
            f_hold_q  <= |r_cyc_i;
            f_own_q   <= f_own;
            f_gap_q   <= f_fail;
            if (f_fail && f_fails_q != 16'hFFFF) f_fails_q <= f_fails_q + 16'd1;
            if (f_n > 3'd1) f_ov_q <= 1'b1;
        end
        f_cyc_q  <= r_cyc_i;
        f_gap2_q <= f_gap_q && !rst_i;
    end

    // ------------------------------------------------------------ properties
    reg ok_silent;
    always @* begin
        ok_silent = 1'b1;
        for (i = 0; i < REQS; i = i + 1)
            if (i[1:0] != f_own && (r_ack_o[i] || r_err_o[i])) ok_silent = 1'b0;
    end
    wire own_ack = r_ack_o[f_own];
    wire own_err = r_err_o[f_own];
    always @* begin
        if (!init_q) begin
            pass_now:    assert(m_cyc_o == (cyc4[f_own] && !f_gap_q) && m_stb_o == m_cyc_o);
            fail_gap:    assert(!f_gap_q || !m_cyc_o);
            own_fields:  assert(!m_cyc_o || (m_we_o == r_we_i[f_own] && m_sel_o == r_sel_i[f_own*4 +: 4] &&
                                             m_dat_o == r_dat_i[f_own*32 +: 32]));
            adr_owner:   assert(!m_cyc_o || m_adr_o == {r_board_i[f_own*BOARD_BITS +: BOARD_BITS],
                                                        r_adr_i[f_own*ADDR_WIDTH +: ADDR_WIDTH]});
            own_silent:  assert(ok_silent);
            ack_pass:    assert(own_ack == (m_req && m_ack_i) && r_dat_o == m_dat_i);
            err_tmo:     assert(own_err == f_fail);
            tmo_bound:   assert(!m_req || m_wait < TIMEOUT);
            fail_flag:   assert(fail_o == f_fail);
            fails_count: assert(fails_o == f_fails_q);
            overlap:     assert(overlap_o == f_ov_q);
            abort_tmo:   assert(!(m_out && !m_req && !rst_i) || f_gap_q);
            own_range:   assert(f_own_q < REQS);   // the model's own invariant
        end
    end

    // ------------------------------------------------ induction strengthening
`ifdef F_PROBE
    (* keep *) wire       f_busy;    // dut.busy_q, joined by the script
    (* keep *) wire [1:0] f_owner;   // dut.owner_q
    (* keep *) wire       f_gap;     // dut.gap_q
    (* keep *) wire [2:0] f_tmo;     // dut.tmo_q
    always @* begin
        if (!init_q) begin
            inv_owner: assert(f_busy == f_hold_q && f_owner == f_own_q);
            inv_gap:   assert(f_gap == f_gap_q);
            inv_tmo:   assert(f_tmo == (f_gap_q ? 3'd0 : m_wait[2:0]) && (f_gap_q || m_wait < TIMEOUT));
            inv_out:   assert(m_out == (m_wait != 4'd0));
        end
    end
`endif

    // ------------------------------------------------------ non-vacuity covers
    // (task cover): a timeout err to the last requester; the bus handed in one
    // clock to a requester that was waiting; an ack of a retry right after the
    // gap of a failure; two failures counted.
    always @* begin
        if (!init_q) begin
            cover_timeout:  cover(r_err_o[REQS-1] && !m_err_i);
            cover_handover: cover(f_hold_q && f_own != f_own_q && f_cyc_q[f_own] && m_req && m_ack_i);
            cover_retry:    cover(f_gap2_q && m_req && m_ack_i);
            cover_fails2:   cover(fails_o == 16'd2 && overlap_o);
        end
    end
`endif

endmodule

`default_nettype wire
