// fbus_master -- proof harness of albatross_bus_master
// (formal/bus_master/bus_master.sby, docs/verification.md "Bus master (unbounded)").
//
// Every input is free.  The requesters r_* are NOT constrained at all: any
// requester behaviour, including the ones Wishbone forbids (changing its fields
// in the middle of an access, dropping cyc before the answer while another
// requester raises it in the same clock, raising cyc in the clock after reset).
// One exception, with HOLD_FIELDS 0 only (the controller's configuration): the
// bus master then passes every field through instead of holding them, and
// its rule is that the requesters keep them, so fields_kept assumes it: while
// an access is pending and its owner holds cyc, the owner's r_we_i, r_board_i,
// r_adr_i, r_sel_i and (a write) r_dat_i are what they were in the last clock
// (a read's data are free, and so is every field of a requester that is not
// the pending access's owner, and of an owner that drops cyc).
// The system-bus slave answers as a classic slave may, or never
// (formal/wb/fwb_master.v on m_*, which asserts the master's requests: stb only
// with cyc, cyc low after reset, and req_stable -- a request carried over an
// edge without an answer keeps we, adr, sel and write data; OPT_ABORT = 1
// because a timeout or an abandoning owner withdraws a request without an
// answer, as Wishbone B4 allows a master to; abort_why below says when it
// happens).  Each requester's answers are asserted here (req_ans_*): ack/err
// never together, only to a requester holding cyc, none in the clock after
// reset.  Reset is high in the first clock only: the RTL's registers start
// unconstrained, so this is a reset from any state.  One clock.
// Defaults REQS = 3, ADDR_WIDTH = 2, BOARD_BITS = 2, TIMEOUT = 5 (3 counter
// bits, so a timeout one clock late is representable), HOLD_FIELDS = 1; the
// script's ctrl tasks set the controller's own parameters instead
// (ctrl_params.py reads them from rtl/albatross_controller.v).
// A reference model (f_*) states the rules of the RTL header:
//   pend    an access is pending: on m_* in the last clock, neither acked nor
//           failed (f_outstanding_o of the m_* property set, not in the gap
//           after a timeout).
//   owner   while an access is pending, its owner; else the owner of the last
//           clock while it keeps cyc; else the lowest index among the
//           requesters with cyc now: from an idle bus, the first to raise cyc
//           (ties to the lowest index); when the owner drops cyc while others
//           wait, the lowest-indexed waiter (not the earliest: the RTL header
//           leaves that case open).  An owner that abandons a pending access
//           (drops cyc) loses the bus.  Reset: no owner.
//   wait    clocks the present m_* request has waited without ack/err
//           (f_wait_o of the m_* property set).
//   fail    m_cyc_o & !m_ack_i & (m_err_i | wait == TIMEOUT-1): an err, or the
//           TIMEOUT-th clock of an access without an answer.
// Properties (labels):
//   pass_now    m_cyc_o = m_stb_o = (owner has cyc) & !(a failure in the last
//               clock): a request passes in the clock it is raised, and a
//               failure drops cyc for exactly one clock.
//   fail_gap    in the clock after a failure m_cyc_o is low.
//   own_fields  in an access's first clock, m_we_o, m_sel_o (HOLD_FIELDS 1:
//               and m_dat_o) are the owner's.
//   fld_pass    (HOLD_FIELDS 0) in every clock with m_cyc_o, m_we_o, m_adr_o,
//               m_sel_o and m_dat_o are the present owner's r_we_i,
//               {r_board_i, r_adr_i}, r_sel_i and r_dat_i: every field
//               passes through, from the owner only (in a hand-over, the new
//               owner's from its access's first clock).
//   adr_owner   in an access's first clock, m_adr_o = {owner's board, owner's
//               word}.
//   hold_fields while an access is pending, m_* keep the last clock's fields
//               (HOLD_FIELDS 1: whatever the owner now drives; HOLD_FIELDS 0:
//               as fields_kept's owner keeps them, a read's data aside;
//               req_stable of fwb_master says the same from the slave's
//               side, store data included).
//   handover    a different owner's access never follows another's without an
//               answer or an idle clock between them.
//   own_silent  a requester other than the owner sees neither ack nor err.
//   ack_pass    the owner's ack = m_cyc_o & m_ack_i; r_dat_o = m_dat_i.
//   err_tmo     the owner's err = fail (exactly in the TIMEOUT-th clock).
//   tmo_bound   a request on m_* has waited at most TIMEOUT-1 clocks.
//   fail_flag   fail_o = fail.
//   fails_count fails_o = failures since reset, saturating at 16'hFFFF.
//   overlap     overlap_o is high from the clock after a clock in which two or
//               more requesters held cyc, until reset.
//   abort_why   a request pending on m_* disappears only in the clock after a
//               failure (a timeout: it had no answer) or when its owner
//               dropped cyc.
//   req_ans_excl, req_ans_cyc, req_ans_reset  a requester's ack and err are
//               never together, come only while it holds cyc, and never in the
//               clock after reset.
//   own_range   the model's owner is a requester (< REQS): its own invariant.
//   we_model    while an access is pending, the model's write flag of the
//               access (f_we_q, which fields_kept reads) is m_we_o of the last
//               clock: its own invariant.
// Induction strengthening (white-box): with -DF_PROBE the script connects f_busy,
// f_owner, f_gap, f_tmo, f_pend and f_held to the RTL's busy_q, owner_q, gap_q,
// tmo_q, pend_q, held_q (Yosys has no hierarchical references: joined after
// flatten); inv_* tie them to the model (inv_held with HOLD_FIELDS 1 only:
// with 0 held_q is never read, and synthesis removes it).
`default_nettype none

module fbus_master #(
    parameter REQS       = 3,  // requesters
    parameter ADDR_WIDTH = 2,  // word-address bits
    parameter BOARD_BITS = 2,  // board-field bits
    parameter TIMEOUT    = 5,  // clocks of cyc without ack/err before an access fails
    parameter HOLD_FIELDS = 1  // the bus master's HOLD_FIELDS (0: every field passed through, fields_kept assumed)
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
    localparam TMO_BITS = (TIMEOUT > 1) ? $clog2(TIMEOUT) : 1;   // the RTL's tmo_q width
    localparam OWN_BITS = (REQS > 2) ? 2 : 1;                   // the RTL's owner_q width
    localparam WAIT_W   = ($clog2(TIMEOUT + 1) > 4) ? $clog2(TIMEOUT + 1) : 4;   // f_wait_o reaches TIMEOUT

    wire [31:0]     r_dat_o;
    wire [REQS-1:0] r_ack_o, r_err_o;
    wire            m_cyc_o, m_stb_o, m_we_o;
    wire [AW-1:0]   m_adr_o;
    wire [3:0]      m_sel_o;
    wire [31:0]     m_dat_o;
    wire            fail_o, overlap_o;
    wire [15:0]     fails_o;

    albatross_bus_master #(.ADDR_WIDTH(ADDR_WIDTH), .BOARD_BITS(BOARD_BITS), .REQS(REQS),
                           .TIMEOUT(TIMEOUT), .HOLD_FIELDS(HOLD_FIELDS)) dut (
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
    always @* assume(!init_q || rst_i);   // reset in the first clock; later, at any time

    // ------------------------------------------------ the Wishbone property sets
    wire       m_pv, m_out, m_rack;
    wire [WAIT_W-1:0] m_wait;
    fwb_master #(.AW(AW), .DW(32), .OPT_ABORT(1), .WAIT_W(WAIT_W)) wb_m (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(m_cyc_o), .stb_i(m_stb_o), .we_i(m_we_o),
        .adr_i(m_adr_o), .sel_i(m_sel_o), .wdat_i(m_dat_o), .rdat_i(m_dat_i),
        .ack_i(m_ack_i), .err_i(m_err_i),
        .f_past_valid_o(m_pv), .f_outstanding_o(m_out), .f_wait_o(m_wait), .f_read_ack_o(m_rack));

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
    reg         f_rst_q   = 1'b0;   // the last clock was a reset clock
    reg         f_mcyc_q  = 1'b0;   // m_cyc_o of the last clock
    reg         f_mans_q  = 1'b0;   // an answer (ack/err) on m_* in the last clock
    reg         f_abort_q = 1'b0;   // the last clock ended an access by its owner's drop (covers)
    localparam FW = 1 + AW + 4 + 32;
    reg  [FW-1:0] f_fld_q;          // m_* fields of the last clock
    reg         f_gap2_q  = 1'b0;   // the clock before the last was a failure (covers)
    reg  [FW-1:0] f_live_q;         // f_live of the last clock (fields_kept)
    reg         f_we_q    = 1'b0;   // the present access is a write (its first clock's we, kept while pending)
    wire        f_pend = m_out && !f_gap_q;
    wire [1:0]  f_own  = (f_pend || (f_hold_q && cyc4[f_own_q])) ? f_own_q : f_first;
    wire        m_req  = m_cyc_o && m_stb_o;
    wire [FW-1:0] m_fld = {m_we_o, m_adr_o, m_sel_o, m_dat_o};
    wire        f_fail = m_req && !m_ack_i && (m_err_i || m_wait == TIMEOUT - 1);
    wire        f_we   = f_pend ? f_we_q : r_we_i[f_own];
    // the model owner's fields now, in m_fld's order
    wire [FW-1:0] f_live = {r_we_i[f_own], r_board_i[f_own*BOARD_BITS +: BOARD_BITS],
                            r_adr_i[f_own*ADDR_WIDTH +: ADDR_WIDTH], r_sel_i[f_own*4 +: 4], r_dat_i[f_own*32 +: 32]};
    // the fields a pending access keeps: all but a read's data (HOLD_FIELDS 1:
    // all), and those of the RTL's held_q (HOLD_FIELDS 0: none, never read)
    wire [FW-1:0] f_kept = {{(FW-32){1'b1}}, {32{HOLD_FIELDS != 0 || f_we_q}}};
    localparam [FW-1:0] HELD = (HOLD_FIELDS != 0) ? {FW{1'b1}} : {FW{1'b0}};
    always @(posedge clk_i) begin
        if (rst_i) begin
            f_hold_q  <= 1'b0;
            f_own_q   <= 2'd0;
            f_gap_q   <= 1'b0;
            f_fails_q <= 16'd0;
            f_ov_q    <= 1'b0;
        end else begin
            f_hold_q  <= cyc4[f_own];
            f_own_q   <= f_own;
            f_gap_q   <= f_fail;
            if (f_fail && f_fails_q != 16'hFFFF) f_fails_q <= f_fails_q + 16'd1;
            if (f_n > 3'd1) f_ov_q <= 1'b1;
        end
        f_cyc_q  <= r_cyc_i;
        f_rst_q  <= rst_i;
        f_mcyc_q <= m_cyc_o && !rst_i;
        f_mans_q <= m_ack_i || m_err_i;
        f_abort_q <= f_pend && !cyc4[f_own] && !rst_i;
        f_fld_q  <= m_fld;
        f_gap2_q <= f_gap_q && !rst_i;
        f_live_q <= f_live;
        f_we_q   <= f_we;
    end

    // HOLD_FIELDS 0: the owner of a pending access keeps its fields (the bus
    // master's rule; f_own is the last clock's owner while f_pend).
    always @* begin
        if (HOLD_FIELDS == 0 && !init_q)
            fields_kept: assume(!(f_pend && cyc4[f_own]) || (f_live & f_kept) == (f_live_q & f_kept));
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
            pass_now:    assert(m_cyc_o == (cyc4[f_own] && !f_gap_q && !f_rst_q) && m_stb_o == m_cyc_o);
            fail_gap:    assert(!f_gap_q || !m_cyc_o);
            own_fields:  assert(!m_cyc_o || f_pend || (m_we_o == r_we_i[f_own] && m_sel_o == r_sel_i[f_own*4 +: 4] &&
                                             (HOLD_FIELDS == 0 || m_dat_o == r_dat_i[f_own*32 +: 32])));
            fld_pass:    assert(HOLD_FIELDS != 0 || !m_cyc_o || m_fld == f_live);
            hold_fields: assert(!m_cyc_o || !f_pend || (m_fld & f_kept) == (f_fld_q & f_kept));
            handover:    assert(!(m_cyc_o && f_mcyc_q && !f_mans_q) || f_pend);
            adr_owner:   assert(!m_cyc_o || f_pend || m_adr_o == {r_board_i[f_own*BOARD_BITS +: BOARD_BITS],
                                                        r_adr_i[f_own*ADDR_WIDTH +: ADDR_WIDTH]});
            own_silent:  assert(ok_silent);
            ack_pass:    assert(own_ack == (m_req && m_ack_i) && r_dat_o == m_dat_i);
            err_tmo:     assert(own_err == f_fail);
            tmo_bound:   assert(!m_req || m_wait < TIMEOUT);
            fail_flag:   assert(fail_o == f_fail);
            fails_count: assert(fails_o == f_fails_q);
            overlap:     assert(overlap_o == f_ov_q);
            abort_why:   assert(!(m_out && !m_req && !rst_i) || f_gap_q || !cyc4[f_own_q]);
            req_ans_excl:  assert((r_ack_o & r_err_o) == {REQS{1'b0}});
            req_ans_cyc:   assert(((r_ack_o | r_err_o) & ~r_cyc_i) == {REQS{1'b0}});
            req_ans_reset: assert(!f_rst_q || (r_ack_o | r_err_o) == {REQS{1'b0}});
            own_range:   assert(f_own_q < REQS);   // the model's own invariant
            we_model:    assert(!f_pend || f_we_q == f_fld_q[FW-1]);
        end
    end

    // ------------------------------------------------ induction strengthening
`ifdef F_PROBE
    (* keep *) wire       f_busy;    // dut.busy_q, joined by the script
    (* keep *) wire [OWN_BITS-1:0] f_owner;   // dut.owner_q
    (* keep *) wire       f_gap;     // dut.gap_q
    (* keep *) wire [TMO_BITS-1:0] f_tmo;   // dut.tmo_q
    (* keep *) wire       f_pendr;   // dut.pend_q
    (* keep *) wire [FW-1:0] f_held; // dut.held_q
    always @* begin
        if (!init_q) begin
            inv_owner: assert(f_busy == f_hold_q && {{(2-OWN_BITS){1'b0}}, f_owner} == f_own_q);
            inv_gap:   assert(f_gap == (f_gap_q || f_rst_q));
            inv_tmo:   assert(f_tmo == ((f_gap_q || f_rst_q) ? {TMO_BITS{1'b0}} : m_wait[TMO_BITS-1:0]) &&
                              (f_gap_q || m_wait < TIMEOUT));
            inv_out:   assert(m_out == (m_wait != {WAIT_W{1'b0}}));
            inv_pend:  assert(f_pendr == f_pend);
            inv_held:  assert(!f_pend || (f_held & HELD) == (f_fld_q & HELD));
        end
    end
`endif

    // ------------------------------------------------------ non-vacuity covers
    // (tasks cover and cover_ctrl): a timeout err to the last requester; the
    // bus handed in one clock to a requester that was waiting; an ack of a
    // retry right after the gap of a failure; two failures counted; and the
    // ones commented below.
    always @* begin
        if (!init_q) begin
            cover_timeout:  cover(r_err_o[REQS-1] && !m_err_i);
            cover_handover: cover(f_hold_q && f_own != f_own_q && f_cyc_q[f_own] && m_req && m_ack_i);
            cover_retry:    cover(f_gap2_q && m_req && m_ack_i);
            cover_fails2:   cover(fails_o == 16'd2 && overlap_o);
            // an ack in an access's first clock (the pass-through path)
            cover_first:    cover(!f_pend && m_req && m_ack_i && !r_ack_o[0]);
            // HOLD_FIELDS 1: an ack of a held access whose owner now drives
            // another address (with 0 the owner keeps it: fields_kept)
            if (HOLD_FIELDS != 0)
                cover_held: cover(f_pend && m_req && m_ack_i &&
                                  m_adr_o != {r_board_i[f_own*BOARD_BITS +: BOARD_BITS], r_adr_i[f_own*ADDR_WIDTH +: ADDR_WIDTH]});
            // HOLD_FIELDS 0: an ack of a read pending for a clock whose owner
            // changed its (free) data: passed through, nothing held (with 1
            // the held data cannot change)
            if (HOLD_FIELDS == 0)
                cover_pass: cover(f_pend && m_req && !m_we_o && m_ack_i && m_dat_o != f_fld_q[31:0]);
            // a slave err passed to the owner
            cover_err:      cover(m_req && m_err_i && r_err_o[1]);
            // the owner dropped a pending access while another raised cyc in
            // that clock: the other gets the bus in the next clock and is acked
            cover_abort:    cover(f_abort_q && f_own != f_own_q && f_cyc_q[f_own] && m_req && m_ack_i);
            // a reset with a requester holding cyc, then its access acked
            cover_reset:    cover(f_rst_q && r_cyc_i[0]);
            // a write acked after a clock pending, its data those of its first
            // clock (HOLD_FIELDS 0: passed through, fields_kept keeping them)
            cover_write_held: cover(f_pend && m_req && m_we_o && m_ack_i && m_dat_o == f_fld_q[31:0]);
            // the hand-over in one clock: the owner, answered in the last
            // clock, drops cyc in the clock in which another requester raises
            // it; that one's write is on the bus at once, with its own data
            // (not the old owner's), and acked in its first clock
            cover_drop_raise: cover(f_hold_q && f_mans_q && !cyc4[f_own_q] && f_own != f_own_q && !f_cyc_q[f_own] &&
                                    m_req && m_we_o && m_ack_i && m_dat_o != r_dat_i[f_own_q*32 +: 32]);
        end
    end
`endif

endmodule

`default_nettype wire
