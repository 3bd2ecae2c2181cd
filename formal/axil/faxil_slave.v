// faxil_slave -- AXI4-Lite property set, seen from a slave's side
// (docs/verification.md "Formal proofs (RTL)").  Written for ALBATROSS in the
// style of formal/wb/fwb_slave.v and of wb2axip's faxil_slave; not a copy.
//
// Attach one instance to the five channels between a free master and the
// slave under proof; it has inputs only (and f_* outputs for the harness).
// The master's side is assumed (any master that obeys AXI4-Lite), the slave's
// answers asserted.  One clock (ACLK = clk_i); reset synchronous, active high
// (rst_i = ~ARESETn).  Nothing is checked in the very first clock (registers
// may be unconstrained): a harness applies reset in its first clock.
// Rules (labels, reported by name by SymbiYosys):
//   Master (assumed, *_a):
//     m_reset_a     AWVALID, WVALID, ARVALID low in a reset clock and in the
//                   clock after it.
//     m_aw_a, m_w_a, m_ar_a
//                   a VALID not taken (READY low) at an edge stays high in the
//                   next clock with the same payload (AWADDR/AWPROT,
//                   WDATA/WSTRB, ARADDR/ARPROT).
//     m_b_a, m_r_a  (OPT_READY_ALWAYS = 1 only) BREADY / RREADY always high.
//   Slave (asserted):
//     s_reset       BVALID, RVALID low in the clock after a reset clock.
//     s_b_stable    a BVALID not taken stays high with the same BRESP.
//     s_r_stable    an RVALID not taken stays high with the same RDATA, RRESP.
//     s_b_owed      BVALID only for a write whose AW and W handshakes both
//                   came at earlier edges (never before or with them).
//     s_r_owed      RVALID only for a read whose AR handshake came earlier.
//     s_exokay      no EXOKAY response (not in AXI4-Lite).
//     s_max_out     (F_MAX_OUT > 0) at most F_MAX_OUT accepted AW, W and AR
//                   not yet answered (the slave applies back-pressure).
//     s_b_wait      (F_MAX_WAIT_B > 0) while a write is owed (both its
//                   handshakes done, no B yet), BVALID is low for at most
//                   F_MAX_WAIT_B clocks in a row: the slave's own response
//                   latency, not counting clocks in which an earlier B waits
//                   for BREADY (the master's stall).
//     s_r_wait      (F_MAX_WAIT_R > 0) the same for reads and RVALID.
// Outputs for induction-strengthening invariants in a harness:
//   f_past_valid_o  low in the first clock only
//   f_aw_out_o, f_w_out_o, f_ar_out_o
//                   AW / W / AR handshakes so far minus B / B / R handshakes
//                   (accepted requests not yet answered)
//   f_b_wait_o, f_r_wait_o  the counters of s_b_wait / s_r_wait
`default_nettype none

module faxil_slave #(
    parameter AW               = 5,  // byte-address bits
    parameter DW               = 32, // data bits
    parameter SW               = DW/8, // strobe bits
    parameter F_LGDEPTH        = 4,  // bits of the outstanding and wait counters
    parameter F_MAX_OUT        = 0,  // 0: no bound; N: at most N accepted, unanswered per channel
    parameter F_MAX_WAIT_B     = 0,  // 0: no bound; N: BVALID low at most N clocks while a write is owed
    parameter F_MAX_WAIT_R     = 0,  // 0: no bound; N: RVALID low at most N clocks while a read is owed
    parameter OPT_READY_ALWAYS = 0   // 1: assume BREADY and RREADY always high
) (
    input  wire                 clk_i,
    input  wire                 rst_i,      // synchronous, active high
    input  wire                 awvalid_i,
    input  wire                 awready_i,
    input  wire [AW-1:0]        awaddr_i,
    input  wire [2:0]           awprot_i,
    input  wire                 wvalid_i,
    input  wire                 wready_i,
    input  wire [DW-1:0]        wdata_i,
    input  wire [SW-1:0]        wstrb_i,
    input  wire                 bvalid_i,
    input  wire                 bready_i,
    input  wire [1:0]           bresp_i,
    input  wire                 arvalid_i,
    input  wire                 arready_i,
    input  wire [AW-1:0]        araddr_i,
    input  wire [2:0]           arprot_i,
    input  wire                 rvalid_i,
    input  wire                 rready_i,
    input  wire [DW-1:0]        rdata_i,
    input  wire [1:0]           rresp_i,
    output reg                  f_past_valid_o,
    output reg  [F_LGDEPTH-1:0] f_aw_out_o,
    output reg  [F_LGDEPTH-1:0] f_w_out_o,
    output reg  [F_LGDEPTH-1:0] f_ar_out_o,
    output reg  [F_LGDEPTH-1:0] f_b_wait_o,
    output reg  [F_LGDEPTH-1:0] f_r_wait_o
);

    initial f_past_valid_o = 1'b0;
    initial f_aw_out_o     = {F_LGDEPTH{1'b0}};
    initial f_w_out_o      = {F_LGDEPTH{1'b0}};
    initial f_ar_out_o     = {F_LGDEPTH{1'b0}};
    initial f_b_wait_o     = {F_LGDEPTH{1'b0}};
    initial f_r_wait_o     = {F_LGDEPTH{1'b0}};

`ifdef FORMAL
    wire aw_hs = awvalid_i & awready_i;
    wire w_hs  = wvalid_i  & wready_i;
    wire ar_hs = arvalid_i & arready_i;
    wire b_hs  = bvalid_i  & bready_i;
    wire r_hs  = rvalid_i  & rready_i;

    // Every channel as it was at the last edge.
    reg          past_rst = 1'b0;
    reg          p_awvalid, p_awready, p_wvalid, p_wready, p_arvalid, p_arready;
    reg          p_bvalid, p_bready, p_rvalid, p_rready;
    reg [AW-1:0] p_awaddr, p_araddr;
    reg [2:0]    p_awprot, p_arprot;
    reg [DW-1:0] p_wdata, p_rdata;
    reg [SW-1:0] p_wstrb;
    reg [1:0]    p_bresp, p_rresp;
    always @(posedge clk_i) begin
        f_past_valid_o <= 1'b1;
        past_rst  <= rst_i;
        p_awvalid <= awvalid_i; p_awready <= awready_i; p_awaddr <= awaddr_i; p_awprot <= awprot_i;
        p_wvalid  <= wvalid_i;  p_wready  <= wready_i;  p_wdata  <= wdata_i;  p_wstrb  <= wstrb_i;
        p_arvalid <= arvalid_i; p_arready <= arready_i; p_araddr <= araddr_i; p_arprot <= arprot_i;
        p_bvalid  <= bvalid_i;  p_bready  <= bready_i;  p_bresp  <= bresp_i;
        p_rvalid  <= rvalid_i;  p_rready  <= rready_i;  p_rdata  <= rdata_i;  p_rresp  <= rresp_i;
    end
    wire chk  = f_past_valid_o;
    wire live = chk & ~past_rst & ~rst_i;   // an edge with no reset on either side

    // Outstanding counts (handshakes at earlier edges).
    wire [F_LGDEPTH-1:0] one = {{(F_LGDEPTH-1){1'b0}}, 1'b1};
    always @(posedge clk_i) begin
        if (rst_i) begin
            f_aw_out_o <= {F_LGDEPTH{1'b0}};
            f_w_out_o  <= {F_LGDEPTH{1'b0}};
            f_ar_out_o <= {F_LGDEPTH{1'b0}};
        end else begin
            f_aw_out_o <= f_aw_out_o + (aw_hs ? one : 0) - (b_hs ? one : 0);
            f_w_out_o  <= f_w_out_o  + (w_hs  ? one : 0) - (b_hs ? one : 0);
            f_ar_out_o <= f_ar_out_o + (ar_hs ? one : 0) - (r_hs ? one : 0);
        end
    end
    wire b_owed = f_aw_out_o != 0 && f_w_out_o != 0;   // a complete write not yet answered
    wire r_owed = f_ar_out_o != 0;
    always @(posedge clk_i) begin
        if (rst_i || !b_owed || bvalid_i)
            f_b_wait_o <= {F_LGDEPTH{1'b0}};
        else if (!(&f_b_wait_o))
            f_b_wait_o <= f_b_wait_o + one;
        if (rst_i || !r_owed || rvalid_i)
            f_r_wait_o <= {F_LGDEPTH{1'b0}};
        else if (!(&f_r_wait_o))
            f_r_wait_o <= f_r_wait_o + one;
    end

    // ------------------------------------------------------ master (assumed)
    always @* begin
        if (rst_i || (chk && past_rst))
            m_reset_a: assume(!awvalid_i && !wvalid_i && !arvalid_i);
        if (live) begin
            if (p_awvalid && !p_awready)
                m_aw_a: assume(awvalid_i && awaddr_i == p_awaddr && awprot_i == p_awprot);
            if (p_wvalid && !p_wready)
                m_w_a:  assume(wvalid_i && wdata_i == p_wdata && wstrb_i == p_wstrb);
            if (p_arvalid && !p_arready)
                m_ar_a: assume(arvalid_i && araddr_i == p_araddr && arprot_i == p_arprot);
        end
        if (OPT_READY_ALWAYS != 0) begin
            m_b_a: assume(bready_i);
            m_r_a: assume(rready_i);
        end
    end

    // ------------------------------------------------------ slave (asserted)
    always @* begin
        if (chk) begin
            if (past_rst)
                s_reset: assert(!bvalid_i && !rvalid_i);
            if (live && p_bvalid && !p_bready)
                s_b_stable: assert(bvalid_i && bresp_i == p_bresp);
            if (live && p_rvalid && !p_rready)
                s_r_stable: assert(rvalid_i && rdata_i == p_rdata && rresp_i == p_rresp);
            if (!rst_i && bvalid_i)
                s_b_owed: assert(b_owed);
            if (!rst_i && rvalid_i)
                s_r_owed: assert(r_owed);
            if (bvalid_i)
                s_exokay: assert(bresp_i != 2'b01);
            if (rvalid_i)
                s_exokay_r: assert(rresp_i != 2'b01);
            if (F_MAX_OUT > 0)
                s_max_out: assert(f_aw_out_o <= F_MAX_OUT && f_w_out_o <= F_MAX_OUT && f_ar_out_o <= F_MAX_OUT);
            if (F_MAX_WAIT_B > 0)
                s_b_wait: assert(f_b_wait_o <= F_MAX_WAIT_B);
            if (F_MAX_WAIT_R > 0)
                s_r_wait: assert(f_r_wait_o <= F_MAX_WAIT_R);
        end
    end
`endif

endmodule

`default_nettype wire
