// fwb_cdc -- proof harness of albatross_wb_cdc (formal/wb_cdc/wb_cdc.sby,
// docs/verification.md "Formal proofs (RTL)").
//
// Two clocks, modelled with SymbiYosys `multiclock on`: one global formal step,
// and s_clk_i and m_clk_i free inputs, so each may rise in any step or stay
// still for any number of steps (any ratio, any jitter, coincident edges).
// Every input changes only at a rising edge of its own clock (the CPU's
// request on s_clk_i, the RAM's answer on m_clk_i).  Reset as docs/rtl.md
// requires: s_rst_i and m_rst_i start high, each synchronous to its clock, and
// each falls (once, for good) only after the other domain has taken its reset
// on at least one edge.  ADDR_WIDTH is 3 and SYNC_STAGES 2 for tractability.
// DATA_MASK ties the data bits it leaves out to 0 on both sides (the RAM's
// answer and the CPU's write data): the bridge moves its 32 data bits side by
// side, each the same way, so the quick proof keeps one free bit per byte lane
// (32'h01010101, with ADDR_WIDTH 2) and the full-width proof keeps them all.
// The CPU side is checked as a Wishbone classic slave (formal/wb/fwb_slave.v,
// OPT_ABORT = 1: the CPU may abandon a request), the RAM side as a master
// (formal/wb/fwb_master.v, OPT_ABORT = 0: the bridge never abandons the RAM),
// against a free RAM that obeys the slave rules (answer at any time, or never).
// End-to-end property (label):
//   ack_match  when the CPU is acked, the last access the RAM side completed
//              is the CPU's present request (we, adr, sel; dat if a write) and,
//              for a read, s_dat_o is the data the RAM answered: an ack never
//              completes a request with another request's access or data
//              (a stale ack of an abandoned access is swallowed).
// Latency is not covered (it needs a fairness assumption on the clocks).
`default_nettype none

module fwb_cdc #(
    parameter ADDR_WIDTH  = 3,   // word-address bits
    parameter SYNC_STAGES = 2,   // flops per toggle synchroniser
    parameter DATA_MASK   = 32'hffffffff  // the data bits left free (the others tied to 0)
) (
    input  wire                  s_clk_i,
    input  wire                  s_rst_i,
    input  wire                  m_clk_i,
    input  wire                  m_rst_i,
    input  wire                  s_cyc_i,
    input  wire                  s_stb_i,
    input  wire                  s_we_i,
    input  wire [ADDR_WIDTH-1:0] s_adr_i,
    input  wire [3:0]            s_sel_i,
    input  wire [31:0]           s_dat_free_i,   // the CPU's write data, before DATA_MASK
    input  wire [31:0]           m_dat_free_i,   // the RAM's answer, before DATA_MASK
    input  wire                  m_ack_i
);

    wire [31:0] s_dat_i = s_dat_free_i & DATA_MASK;
    wire [31:0] m_dat_i = m_dat_free_i & DATA_MASK;

    wire [31:0]           s_dat_o, m_dat_o;
    wire                  s_ack_o, m_cyc_o, m_stb_o, m_we_o;
    wire [ADDR_WIDTH-1:0] m_adr_o;
    wire [3:0]            m_sel_o;

    albatross_wb_cdc #(.ADDR_WIDTH(ADDR_WIDTH), .SYNC_STAGES(SYNC_STAGES)) dut (
        .s_clk_i(s_clk_i), .s_rst_i(s_rst_i), .m_clk_i(m_clk_i), .m_rst_i(m_rst_i),
        .s_cyc_i(s_cyc_i), .s_stb_i(s_stb_i), .s_we_i(s_we_i), .s_adr_i(s_adr_i),
        .s_sel_i(s_sel_i), .s_dat_i(s_dat_i), .s_dat_o(s_dat_o), .s_ack_o(s_ack_o),
        .m_cyc_o(m_cyc_o), .m_stb_o(m_stb_o), .m_we_o(m_we_o), .m_adr_o(m_adr_o),
        .m_sel_o(m_sel_o), .m_dat_o(m_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i)
    );

`ifdef FORMAL
    // ------------------------------------------------- clocks, inputs, reset
    reg s_clk_q = 1'b0, m_clk_q = 1'b0;   // the clocks in the last global step
    reg s_rst_q = 1'b1, m_rst_q = 1'b1;
    reg [42+ADDR_WIDTH:0] s_in_q;
    reg [32:0]            m_in_q;
    reg s_took = 1'b0, m_took = 1'b0;     // the domain has had an edge in reset
    reg first = 1'b1;
    always @($global_clock) begin
        first   <= 1'b0;
        s_clk_q <= s_clk_i;
        m_clk_q <= m_clk_i;
        s_rst_q <= s_rst_i;
        m_rst_q <= m_rst_i;
        s_in_q  <= {s_cyc_i, s_stb_i, s_we_i, s_adr_i, s_sel_i, s_dat_i};
        m_in_q  <= {m_ack_i, m_dat_i};
        if (s_clk_i && !s_clk_q && s_rst_q) s_took <= 1'b1;
        if (m_clk_i && !m_clk_q && m_rst_q) m_took <= 1'b1;
    end
    wire s_edge = s_clk_i && !s_clk_q;
    wire m_edge = m_clk_i && !m_clk_q;
    always @* begin
        if (first) begin
            assume(s_rst_i && m_rst_i);
            assume(!s_clk_i && !m_clk_i);
        end else begin
            if (!s_edge) assume(s_rst_i == s_rst_q && {s_cyc_i, s_stb_i, s_we_i, s_adr_i, s_sel_i, s_dat_i} == s_in_q);
            if (!m_edge) assume(m_rst_i == m_rst_q && {m_ack_i, m_dat_i} == m_in_q);
            if (!s_rst_q) assume(!s_rst_i);            // reset once, at the start
            if (!m_rst_q) assume(!m_rst_i);
            if (s_rst_q && !s_rst_i) assume(m_took);   // each falls after the other side took it
            if (m_rst_q && !m_rst_i) assume(s_took);
        end
    end

    // ---------------------------------------------------- Wishbone, both sides
    wire       s_pv, s_out, s_rack, m_pv, m_out, m_rack;
    wire [3:0] s_wait, m_wait;
    fwb_slave #(.AW(ADDR_WIDTH), .DW(32), .OPT_ABORT(1)) wb_s (
        .clk_i(s_clk_i), .rst_i(s_rst_i), .cyc_i(s_cyc_i), .stb_i(s_stb_i), .we_i(s_we_i),
        .adr_i(s_adr_i), .sel_i(s_sel_i), .wdat_i(s_dat_i), .rdat_i(s_dat_o),
        .ack_i(s_ack_o), .err_i(1'b0),
        .f_past_valid_o(s_pv), .f_outstanding_o(s_out), .f_wait_o(s_wait), .f_read_ack_o(s_rack));
    fwb_master #(.AW(ADDR_WIDTH), .DW(32), .OPT_ABORT(0)) wb_m (
        .clk_i(m_clk_i), .rst_i(m_rst_i), .cyc_i(m_cyc_o), .stb_i(m_stb_o), .we_i(m_we_o),
        .adr_i(m_adr_o), .sel_i(m_sel_o), .wdat_i(m_dat_o), .rdat_i(m_dat_i),
        .ack_i(m_ack_i), .err_i(1'b0),
        .f_past_valid_o(m_pv), .f_outstanding_o(m_out), .f_wait_o(m_wait), .f_read_ack_o(m_rack));

    // ------------------------------------------------------------ ack_match
    // The last access the RAM side completed (recorded at its ack edge).
    reg                  l_valid = 1'b0;
    reg                  l_we;
    reg [ADDR_WIDTH-1:0] l_adr;
    reg [3:0]            l_sel;
    reg [31:0]           l_dat, l_rdat;
    always @(posedge m_clk_i) begin
        if (m_cyc_o && m_stb_o && m_ack_i && !m_rst_i) begin
            l_valid <= 1'b1;
            l_we    <= m_we_o;
            l_adr   <= m_adr_o;
            l_sel   <= m_sel_o;
            l_dat   <= m_dat_o;
            l_rdat  <= m_dat_i;
        end
    end
    wire s_req = s_cyc_i && s_stb_i;
    always @* begin
        if (!first && !s_rst_i && s_ack_o && s_req)
            ack_match: assert(l_valid && l_we == s_we_i && l_adr == s_adr_i && l_sel == s_sel_i &&
                              (s_we_i ? l_dat == s_dat_i : s_dat_o == l_rdat));
    end

    // ------------------------------------------------------------- covers
    reg [1:0] n_acks = 2'd0;   // CPU acks so far (saturating)
    always @(posedge s_clk_i) if (s_ack_o && s_req && n_acks != 2'd3) n_acks <= n_acks + 2'd1;
    always @* begin
        if (!first) begin
            cover_read:  cover(s_ack_o && s_req && !s_we_i);
            cover_two:   cover(n_acks == 2'd2);
        end
    end
`endif

endmodule

`default_nettype wire
