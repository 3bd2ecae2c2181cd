// albatross_wb_cdc -- Wishbone B4 classic clock-domain-crossing bridge (ALBATROSS).
//
// Lets a CPU on its own clock (slave side: s_clk_i, s_rst_i) use one port of
// albatross_dpram, which runs on the RAM clock (master side: m_clk_i, m_rst_i).
// The two clocks are fully independent.  Rules:
//   * Handshake: one access at a time, carried by a toggle pair.  The CPU side
//     registers the request (we, adr, sel, dat) and flips req_tog_q; the RAM
//     side sees the flip through SYNC_STAGES flops, copies the request, runs
//     one Wishbone cycle on the RAM, holds the read data in rdat_q and flips
//     ack_tog_q; the CPU side sees that flip through SYNC_STAGES flops and acks
//     for one cycle with the held data.  Only the two toggles are synchronised.
//     The request fields stay unchanged from the flip of req_tog_q until the
//     CPU side has seen ack_tog_q, and rdat_q from the flip of ack_tog_q until
//     the next request, so no multi-bit value is ever sampled while it changes.
//     (Constrain req_*_q -> m_*_q and rdat_q -> s_dat_q as datapath-only
//     max-delay paths of at most SYNC_STAGES-1 periods of the receiving clock.)
//   * Latency bound, N = SYNC_STAGES, Ts and Tm the longest s_clk_i and m_clk_i
//     periods during the access, measured from the s_clk_i edge after which
//     the CPU raises stb to the s_clk_i edge at which it samples ack:
//         L <= (N + 4) * Ts + (N + 5) * Tm            (N = 2: 6 Ts + 7 Tm)
//     and, if the CPU abandoned its previous request (see below):
//         L <= (2N + 4) * Ts + (2N + 10) * Tm         (N = 2: 8 Ts + 14 Tm)
//     Terms: 1 Ts to register the request; (N + 2) Tm to synchronise it (one
//     period for a metastable first capture) and register it on the RAM bus;
//     3 Tm for albatross_dpram (its access time is 1-2 cycles whatever the
//     other port does); (N + 3) Ts to synchronise the ack, register it and have
//     it sampled.  The abandoned access can delay a new one by at most one more
//     access time.  No term depends on the other RAM port.
//   * Abandon: the CPU may withdraw a request by dropping cyc (or stb) for at
//     least one s_clk_i edge, e.g. on a crash or a reset of the CPU alone.  An
//     access already handed to the RAM side still completes there, and its ack
//     is swallowed; a new request is accepted only after that, so a stale ack
//     can never complete a later request.  A write that was withdrawn may or
//     may not have been performed.  Changing a request while holding cyc and
//     stb high, without such a gap, breaks Wishbone and is not detected.
//   * Reset: s_rst_i and m_rst_i (synchronous, active high) are one bridge
//     reset, e.g. a system reset synchronised into each domain: each must stay
//     asserted until the other domain has taken it on at least one clock edge.
//     Never reset one side alone (a CPU-only reset is handled as an abandon).
//     Reset clears control state only, never the data registers.
`default_nettype none

module albatross_wb_cdc #(
    parameter ADDR_WIDTH  = 10,  // word-address bits, as albatross_dpram's ADDR_WIDTH
    parameter SYNC_STAGES = 2    // flops per toggle synchroniser, at least 2
) (
    input  wire                  s_clk_i,   // CPU clock
    input  wire                  s_rst_i,   // synchronous to s_clk_i, active high
    input  wire                  m_clk_i,   // RAM clock
    input  wire                  m_rst_i,   // synchronous to m_clk_i, active high
    // CPU side: Wishbone B4 classic slave, on s_clk_i
    input  wire                  s_cyc_i,
    input  wire                  s_stb_i,
    input  wire                  s_we_i,
    input  wire [ADDR_WIDTH-1:0] s_adr_i,
    input  wire [3:0]            s_sel_i,
    input  wire [31:0]           s_dat_i,
    output wire [31:0]           s_dat_o,
    output wire                  s_ack_o,
    // RAM side: Wishbone B4 classic master, on m_clk_i
    output wire                  m_cyc_o,
    output wire                  m_stb_o,
    output wire                  m_we_o,
    output wire [ADDR_WIDTH-1:0] m_adr_o,
    output wire [3:0]            m_sel_o,
    output wire [31:0]           m_dat_o,
    input  wire [31:0]           m_dat_i,
    input  wire                  m_ack_i
);

    // A synchroniser needs two flops at least: stop elaboration otherwise.
    generate
        if (SYNC_STAGES < 2) begin : g_sync_stages_check
            albatross_wb_cdc_SYNC_STAGES_must_be_at_least_2 u_error ();
        end
    endgenerate

    // ---------------------------------------------------------------- CPU side
    reg                  req_tog_q;  // flips once per request handed to the RAM side
    reg                  req_we_q;   // request fields, stable while req_tog_q crosses
    reg [ADDR_WIDTH-1:0] req_adr_q;
    reg [3:0]            req_sel_q;
    reg [31:0]           req_dat_q;
    (* ASYNC_REG = "TRUE" *)
    reg [SYNC_STAGES-1:0] ack_sync_q;  // ack_tog_q synchroniser, [SYNC_STAGES-1] is safe
    reg                  wait_q;     // the CPU still waits for the access in flight
    reg                  s_ack_q;
    reg [31:0]           s_dat_q;

    // --------------------------------------------------------------- RAM side
    (* ASYNC_REG = "TRUE" *)
    reg [SYNC_STAGES-1:0] req_sync_q;  // req_tog_q synchroniser, [SYNC_STAGES-1] is safe
    reg                  ack_tog_q;  // toggle value of the last request served
    reg                  m_stb_q;    // RAM bus cycle in progress
    reg                  m_we_q;
    reg [ADDR_WIDTH-1:0] m_adr_q;
    reg [3:0]            m_sel_q;
    reg [31:0]           m_dat_q;
    reg [31:0]           rdat_q;     // read data, stable while ack_tog_q crosses

    // CPU side next state.
    wire s_req    = s_cyc_i & s_stb_i;                       // the CPU presents a request
    wire s_busy   = req_tog_q ^ ack_sync_q[SYNC_STAGES-1];   // an access is in flight
    wire s_accept = s_req & ~s_busy & ~wait_q & ~s_ack_q;    // hand it over at this edge
    // Ack only if the CPU has held its request all along; else swallow.
    wire s_ack_d  = s_req & wait_q & ~s_busy;
    wire wait_d   = s_accept | (s_req & wait_q & s_busy);

    always @(posedge s_clk_i) begin
        if (s_rst_i) begin
            req_tog_q  <= 1'b0;
            ack_sync_q <= {SYNC_STAGES{1'b0}};
            wait_q     <= 1'b0;
            s_ack_q    <= 1'b0;
        end else begin
            req_tog_q  <= req_tog_q ^ s_accept;
            ack_sync_q <= {ack_sync_q[SYNC_STAGES-2:0], ack_tog_q};
            wait_q     <= wait_d;
            s_ack_q    <= s_ack_d;
        end
    end

    always @(posedge s_clk_i) begin
        if (s_accept) begin
            req_we_q  <= s_we_i;
            req_adr_q <= s_adr_i;
            req_sel_q <= s_sel_i;
            req_dat_q <= s_dat_i;
        end
        if (s_ack_d) begin
            s_dat_q <= rdat_q;
        end
    end

    // RAM side next state.
    wire m_start = (req_sync_q[SYNC_STAGES-1] ^ ack_tog_q) & ~m_stb_q;  // new request
    wire m_done  = m_stb_q & m_ack_i;                   // the RAM acks at this edge
    wire m_stb_d = m_start | (m_stb_q & ~m_ack_i);

    always @(posedge m_clk_i) begin
        if (m_rst_i) begin
            req_sync_q <= {SYNC_STAGES{1'b0}};
            ack_tog_q  <= 1'b0;
            m_stb_q    <= 1'b0;
        end else begin
            req_sync_q <= {req_sync_q[SYNC_STAGES-2:0], req_tog_q};
            ack_tog_q  <= ack_tog_q ^ m_done;
            m_stb_q    <= m_stb_d;
        end
    end

    always @(posedge m_clk_i) begin
        if (m_start) begin
            m_we_q  <= req_we_q;
            m_adr_q <= req_adr_q;
            m_sel_q <= req_sel_q;
            m_dat_q <= req_dat_q;
        end
        if (m_done) begin
            rdat_q <= m_dat_i;
        end
    end

    assign s_dat_o = s_dat_q;
    assign s_ack_o = s_ack_q;
    assign m_cyc_o = m_stb_q;
    assign m_stb_o = m_stb_q;
    assign m_we_o  = m_we_q;
    assign m_adr_o = m_adr_q;
    assign m_sel_o = m_sel_q;
    assign m_dat_o = m_dat_q;

endmodule

`default_nettype wire
