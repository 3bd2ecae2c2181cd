// albatross_axil2native -- AXI4-Lite slave to native request/acknowledge port
// (ALBATROSS; docs/rtl.md "albatross_dpram_axil").
//
// A generic front-end: one AXI4-Lite slave (32-bit data, byte addresses) in,
// one native port of albatross_dpram_core out (req held with stable fields
// until a one-clock ack, read data in the ack clock).  Rules:
//   * Channels.  AW, W and AR each have a one-entry holding register; a
//     channel is ready exactly when its register is empty (ready never depends
//     on valid: no combinational path through the adapter).  AW and W are
//     accepted independently, in either order or together; a write goes to
//     the native port once both are held.
//   * One native access at a time.  A write starts when its AW and W are held
//     and the B register is free (or emptied at this edge), a read when its
//     AR is held and the R register is free (or emptied at this edge); the
//     native port must be idle or acknowledging at this edge.  If both could
//     start, the read goes first.  Neither kind can starve the other: a
//     channel's holding register is released only at its access's ack, so
//     when an access ends no second one of the same kind is ready to follow.
//     The start is at the same edge as the last handshake: no extra clock.
//   * Responses.  At the native ack the held request is released (its ready
//     rises in the next clock) and BVALID or RVALID rises in the next clock,
//     held with its data until the master's BREADY / RREADY handshake.  BRESP
//     and RRESP are always OKAY: every address is a RAM word (the interconnect
//     decodes the window; inside it the word address wraps modulo the RAM
//     size), so there is no error to report.  AxPROT is ignored.
//   * Byte lanes.  WSTRB bit n is the byte enable of lane n (bits 8n+7:8n); a
//     write with WSTRB = 0 is performed as a no-op access and answered OKAY.
//     The word address is AxADDR[ADDR_WIDTH+1:2]; AxADDR[1:0] are ignored
//     (AXI4-Lite: the strobes say which bytes are written; reads return the
//     whole word).
//   * Latency (native access bound NAT clocks from req to ack; 2 for
//     albatross_dpram_core): with its response channel free, BVALID rises at
//     most 2 * NAT + 1 clocks after the edge of the handshake that completed
//     the write (a read may go first), RVALID at most 2 * NAT after the AR
//     handshake (reads go first, so a read waits only for a write already
//     started); at least 2 clocks.  Clocks in which an earlier B (R) waits for
//     the master's BREADY (RREADY) come on top, nothing else.
//   * Throughput: one access per 3 to 4 clocks per direction with BREADY /
//     RREADY high (the holding register is released at the ack).
//   * Reset (synchronous, active high) empties every register and drops req.
`default_nettype none

module albatross_axil2native #(
    parameter ADDR_WIDTH = 10  // native word-address bits (AXI byte address: ADDR_WIDTH + 2 bits)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,            // synchronous, active high
    // AXI4-Lite slave
    input  wire                  s_axi_awvalid_i,
    output wire                  s_axi_awready_o,
    input  wire [ADDR_WIDTH+1:0] s_axi_awaddr_i,
    input  wire [2:0]            s_axi_awprot_i,   // ignored
    input  wire                  s_axi_wvalid_i,
    output wire                  s_axi_wready_o,
    input  wire [31:0]           s_axi_wdata_i,
    input  wire [3:0]            s_axi_wstrb_i,
    output wire                  s_axi_bvalid_o,
    input  wire                  s_axi_bready_i,
    output wire [1:0]            s_axi_bresp_o,
    input  wire                  s_axi_arvalid_i,
    output wire                  s_axi_arready_o,
    input  wire [ADDR_WIDTH+1:0] s_axi_araddr_i,
    input  wire [2:0]            s_axi_arprot_i,   // ignored
    output wire                  s_axi_rvalid_o,
    input  wire                  s_axi_rready_i,
    output wire [31:0]           s_axi_rdata_o,
    output wire [1:0]            s_axi_rresp_o,
    // native request/acknowledge master
    output wire                  n_req_o,
    output wire                  n_we_o,
    output wire [ADDR_WIDTH-1:0] n_adr_o,
    output wire [3:0]            n_be_o,
    output wire [31:0]           n_wdata_o,
    input  wire [31:0]           n_rdata_i,
    input  wire                  n_ack_i
);

    // Holding registers (one per request channel) and their fill flags.
    reg                  aw_full_q, w_full_q, ar_full_q;
    reg [ADDR_WIDTH-1:0] aw_adr_q, ar_adr_q;
    reg [31:0]           w_data_q;
    reg [3:0]            w_strb_q;
    // The native access in flight, and the response registers.
    reg                  req_q, req_we_q;
    reg                  bvalid_q, rvalid_q;
    reg [31:0]           rdata_q;

    wire aw_hs = s_axi_awvalid_i & ~aw_full_q;
    wire w_hs  = s_axi_wvalid_i  & ~w_full_q;
    wire ar_hs = s_axi_arvalid_i & ~ar_full_q;
    wire done  = req_q & n_ack_i;            // the access in flight ends at this edge
    wire n_free = ~req_q | n_ack_i;          // the native port takes a new req after this edge
    // A request is complete once its handshakes are done (now or earlier);
    // the one in flight is not a candidate.
    wire wr_can = (aw_full_q | aw_hs) & (w_full_q | w_hs) & ~(req_q & req_we_q)
                & (~bvalid_q | s_axi_bready_i);
    wire rd_can = (ar_full_q | ar_hs) & ~(req_q & ~req_we_q)
                & (~rvalid_q | s_axi_rready_i);
    wire start    = n_free & (wr_can | rd_can);
    wire start_we = wr_can & ~rd_can;

    always @(posedge clk_i) begin
        if (rst_i) begin
            aw_full_q  <= 1'b0;
            w_full_q   <= 1'b0;
            ar_full_q  <= 1'b0;
            req_q      <= 1'b0;
            req_we_q   <= 1'b0;
            bvalid_q   <= 1'b0;
            rvalid_q   <= 1'b0;
        end else begin
            if (aw_hs)
                aw_full_q <= 1'b1;
            else if (done & req_we_q)
                aw_full_q <= 1'b0;
            if (w_hs)
                w_full_q <= 1'b1;
            else if (done & req_we_q)
                w_full_q <= 1'b0;
            if (ar_hs)
                ar_full_q <= 1'b1;
            else if (done & ~req_we_q)
                ar_full_q <= 1'b0;
            if (start) begin
                req_q      <= 1'b1;
                req_we_q   <= start_we;
            end else if (done) begin
                req_q      <= 1'b0;
            end
            if (done & req_we_q)
                bvalid_q <= 1'b1;
            else if (s_axi_bready_i)
                bvalid_q <= 1'b0;
            if (done & ~req_we_q)
                rvalid_q <= 1'b1;
            else if (s_axi_rready_i)
                rvalid_q <= 1'b0;
        end
    end

    // Payload registers: no reset (qualified by the flags above).
    always @(posedge clk_i) begin
        if (aw_hs)
            aw_adr_q <= s_axi_awaddr_i[ADDR_WIDTH+1:2];
        if (w_hs) begin
            w_data_q <= s_axi_wdata_i;
            w_strb_q <= s_axi_wstrb_i;
        end
        if (ar_hs)
            ar_adr_q <= s_axi_araddr_i[ADDR_WIDTH+1:2];
        if (done & ~req_we_q) rdata_q <= n_rdata_i;
    end

    assign s_axi_awready_o = ~aw_full_q;
    assign s_axi_wready_o  = ~w_full_q;
    assign s_axi_arready_o = ~ar_full_q;
    assign s_axi_bvalid_o  = bvalid_q;
    assign s_axi_bresp_o   = 2'b00;            // OKAY
    assign s_axi_rvalid_o  = rvalid_q;
    assign s_axi_rdata_o   = rdata_q;
    assign s_axi_rresp_o   = 2'b00;            // OKAY

    assign n_req_o   = req_q;
    assign n_we_o    = req_we_q;
    assign n_adr_o   = req_we_q ? aw_adr_q : ar_adr_q;
    assign n_be_o    = req_we_q ? w_strb_q : 4'h0;
    assign n_wdata_o = w_data_q;

    // AxPROT and the byte offset AxADDR[1:0] carry nothing for a RAM.
    wire unused_ok = &{1'b0, s_axi_awprot_i, s_axi_arprot_i, s_axi_awaddr_i[1:0], s_axi_araddr_i[1:0]};

endmodule

`default_nettype wire
