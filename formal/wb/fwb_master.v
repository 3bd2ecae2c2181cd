// fwb_master -- Wishbone B4 classic property set, seen from a master's side
// (docs/verification.md "Formal proofs (RTL)").  Written for ALBATROSS in the
// style of wb2axip's fwbc_master; not a copy.
//
// Attach one instance to the bus between a master and a slave; it has inputs
// only (and f_* outputs for the harness).  By default (OPT_DUAL = 0) it CHECKS
// A MASTER: the master's requests are asserted, the slave's answers assumed.
// With OPT_DUAL = 1 the roles swap: the requests are assumed (the master is a
// free environment) and the answers asserted, which checks a slave;
// fwb_slave is exactly that, so both files share these properties.
// Rules (assertion/assumption labels, reported by name by SymbiYosys):
//   Requests (req = cyc & stb):
//     req_stb_cyc   stb only with cyc.
//     req_reset     in the clock after a reset clock, cyc is low.
//     req_held      (OPT_ABORT = 0) a request not answered in a clock is still
//                   on the bus in the next one (unless the bus is in reset).
//     req_stable    a request carried over an edge without an answer keeps
//                   we, adr and sel, and dat when it is a write.
//   Answers (ack, err):
//     ans_excl      ack and err never together.
//     ans_in_req    ack or err only in a clock with a request (classic, no
//                   pipelining; a combinational answer in the request's own
//                   clock is allowed).  With OPT_ABORT = 1 also in the clock in
//                   which the master withdrew a pending request (the slave
//                   cannot know it yet; the master ignores that answer).
//     ans_reset     no ack or err in the clock after a reset clock.
//     ans_max_wait  (MAX_WAIT > 0) a request is answered at the latest
//                   MAX_WAIT clocks after its first clock (MAX_WAIT = 2: in
//                   the request's 1st, 2nd or 3rd clock).
// Read data is valid in the clock of a read's ack; checking its value needs a
// model of the slave, so it is the harness's job (f_read_ack_o marks it).
// Nothing is checked in the very first clock (registers may be unconstrained):
// a harness applies reset in its first clock.  One clock: every rule is about
// rising edges of clk_i.
// Outputs for induction-strengthening invariants in a harness:
//   f_past_valid_o   low in the first clock only
//   f_outstanding_o  requests carried over the last edge without an answer
//                    (classic: 0 or 1): the request pending since an earlier clock
//   f_wait_o         clocks the present request has already waited (saturates)
//   f_read_ack_o     ack of a read in this clock
`default_nettype none

module fwb_master #(
    parameter AW        = 3,     // address bits
    parameter DW        = 32,    // data bits
    parameter SW        = DW/8,  // byte-select bits
    parameter MAX_WAIT  = 0,     // 0: no bound; N: answer at most N clocks after the request's first clock
    parameter OPT_ABORT = 0,     // 1: the master may withdraw a request (drop cyc or stb) before its answer
    parameter OPT_DUAL  = 0,     // 0: assert the requests, assume the answers; 1: the reverse
    parameter WAIT_W    = 4      // bits of f_wait_o (must hold MAX_WAIT)
) (
    input  wire              clk_i,
    input  wire              rst_i,      // bus reset, synchronous, active high
    input  wire              cyc_i,
    input  wire              stb_i,
    input  wire              we_i,
    input  wire [AW-1:0]     adr_i,
    input  wire [SW-1:0]     sel_i,
    input  wire [DW-1:0]     wdat_i,     // master -> slave data
    input  wire [DW-1:0]     rdat_i,     // slave -> master data (not checked here)
    input  wire              ack_i,
    input  wire              err_i,
    output reg               f_past_valid_o,
    output reg               f_outstanding_o,
    output reg  [WAIT_W-1:0] f_wait_o,
    output wire              f_read_ack_o
);

`ifdef FORMAL
    wire req = cyc_i & stb_i;
    wire ans = ack_i | err_i;

    initial f_past_valid_o  = 1'b0;
    initial f_outstanding_o = 1'b0;
    initial f_wait_o        = {WAIT_W{1'b0}};
    reg past_rst = 1'b0;
    always @(posedge clk_i) begin
        f_past_valid_o  <= 1'b1;
        past_rst        <= rst_i;
        f_outstanding_o <= req & ~ans & ~rst_i;
        if (req & ~ans & ~rst_i)
            f_wait_o <= (&f_wait_o) ? f_wait_o : f_wait_o + 1'b1;
        else
            f_wait_o <= {WAIT_W{1'b0}};
    end
    assign f_read_ack_o = req & ack_i & ~we_i;

    // The request carried over the last edge, as it was.
    reg          p_we;
    reg [AW-1:0] p_adr;
    reg [SW-1:0] p_sel;
    reg [DW-1:0] p_dat;
    always @(posedge clk_i) begin
        p_we  <= we_i;
        p_adr <= adr_i;
        p_sel <= sel_i;
        p_dat <= wdat_i;
    end

    wire chk = f_past_valid_o;          // every rule skips the first clock
    wire pend = chk & f_outstanding_o;  // a request is pending from the last clock

    // ------------------------------------------------------------- requests
    wire ok_stb_cyc = !stb_i || cyc_i;
    wire ok_reset   = !(chk && past_rst) || !cyc_i;
    wire ok_held    = OPT_ABORT || !pend || rst_i || req;
    wire ok_stable  = !(pend && req) ||
                      (we_i == p_we && adr_i == p_adr && sel_i == p_sel && (!we_i || wdat_i == p_dat));
    always @* begin
        if (chk) begin
            if (OPT_DUAL == 0) begin
                req_stb_cyc: assert(ok_stb_cyc);
                req_reset:   assert(ok_reset);
                req_held:    assert(ok_held);
                req_stable:  assert(ok_stable);
            end else begin
                req_stb_cyc_a: assume(ok_stb_cyc);
                req_reset_a:   assume(ok_reset);
                req_held_a:    assume(ok_held);
                req_stable_a:  assume(ok_stable);
            end
        end
    end

    // -------------------------------------------------------------- answers
    wire ok_excl     = !(ack_i && err_i);
    wire ok_in_req   = !ans || req || (OPT_ABORT && pend);
    wire ok_ans_rst  = !(chk && past_rst) || !ans;
    wire ok_max_wait = (MAX_WAIT == 0) || !(req && !ans && f_wait_o >= MAX_WAIT);
    always @* begin
        if (chk) begin
            if (OPT_DUAL != 0) begin
                ans_excl:     assert(ok_excl);
                ans_in_req:   assert(ok_in_req);
                ans_reset:    assert(ok_ans_rst);
                ans_max_wait: assert(ok_max_wait);
            end else begin
                ans_excl_a:     assume(ok_excl);
                ans_in_req_a:   assume(ok_in_req);
                ans_reset_a:    assume(ok_ans_rst);
                ans_max_wait_a: assume(ok_max_wait);
            end
        end
    end
`else
    initial f_past_valid_o  = 1'b0;
    initial f_outstanding_o = 1'b0;
    initial f_wait_o        = {WAIT_W{1'b0}};
    assign f_read_ack_o = 1'b0;
`endif

endmodule

`default_nettype wire
