// formal_export -- property wrapper of the Export engine (albatross_export,
// DESTS = 1, TAKEN_AT = 0, ADDR_WIDTH = 6, W = 1..3) for a bounded proof
// (formal/rtl/run_check.py, engine smtbmc).  The environment is adversarial:
// the slave answers any time after a request (never err), with any data (any
// Actual and ReadLocked byte, valid or not); the stream offers words at any
// time; start_i comes at any time with any base, W and Actual copy.  Each
// transfer begins from the inputs sampled at start (the engine keeps nothing
// else between transfers), so a run from reset covers every transfer up to
// the depth.  Properties (assertion labels):
//   no_locked_write   a value store never goes to the buffer named by the
//                     ReadLocked the engine loaded in this Export, nor to the
//                     buffer of its Actual copy;
//   complete_publish  the store of Actual names a buffer 1..3 whose W words
//                     were all stored (acked) in this Export, and not the
//                     loaded ReadLocked;
//   exact_accesses    an Export takes exactly W + 2 accesses, plus 1 when the
//                     Actual copy was unknown at start (no failed store of
//                     Actual pending: tried_i = 0, as in an endpoint);
//   in_channel        every access lies inside the channel.
`default_nettype none

module formal_export (
    input wire        clk_i,
    input wire        rst_i,
    input wire        start_i,
    input wire [5:0]  base_i,
    input wire [1:0]  words_i,
    input wire        act_known_i,
    input wire [1:0]  act_i,
    input wire [31:0] word_i,
    input wire        word_valid_i,
    input wire [31:0] wb_dat_i,
    input wire        wb_ack_i
);
    reg init_q = 1'b1;
    always @(posedge clk_i) init_q <= 1'b0;

    wire        cyc, stb, we, idle, ready, done, cut;
    wire [5:0]  adr;
    wire [3:0]  sel;
    wire [31:0] dat;
    wire [1:0]  windex;
    wire        published, corrupt, known_o;
    wire [1:0]  act_o;
    wire [7:0]  fails;

    albatross_export #(.ADDR_WIDTH(6), .WORDS_WIDTH(2), .COUNT_WIDTH(8), .TAKEN_AT(0), .DESTS(1)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(start_i), .base_i(base_i), .need_i(1'b1), .words_i(words_i), .taken_at_i(32'd0),
        .act_known_i(act_known_i), .act_i(act_i), .tried_i(2'd0), .may_access_i(1'b1), .idle_o(idle),
        .word_i(word_i), .word_valid_i(word_valid_i), .word_ready_o(ready), .word_index_o(windex),
        .done_o(done), .published_o(published), .corrupt_o(corrupt), .cut_o(cut), .fails_o(fails),
        .act_known_o(known_o), .act_o(act_o),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_sel_o(sel), .wb_dat_o(dat),
        .wb_dat_i(wb_dat_i), .wb_ack_i(wb_ack_i), .wb_err_i(1'b0)
    );

    // Environment.
    always @* begin
        assume(rst_i == init_q);                          // reset in the first step only
        assume(!wb_ack_i || stb);                         // an answer only to a request
        assume(words_i != 2'd0);                          // W = 1..3
        assume(base_i <= 6'd50);                          // the channel fits: base + 1 + 3W < 64
        assume(!act_known_i || act_i != 2'd0);            // a known copy names a buffer
    end

    // What this Export has done, seen from the bus.
    reg       open_q;                                     // an Export is under way
    reg [5:0] base_q;
    reg [1:0] w_q;
    reg [1:0] copy_q;                                     // Actual copy (0: unknown)
    reg       known_start_q;
    reg [1:0] rl_q;                                       // ReadLocked loaded (0: none or invalid)
    reg [8:0] written_q;                                  // word k of buffer b at bit 3(b-1)+k
    reg [3:0] acks_q;

    wire [5:0] off   = adr - base_q - 6'd1;               // word offset from Buffer1
    wire [5:0] w6    = {4'd0, w_q};
    wire [1:0] b     = off < w6 ? 2'd1 : off < (w6 << 1) ? 2'd2 : 2'd3;
    wire [5:0] k     = b == 2'd1 ? off : b == 2'd2 ? off - w6 : off - (w6 << 1);
    wire [3:0] bit_i = 4'd3 * ({2'd0, b} - 4'd1) + k[3:0];
    wire       vstore = stb && we && sel == 4'hF;
    wire       astore = stb && we && sel == 4'b0001;
    wire [1:0] pub   = dat[1:0];
    wire [2:0] need_mask = w_q == 2'd1 ? 3'b001 : w_q == 2'd2 ? 3'b011 : 3'b111;
    wire [2:0] have  = pub == 2'd1 ? written_q[2:0] : pub == 2'd2 ? written_q[5:3] : written_q[8:6];
    wire [7:0] rbyte = wb_dat_i[15:8];
    wire [7:0] abyte = wb_dat_i[7:0];

    always @(posedge clk_i) begin
        if (rst_i) begin
            open_q <= 1'b0;
        end else begin
            if (start_i && idle) begin
                open_q        <= 1'b1;
                base_q        <= base_i;
                w_q           <= words_i;
                copy_q        <= act_known_i ? act_i : 2'd0;
                known_start_q <= act_known_i;
                rl_q          <= 2'd0;
                written_q     <= 9'd0;
                acks_q        <= 4'd0;
            end
            if (wb_ack_i && stb) begin
                acks_q <= acks_q + 4'd1;
                if (!we && sel == 4'b0010) rl_q <= (rbyte[7:2] == 6'd0) ? rbyte[1:0] : 2'd0;
                if (!we && sel == 4'b0001 && abyte[7:2] == 6'd0 && abyte[1:0] != 2'd0) copy_q <= abyte[1:0];
                if (vstore) written_q[bit_i] <= 1'b1;
            end
            if (done) open_q <= 1'b0;
        end
    end

    always @* begin
        if (!init_q && !rst_i && open_q) begin
            if (vstore) no_locked_write: assert((rl_q == 2'd0 || b != rl_q) && (copy_q == 2'd0 || b != copy_q));
            if (astore) complete_publish: assert(pub != 2'd0 && dat[7:2] == 6'd0 && (have & need_mask) == need_mask &&
                                                 pub != rl_q);
            if (done) exact_accesses: assert(acks_q == {2'd0, w_q} + 4'd2 + {3'd0, !known_start_q});
            if (stb) in_channel: assert(adr >= base_q && adr <= base_q + 6'd3 * w6);
        end
    end

    wire unused = &{1'b0, cyc, ready, cut, windex, published, corrupt, known_o, act_o, fails, k[5:4], dat[31:8]};
endmodule

`default_nettype wire
