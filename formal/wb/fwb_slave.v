// fwb_slave -- Wishbone B4 classic property set, seen from a slave's side
// (docs/verification.md "Formal proofs (RTL)"): the mirror of fwb_master.
//
// By default (OPT_DUAL = 0) it CHECKS A SLAVE: the master's requests are
// assumed (any master that obeys Wishbone classic) and the slave's answers
// asserted, with the labels of fwb_master (ans_excl, ans_in_req, ans_reset,
// ans_max_wait).  With OPT_DUAL = 1 it checks the master instead (req_*
// asserted, answers assumed), the same as fwb_master with OPT_DUAL = 0.  The
// rules themselves are written once, in fwb_master; this file only swaps the
// roles, so the two sets can never drift apart.  Parameters, ports and f_*
// outputs are those of fwb_master.
`default_nettype none

module fwb_slave #(
    parameter AW        = 3,     // address bits
    parameter DW        = 32,    // data bits
    parameter SW        = DW/8,  // byte-select bits
    parameter MAX_WAIT  = 0,     // 0: no bound; N: the slave answers at most N clocks after the request's first clock
    parameter OPT_ABORT = 0,     // 1: the master may withdraw a request (drop cyc or stb) before its answer
    parameter OPT_DUAL  = 0,     // 0: assume the requests, assert the answers; 1: the reverse
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
    output wire              f_past_valid_o,
    output wire              f_outstanding_o,
    output wire [WAIT_W-1:0] f_wait_o,
    output wire              f_read_ack_o
);

    fwb_master #(
        .AW(AW), .DW(DW), .SW(SW), .MAX_WAIT(MAX_WAIT), .OPT_ABORT(OPT_ABORT),
        .OPT_DUAL(OPT_DUAL == 0 ? 1 : 0), .WAIT_W(WAIT_W)
    ) props (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(cyc_i), .stb_i(stb_i), .we_i(we_i),
        .adr_i(adr_i), .sel_i(sel_i), .wdat_i(wdat_i), .rdat_i(rdat_i),
        .ack_i(ack_i), .err_i(err_i),
        .f_past_valid_o(f_past_valid_o), .f_outstanding_o(f_outstanding_o),
        .f_wait_o(f_wait_o), .f_read_ack_o(f_read_ack_o)
    );

endmodule

`default_nettype wire
