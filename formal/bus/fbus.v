// fbus -- proof harness of albatross_bus (formal/bus/bus.sby,
// docs/verification.md "Formal proofs (RTL)").
//
// The harness gives the bus a reset in the first clock only (the bus has
// none; its one register, the answering board, needs none).  The master side
// is checked as a Wishbone classic slave (formal/wb/fwb_slave.v: any master
// that obeys the rules), each board's side as a master (formal/wb/fwb_master.v:
// any board that obeys the slave rules, answering with ack or err within
// MAX_WAIT = 2 clocks as albatross_dpram's port B does, so the bus must pass
// that bound on).  Boards answer registered, as the bus requires: never in a
// request's first clock (board_registered, an assumption).
// NB = 3 boards, so board numbers 3..15 exist in the address but not on the
// bus; ADDR_WIDTH = 3.  Routing properties (labels):
//   route_cyc     cyc and stb reach only the addressed board.
//   route_fields  every board sees the master's we, adr (word part), sel, dat.
//   route_answer  for an existing board, ack and err are that board's, and
//                 so is dat with an ack.
//   err_absent    a request to a board >= NB is answered with err in its
//                 second clock (pending since an earlier clock) ...
//   absent_late   ... and never in its first.
//   ack_selected  ack only when an existing board is addressed.
`default_nettype none

module fbus #(
    parameter NB         = 3,   // boards
    parameter ADDR_WIDTH = 3    // word-address bits of a board RAM
) (
    input  wire                     clk_i,
    input  wire                     rst_i,
    input  wire                     m_cyc_i,
    input  wire                     m_stb_i,
    input  wire                     m_we_i,
    input  wire [ADDR_WIDTH+3:0]    m_adr_i,
    input  wire [3:0]               m_sel_i,
    input  wire [31:0]              m_dat_i,
    input  wire [NB*32-1:0]         s_dat_i,
    input  wire [NB-1:0]            s_ack_i,
    input  wire [NB-1:0]            s_err_i
);

    wire [31:0]            m_dat_o;
    wire                   m_ack_o, m_err_o;
    wire [NB-1:0]          s_cyc_o, s_stb_o, s_we_o;
    wire [NB*ADDR_WIDTH-1:0] s_adr_o;
    wire [NB*4-1:0]        s_sel_o;
    wire [NB*32-1:0]       s_dat_o;

    albatross_bus #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) dut (
        .clk_i(clk_i), .m_cyc_i(m_cyc_i), .m_stb_i(m_stb_i), .m_we_i(m_we_i), .m_adr_i(m_adr_i),
        .m_sel_i(m_sel_i), .m_dat_i(m_dat_i), .m_dat_o(m_dat_o), .m_ack_o(m_ack_o),
        .m_err_o(m_err_o),
        .s_cyc_o(s_cyc_o), .s_stb_o(s_stb_o), .s_we_o(s_we_o), .s_adr_o(s_adr_o),
        .s_sel_o(s_sel_o), .s_dat_o(s_dat_o), .s_dat_i(s_dat_i), .s_ack_i(s_ack_i),
        .s_err_i(s_err_i)
    );

`ifdef FORMAL
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);

    wire       m_pv, m_out, m_rack;
    wire [3:0] m_wait;
    fwb_slave #(.AW(ADDR_WIDTH+4), .DW(32), .MAX_WAIT(2)) wb_m (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(m_cyc_i), .stb_i(m_stb_i), .we_i(m_we_i),
        .adr_i(m_adr_i), .sel_i(m_sel_i), .wdat_i(m_dat_i), .rdat_i(m_dat_o),
        .ack_i(m_ack_o), .err_i(m_err_o),
        .f_past_valid_o(m_pv), .f_outstanding_o(m_out), .f_wait_o(m_wait), .f_read_ack_o(m_rack));

    wire [NB-1:0] registered;
    genvar b;
    generate for (b = 0; b < NB; b = b + 1) begin : board
        wire       pv, out, rack;
        wire [3:0] wt;
        fwb_master #(.AW(ADDR_WIDTH), .DW(32), .MAX_WAIT(2)) wb (
            .clk_i(clk_i), .rst_i(rst_i), .cyc_i(s_cyc_o[b]), .stb_i(s_stb_o[b]), .we_i(s_we_o[b]),
            .adr_i(s_adr_o[b*ADDR_WIDTH +: ADDR_WIDTH]), .sel_i(s_sel_o[b*4 +: 4]),
            .wdat_i(s_dat_o[b*32 +: 32]), .rdat_i(s_dat_i[b*32 +: 32]),
            .ack_i(s_ack_i[b]), .err_i(s_err_i[b]),
            .f_past_valid_o(pv), .f_outstanding_o(out), .f_wait_o(wt), .f_read_ack_o(rack));
        // A registered board: an answer only to a request pending since an earlier clock.
        assign registered[b] = !(s_ack_i[b] || s_err_i[b]) || out;
    end endgenerate
    always @* if (!init_q) board_registered: assume(&registered);

    // ----------------------------------------------------------- routing
    wire [3:0] brd = m_adr_i[ADDR_WIDTH +: 4];
    wire       req = m_cyc_i & m_stb_i;
    reg  ok_cyc, ok_fields, ok_answer;
    reg  b_ack, b_err;     // the addressed board's answer (0 for an absent board)
    reg  [31:0] b_dat;
    integer i;
    always @* begin
        ok_cyc = 1'b1;
        b_ack = 1'b0;
        b_err = 1'b0;
        b_dat = 32'd0;
        ok_fields = 1'b1;
        for (i = 0; i < NB; i = i + 1) begin
            if ((s_cyc_o[i] || s_stb_o[i]) && brd != i) ok_cyc = 1'b0;
            if (brd == i && (s_cyc_o[i] != m_cyc_i || s_stb_o[i] != m_stb_i)) ok_cyc = 1'b0;
            if (s_we_o[i] != m_we_i || s_adr_o[i*ADDR_WIDTH +: ADDR_WIDTH] != m_adr_i[ADDR_WIDTH-1:0] ||
                s_sel_o[i*4 +: 4] != m_sel_i || s_dat_o[i*32 +: 32] != m_dat_i) ok_fields = 1'b0;
            if (brd == i) begin
                b_ack = s_ack_i[i];
                b_err = s_err_i[i];
                b_dat = s_dat_i[i*32 +: 32];
            end
        end
        ok_answer = brd >= NB || (m_ack_o == b_ack && m_err_o == b_err && (!b_ack || m_dat_o == b_dat));
    end
    always @* begin
        if (!init_q) begin
            route_cyc:    assert(ok_cyc);
            route_fields: assert(ok_fields);
            route_answer: assert(ok_answer);
            err_absent:   assert(!(req && brd >= NB && m_out) || m_err_o);
            absent_late:  assert(!(req && brd >= NB && !m_out) || !m_err_o);
            ack_selected: assert(!m_ack_o || brd < NB);
        end
    end

    always @* begin
        if (!init_q) begin
            cover_ack:  cover(req && m_ack_o && brd == NB-1);
            cover_err:  cover(req && m_err_o && brd >= NB);
        end
    end
`endif

endmodule

`default_nettype wire
