// formal_controller -- black-box property harness of albatross_controller for
// the bounded proofs (tools/mk/formal_rtl.mk, docs/verification.md "Formal proofs (RTL)").
//
// Only the controller's ports are used, never its internal signals.  The
// configuration is the smallest that exercises an Export: one board (NB = 1),
// ADDR_WIDTH = 3, N_CHAN = 1, TIMEOUT = 3, and the ROM formal/rtl/ctrl_time.hex:
// one TIME entry (W = 1, ND = 1, destination board 0, base word 0, E1 = 0,
// E2 = H1 = 24).  The destination channel is modelled word by word: word 0
// holds the control bytes {ReadLocked, Actual}, words 1..6 the three buffers of
// W + 1 = 2 words (value, taken_at).  The bus is free: ack and err may come in
// any clock of a request (or never: a timeout), and a store answered with err
// may or may not have landed (free choice), as with the fault injector.  The
// consumer is free too, within the protocol (the paper, figure 3): in any clock it
// may load Actual, or store ReadLocked := the Actual it last loaded; its lock
// on buffer r is *confirmed* when a load of Actual returns r == ReadLocked,
// and lasts until its next ReadLocked store (it reads buffer r meanwhile).
// The initial control bytes are any valid pair, confirmed or not (the RAM
// keeps its contents across a controller reset).  Each clock the controller's
// access and the consumer's action see the state at the start of the clock,
// a valid serialisation of two byte-atomic accesses.
// Properties (labels; times are time_o values, S = cycle start + E1):
//   complete_publish  every landed store of Actual = b happens after landed
//                     stores of every word of buffer b (W value words and
//                     taken_at) since the slot start (the same transfer).
//   no_locked_write   no store into a word of buffer r lands while the
//                     consumer holds a confirmed lock on r.
//   slot_idle         the bus is idle before the first slot's first access,
//                     and in clocks S..S+6 of every planned slot;
//   slot_start        the first access is on the bus in clock S+7
//                     (docs/controller.md "Timing": FETCH_CYCLES = 7) for the slots at
//                     S = T0 and S = T0 + H1; T0 = 2*N_CHAN + 10 + 8*NE = 20
//                     (counters cleared, header read, the start-up CRC pass,
//                     a word a clock: ROM_CRC_BITS 32, so that the unrolling
//                     stays 56 clocks deep; the default 4 would start at 104).
//   time_step         time_o counts clocks since reset (binds time_o to the
//                     harness's clock count).
//   rom_valid         the ROM was read and is valid (error_o low, no entry
//                     skipped): guards against a vacuous proof.
`default_nettype none

module formal_controller (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire [31:0] m_dat_free,   // read data of words the model does not hold
    input  wire        m_ack_i,
    input  wire        m_err_i,
    input  wire        err_landed,   // a store answered with err landed anyway
    input  wire [1:0]  cons_op,      // consumer: 0 none, 1 load Actual, 2 store ReadLocked
    input  wire [1:0]  init_act,     // initial control bytes
    input  wire [1:0]  init_rl,
    input  wire        init_conf
);
    localparam NB = 1, AW = 3, N_CHAN = 1, TIMEOUT = 3;
    localparam [31:0] T0 = 32'd20, H1 = 32'd24, E1 = 32'd0, FETCH = 32'd7;

    wire                m_cyc_o, m_stb_o, m_we_o;
    wire [AW+3:0]       m_adr_o;
    wire [3:0]          m_sel_o;
    wire [31:0]         m_dat_o;
    wire [31:0]         time_o;
    wire                error_o;
    wire [15:0]         rom_errors_o;
    reg  [31:0]         m_dat_i;

    albatross_controller #(
        .NB(NB), .ADDR_WIDTH(AW), .N_CHAN(N_CHAN), .ROM_WORDS(12),
        .ROM_FILE("formal/rtl/ctrl_time.hex"), .TIMEOUT(TIMEOUT), .POLL(16), .ROM_CRC_BITS(32)
    ) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(m_cyc_o), .m_stb_o(m_stb_o), .m_we_o(m_we_o), .m_adr_o(m_adr_o),
        .m_sel_o(m_sel_o), .m_dat_o(m_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i),
        .m_err_i(m_err_i), .time_o(time_o), .error_o(error_o), .rom_errors_o(rom_errors_o)
    );

`ifdef FORMAL
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;

    // ------------------------------------------------------------- the bus
    wire req  = m_cyc_o & m_stb_o;
    always @* begin
        assume(rst_i == init_q);
        if (!req) begin
            assume(!m_ack_i);
            assume(!m_err_i);
        end
        assume(!(m_ack_i && m_err_i));
    end
    wire [3:0]    board = m_adr_o[AW+3:AW];
    wire [AW-1:0] word  = m_adr_o[AW-1:0];
    wire ours   = req && board == 4'd0;
    wire landed = ours && m_we_o && (m_ack_i || (m_err_i && err_landed));

    // ------------------------------------------------ the destination channel
    reg [1:0] act, rl;        // control bytes
    reg       conf;           // the consumer's lock on rl is confirmed
    reg [1:0] cons_seen;      // the Actual the consumer loaded last
    reg [5:0] written;        // words 1..6 stored (landed) since the slot start
    wire ctrl_word = word == 3'd0;
    wire [1:0] buf_of = (word == 3'd1 || word == 3'd2) ? 2'd1 :
                        (word == 3'd3 || word == 3'd4) ? 2'd2 :
                        (word == 3'd5 || word == 3'd6) ? 2'd3 : 2'd0;
    wire [1:0] new_act = m_dat_o[1:0];
    wire act_store = landed && ctrl_word && m_sel_o[0];
    always @* begin
        m_dat_i = m_dat_free;
        if (ours && ctrl_word) m_dat_i[15:0] = {6'd0, rl, 6'd0, act};
    end

    // slot starts (time_o), for the written mask and the slot properties
    wire [31:0] S0 = T0 + E1;
    wire [31:0] S1 = T0 + H1 + E1;
    wire at_start = time_o == S0 || time_o == S1;

    always @(posedge clk_i) begin
        if (init_q) begin
            act       <= init_act;
            rl        <= init_rl;
            conf      <= init_conf;
            cons_seen <= init_act;
            written   <= 6'd0;
        end else begin
            if (act_store) act <= new_act;
            if (landed && !ctrl_word && buf_of != 2'd0) written[word - 3'd1] <= 1'b1;
            if (at_start) written <= 6'd0;
            case (cons_op)
                2'd1: begin cons_seen <= act; if (act == rl) conf <= 1'b1; end
                2'd2: begin rl <= cons_seen; conf <= 1'b0; end
                default: ;
            endcase
        end
    end
    always @* begin
        if (init_q) begin
            assume(init_act != 2'd0);
            assume(init_rl != 2'd0);
        end
    end

    // ----------------------------------------------------------- properties
    wire [1:0] full = (new_act == 2'd1) ? written[1:0] :
                      (new_act == 2'd2) ? written[3:2] :
                      (new_act == 2'd3) ? written[5:4] : 2'b00;
    reg [31:0] clocks_q = 32'd0;   // clocks since reset
    always @(posedge clk_i) clocks_q <= init_q ? 32'd0 : clocks_q + 32'd1;
    always @* begin
        if (!init_q) begin
            complete_publish: assert(!act_store || full == 2'b11);
            no_locked_write:  assert(!(landed && buf_of != 2'd0 && conf && buf_of == rl));
            slot_idle:        assert(!(m_cyc_o && (time_o < S0 + FETCH ||
                                        (time_o >= S1 && time_o < S1 + FETCH))));
            slot_start:       assert(!(time_o == S0 + FETCH || time_o == S1 + FETCH) || m_cyc_o);
            time_step:        assert(time_o == clocks_q);
            rom_valid:        assert(!error_o && rom_errors_o == 16'd0);
        end
    end

    // Non-vacuity, as assertions that must FAIL (the proof flow reads them
    // with -DREACH only and expects a counterexample for each): an Export
    // publishes in the first slot and in the second.
`ifdef REACH
    always @* begin
        if (!init_q) begin
            reach_publish0: assert(!(act_store && time_o < S1));
            reach_publish1: assert(!(act_store && time_o > S1));
        end
    end
`endif
`endif

endmodule

`default_nettype wire
