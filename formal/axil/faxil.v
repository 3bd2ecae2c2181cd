// faxil -- proof harness of albatross_dpram_axil (formal/axil/axil.sby,
// docs/verification.md "Formal proofs (RTL)").
//
// Port A (AXI4-Lite) is driven by a free master constrained only by
// formal/axil/faxil_slave.v, which asserts the slave's answers with the
// response bound of docs/rtl.md "albatross_dpram_axil" (F_MAX_WAIT_B = 5,
// F_MAX_WAIT_R = 4: BVALID low at most 5 clocks while a write is owed, RVALID
// at most 4 while a read is; clocks the master stalls an earlier response not
// counted) and at most 2 requests per channel accepted and unanswered
// (F_MAX_OUT = 2: one whose response waits, one held).  The covers show both
// bounds reached (cover_b_max, cover_r_max), so they are exact.  Port B (Wishbone B4 classic) is driven by a
// free master constrained by formal/wb/fwb_slave.v with the core's bound
// MAX_WAIT = 2, which therefore holds whatever the AXI side does.  Reset in
// the first clock only.  ADDR_WIDTH is 3 (8 words, 5-bit byte addresses).
// The script joins the probes f_n_* to the wrapper's native port A (adapter
// -> core; Yosys has no hierarchical references) after flatten.
// Properties besides the two property sets (labels):
//   n_stable     the adapter, a native master, holds req and its fields
//                until the ack.
//   wr_fields    a native write of port A carries the address, the byte
//                enables (= WSTRB) and the enabled bytes of the AXI write
//                whose AW and W were accepted (the record of the last ones).
//   rd_addr      a native read of port A reads the word of the accepted AR.
//   wr_once, rd_once  one native access per AXI request: a native write
//                (read) only for an owed AXI write (read) not yet performed.
//   b_after, r_after  BVALID / RVALID only after the native access was done.
//   rd_data      RDATA is the word the native read returned.
//   atomicity_a/b  byte atomicity and write-data correctness against a shadow
//                of one symbolic word fa (as formal/dpram/fdpram.v): each byte
//                lane holds the data of the last write acknowledged to it by
//                either port (port A's data taken from the AXI write record,
//                so a lost or misrouted lane is caught), and a read of either
//                port returns exactly that byte in every lane.
//   one_ack      native acks of the two ports never in one clock.
//   resp_okay    BRESP and RRESP are OKAY.
//   ready_idle   AWREADY, WREADY, ARREADY are low only while a request of that
//                channel is accepted and unanswered (no other stall).
// Induction strengthening (white-box, -DF_PROBE): the RAM word fa, the slot and
// the read register, and the inv_* invariants.
`default_nettype none

module faxil #(
    parameter ADDR_WIDTH = 3   // word-address bits of the RAM under proof
) (
    input  wire                  clk_i,
    input  wire                  rst_i,
    input  wire                  awvalid_i,
    input  wire [ADDR_WIDTH+1:0] awaddr_i,
    input  wire [2:0]            awprot_i,
    input  wire                  wvalid_i,
    input  wire [31:0]           wdata_i,
    input  wire [3:0]            wstrb_i,
    input  wire                  bready_i,
    input  wire                  arvalid_i,
    input  wire [ADDR_WIDTH+1:0] araddr_i,
    input  wire [2:0]            arprot_i,
    input  wire                  rready_i,
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i
);

    wire        awready, wready, bvalid, arready, rvalid, b_ack_o;
    wire [1:0]  bresp, rresp;
    wire [31:0] rdata, b_dat_o;

    albatross_dpram_axil #(.ADDR_WIDTH(ADDR_WIDTH)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .s_axi_awvalid_i(awvalid_i), .s_axi_awready_o(awready), .s_axi_awaddr_i(awaddr_i),
        .s_axi_awprot_i(awprot_i), .s_axi_wvalid_i(wvalid_i), .s_axi_wready_o(wready),
        .s_axi_wdata_i(wdata_i), .s_axi_wstrb_i(wstrb_i), .s_axi_bvalid_o(bvalid),
        .s_axi_bready_i(bready_i), .s_axi_bresp_o(bresp), .s_axi_arvalid_i(arvalid_i),
        .s_axi_arready_o(arready), .s_axi_araddr_i(araddr_i), .s_axi_arprot_i(arprot_i),
        .s_axi_rvalid_o(rvalid), .s_axi_rready_i(rready_i), .s_axi_rdata_o(rdata),
        .s_axi_rresp_o(rresp),
        .b_cyc_i(b_cyc_i), .b_stb_i(b_stb_i), .b_we_i(b_we_i), .b_adr_i(b_adr_i),
        .b_sel_i(b_sel_i), .b_dat_i(b_dat_i), .b_dat_o(b_dat_o), .b_ack_o(b_ack_o)
    );

`ifdef FORMAL
    // ---------------------------------------------------------------- reset
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);

    // -------------------------------------------------------- property sets
    wire       past_valid;
    wire [3:0] aw_out, w_out, ar_out, b_wait, r_wait;
    faxil_slave #(.AW(ADDR_WIDTH + 2), .DW(32), .F_LGDEPTH(4), .F_MAX_OUT(2),
                  .F_MAX_WAIT_B(5), .F_MAX_WAIT_R(4)) axil_a (
        .clk_i(clk_i), .rst_i(rst_i),
        .awvalid_i(awvalid_i), .awready_i(awready), .awaddr_i(awaddr_i), .awprot_i(awprot_i),
        .wvalid_i(wvalid_i), .wready_i(wready), .wdata_i(wdata_i), .wstrb_i(wstrb_i),
        .bvalid_i(bvalid), .bready_i(bready_i), .bresp_i(bresp),
        .arvalid_i(arvalid_i), .arready_i(arready), .araddr_i(araddr_i), .arprot_i(arprot_i),
        .rvalid_i(rvalid), .rready_i(rready_i), .rdata_i(rdata), .rresp_i(rresp),
        .f_past_valid_o(past_valid), .f_aw_out_o(aw_out), .f_w_out_o(w_out), .f_ar_out_o(ar_out),
        .f_b_wait_o(b_wait), .f_r_wait_o(r_wait));
    wire       b_past_valid, b_out, b_rack;
    wire [3:0] b_wait_wb;
    fwb_slave #(.AW(ADDR_WIDTH), .DW(32), .MAX_WAIT(2)) wb_b (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(b_cyc_i), .stb_i(b_stb_i), .we_i(b_we_i),
        .adr_i(b_adr_i), .sel_i(b_sel_i), .wdat_i(b_dat_i), .rdat_i(b_dat_o),
        .ack_i(b_ack_o), .err_i(1'b0),
        .f_past_valid_o(b_past_valid), .f_outstanding_o(b_out), .f_wait_o(b_wait_wb), .f_read_ack_o(b_rack));

    // ------------------------------------------- probes: native port A
    (* keep *) wire                  f_n_req, f_n_we, f_n_ack;
    (* keep *) wire [ADDR_WIDTH-1:0] f_n_adr;
    (* keep *) wire [3:0]            f_n_be;
    (* keep *) wire [31:0]           f_n_wdata, f_n_rdata;

    // The AXI requests as accepted (one in flight per channel: s_max_out).
    reg [ADDR_WIDTH-1:0] rec_aw, rec_ar;
    reg [31:0]           rec_wd;
    reg [3:0]            rec_ws;
    always @(posedge clk_i) begin
        if (awvalid_i && awready) rec_aw <= awaddr_i[ADDR_WIDTH+1:2];
        if (wvalid_i && wready) begin
            rec_wd <= wdata_i;
            rec_ws <= wstrb_i;
        end
        if (arvalid_i && arready) rec_ar <= araddr_i[ADDR_WIDTH+1:2];
    end
    wire [31:0] strb_mask = {{8{rec_ws[3]}}, {8{rec_ws[2]}}, {8{rec_ws[1]}}, {8{rec_ws[0]}}};

    wire n_wr_ack = f_n_ack && f_n_we;
    wire n_rd_ack = f_n_ack && !f_n_we;
    reg  wr_done = 1'b0, rd_done = 1'b0;   // the owed request's native access is done
    reg  [31:0] rd_val;                    // the word it returned
    reg  p_req = 1'b0, p_ack, p_we;
    reg  [ADDR_WIDTH-1:0] p_adr;
    reg  [3:0]  p_be;
    reg  [31:0] p_wdata;
    always @(posedge clk_i) begin
        p_req <= f_n_req && !rst_i; p_ack <= f_n_ack; p_we <= f_n_we; p_adr <= f_n_adr;
        p_be <= f_n_be; p_wdata <= f_n_wdata;
        if (rst_i || (bvalid && bready_i)) wr_done <= 1'b0;
        else if (n_wr_ack)                 wr_done <= 1'b1;
        if (rst_i || (rvalid && rready_i)) rd_done <= 1'b0;
        else if (n_rd_ack)                 rd_done <= 1'b1;
        if (n_rd_ack) rd_val <= f_n_rdata;
    end
    wire b_owed = aw_out != 4'd0 && w_out != 4'd0;
    wire r_owed = ar_out != 4'd0;

    always @* begin
        if (!init_q) begin
            if (p_req && !p_ack)
                n_stable: assert(f_n_req && f_n_we == p_we && f_n_adr == p_adr &&
                                 (!f_n_we || (f_n_be == p_be && f_n_wdata == p_wdata)));
            if (n_wr_ack) begin
                wr_fields: assert(f_n_adr == rec_aw && f_n_be == rec_ws &&
                                  (f_n_wdata & strb_mask) == (rec_wd & strb_mask));
                wr_once:   assert(b_owed && !wr_done);
            end
            if (n_rd_ack) begin
                rd_addr:   assert(f_n_adr == rec_ar);
                rd_once:   assert(r_owed && !rd_done);
            end
            if (bvalid) b_after: assert(wr_done);
            if (rvalid) begin
                r_after: assert(rd_done);
                rd_data: assert(rdata == rd_val);
            end
            resp_okay:  assert((!bvalid || bresp == 2'b00) && (!rvalid || rresp == 2'b00));
            one_ack:    assert(!(f_n_ack && b_ack_o));
            ready_idle: assert((awready || aw_out != 4'd0) && (wready || w_out != 4'd0) &&
                               (arready || ar_out != 4'd0));
        end
    end

    // --------------------------------------------------------- byte atomicity
    (* anyconst *) reg [ADDR_WIDTH-1:0] fa;   // the symbolic word
    reg [3:0]  sh_valid = 4'd0;
    reg [31:0] sh_word;
    wire a_hit = f_n_ack && f_n_adr == fa;
    wire b_hit = b_ack_o && b_adr_i == fa;
    wire [3:0] a_wr = {4{a_hit && f_n_we}} & rec_ws;   // lanes written (AXI's strobes), acked now
    wire [3:0] b_wr = {4{b_hit && b_we_i}} & b_sel_i;
    wire a_rd = a_hit && !f_n_we;
    wire b_rd = b_hit && !b_we_i;
    wire [3:0] a_ok, b_ok;
    genvar l;
    generate for (l = 0; l < 4; l = l + 1) begin : lane
        wire [7:0] sh = sh_word[8*l +: 8];
        wire [7:0] ar = f_n_rdata[8*l +: 8];
        wire [7:0] br = b_dat_o[8*l +: 8];
        assign a_ok[l] = !(a_rd && sh_valid[l]) || ar == sh;
        assign b_ok[l] = !(b_rd && sh_valid[l]) || br == sh;
        always @(posedge clk_i) begin
            if (!init_q) begin
                if (a_wr[l] || b_wr[l]) begin
                    sh_valid[l]       <= 1'b1;
                    sh_word[8*l +: 8] <= a_wr[l] ? rec_wd[8*l +: 8] : b_dat_i[8*l +: 8];
                end else if (!sh_valid[l] && (a_rd || b_rd)) begin
                    sh_valid[l]       <= 1'b1;
                    sh_word[8*l +: 8] <= a_rd ? ar : br;
                end
            end
        end
    end endgenerate
    always @* begin
        if (!init_q) begin
            atomicity_a: assert(&a_ok);
            atomicity_b: assert(&b_ok);
        end
    end

    // ------------------------------------------------ induction strengthening
`ifdef F_PROBE
    (* keep *) wire [32*(1<<ADDR_WIDTH)-1:0] f_mem;   // dut.u_core.mem[0..]
    (* keep *) wire        f_slot;                    // dut.u_core.slot_q
    (* keep *) wire [ADDR_WIDTH-1:0] f_aw_adr, f_ar_adr; // dut.u_axil.aw_adr_q, ar_adr_q
    (* keep *) wire [31:0] f_w_data;                  // dut.u_axil.w_data_q
    (* keep *) wire [3:0]  f_w_strb;                  // dut.u_axil.w_strb_q
    wire [31:0] f_mem_word = f_mem[32*fa +: 32];
    wire [3:0]  ack_wr  = a_wr | b_wr;
    wire [31:0] ack_dat = f_n_ack ? rec_wd : b_dat_i;
    wire [3:0]  sh_ok;
    generate for (l = 0; l < 4; l = l + 1) begin : inv_lane
        assign sh_ok[l] = !sh_valid[l] ||
                          f_mem_word[8*l +: 8] == (ack_wr[l] ? ack_dat[8*l +: 8] : sh_word[8*l +: 8]);
    end endgenerate
    always @* begin
        if (!init_q) begin
            inv_shadow: assert(&sh_ok);
            inv_ack_a:  assert(!f_n_ack || (f_n_req && f_slot));
            inv_ack_b:  assert(!b_ack_o || (b_out && !f_slot));
            inv_wait_b: assert(b_wait_wb <= 4'd2 && (b_wait_wb != 4'd2 || b_ack_o) &&
                               (b_wait_wb != 4'd1 || b_ack_o || f_slot));
            inv_rdata:  assert(!a_rd || f_n_rdata == f_mem_word);
            inv_rdata_b: assert(!b_rd || b_dat_o == f_mem_word);
            // the adapter's state, seen through its outputs and the records
            // a held request is the accepted one; the one in flight is held
            inv_hold_aw: assert(awready || f_aw_adr == rec_aw);
            inv_hold_w:  assert(wready || (f_w_data == rec_wd && f_w_strb == rec_ws));
            inv_hold_ar: assert(arready || f_ar_adr == rec_ar);
            inv_req:     assert(!f_n_req || (f_n_we ? (!awready && !wready) : !arready));
            // the outstanding counts are the held request plus the pending response;
            // the native access is done exactly while the response is pending
            inv_aw_out:  assert(aw_out == {3'd0, !awready} + {3'd0, bvalid});
            inv_w_out:   assert(w_out  == {3'd0, !wready}  + {3'd0, bvalid});
            inv_ar_out:  assert(ar_out == {3'd0, !arready} + {3'd0, rvalid});
            inv_wr_done: assert(wr_done == bvalid);
            inv_rd_done: assert(rd_done == rvalid && (!rvalid || rdata == rd_val));
            inv_busy:    assert(!f_n_req || (f_n_we ? !bvalid : !rvalid));
            // the response bound, stepwise: a complete write not in flight waits
            // only for a read in flight, at most 2 clocks; in flight, it is acked
            // by its 4th clock after the handshake, in its own slot after the 3rd
            inv_b_wait:  assert(!(b_owed && !bvalid) ||
                                (f_n_req && f_n_we ? (b_wait <= 4'd4 && (b_wait != 4'd4 || f_n_ack) &&
                                                      (b_wait != 4'd3 || f_n_ack || !f_slot))
                                                   : (f_n_req && b_wait <= 4'd2 &&
                                                      (b_wait != 4'd2 || f_n_ack))));
            // reads go first, so a read waits only for a write started earlier
            inv_r_wait:  assert(!(r_owed && !rvalid) ||
                                (f_n_req && !f_n_we ? (r_wait <= 4'd3 && (r_wait != 4'd3 || f_n_ack) &&
                                                       (r_wait != 4'd2 || f_n_ack || !f_slot))
                                                    : (f_n_req && r_wait <= 4'd1 &&
                                                       (r_wait != 4'd1 || f_n_ack))));
        end
    end
`endif

    // ------------------------------------------------------ non-vacuity covers
    always @* begin
        if (!init_q) begin
            cover_b_stall:  cover(bvalid && !bready_i && awvalid_i && wvalid_i);
            cover_r_max:    cover(r_wait == 4'd4);
            cover_b_max:    cover(b_wait == 4'd5);
            cover_read_a:   cover(a_rd && sh_valid == 4'hF);
            cover_w_first:  cover(wvalid_i && wready && !awvalid_i);
        end
    end
`endif

endmodule

`default_nettype wire
