// tb_endpoint_loop -- small self-checking bench of the packaged IP, the
// simulation of the FuseSoC cores (tb/endpoint/tb_endpoint_loop.core,
// tools/mk/fusesoc.mk): an albatross_export_endpoint on port A of an
// albatross_dpram publishes the values 1, 2, 3, ... of one three-buffer
// channel (value s: word k = s * (k + 1), so the RAM's zeros are value 0),
// an albatross_import_endpoint on port B imports it, both at pseudo-random
// paces (an LFSR) so that Imports meet Exports at every phase and both Old
// and New Imports happen; both sides stall their words (word_valid_i,
// word_ready_i) at random.
// Rules checked at every Import's done_o (each failure prints "expected X,
// got Y" and the bench ends with FAIL):
//   * no corrupt_o on either side;
//   * untorn: every word k of the value read is s * (k + 1) for the s of its
//     word 0, and the words come in order 0..WORDS-1;
//   * never back in time: s >= the previous Import's s, and s <= the value
//     being published (no value from the future);
//   * New exactly when newer: new_o == (s != previous s), the first Import
//     after reset New.
// The consumer starts after the first Export (the simulated RAM's buffers
// hold x until written; the bench fails on any x word read).
// Before the endpoints leave reset the bench stores the channel's first
// control word through port B (Actual = ReadLocked = the contract's initial
// index, from albatross_contract.vh), as the compiler's RAM image would.
// Ends on its own: PASS after IMPORTS Imports with at least one Old and
// MIN_NEW New ones, FAIL at the watchdog (MAX_CYCLES clocks).
`timescale 1ns/1ps
`default_nettype none

module tb_endpoint_loop #(
    parameter IMPORTS    = 3000,   // Imports checked before PASS
    parameter MIN_NEW    = 500,    // New Imports required (the producer keeps pace)
    parameter MAX_CYCLES = 400000  // watchdog in clocks
);
    localparam AW    = 6;  // word-address bits of the RAM (64 words)
    localparam BASE  = 8;  // the channel's base word
    localparam WORDS = 4;  // W

`include "albatross_contract.vh"

    localparam [31:0] INIT_CTRL = (ALB_CH_INITIAL_INDEX << (8 * ALB_CH_OFF_ACTUAL)) |
                                  (ALB_CH_INITIAL_INDEX << (8 * ALB_CH_OFF_READLOCKED));

    reg clk = 1'b0;
    always #5 clk = !clk;
    reg rst = 1'b1;       // RAM reset
    reg ep_rst = 1'b1;    // endpoints' reset, held until the channel is initialised

    // port A: the export endpoint; port B: the bench's init store, then the import endpoint
    wire          a_cyc, a_stb, a_we, a_ack, b_ack;
    wire [AW-1:0] a_adr;
    wire [3:0]    a_sel;
    wire [31:0]   a_wdat, a_rdat, b_rdat;
    wire          i_cyc, i_stb, i_we;
    wire [AW-1:0] i_adr;
    wire [3:0]    i_sel;
    wire [31:0]   i_wdat;
    reg           init_q = 1'b0;  // the bench drives port B

    albatross_dpram #(.ADDR_WIDTH(AW)) u_ram (
        .clk_i(clk), .rst_i(rst),
        .a_cyc_i(a_cyc), .a_stb_i(a_stb), .a_we_i(a_we), .a_adr_i(a_adr), .a_sel_i(a_sel),
        .a_dat_i(a_wdat), .a_dat_o(a_rdat), .a_ack_o(a_ack),
        .b_cyc_i(init_q | i_cyc), .b_stb_i(init_q | i_stb), .b_we_i(init_q | i_we),
        .b_adr_i(init_q ? BASE[AW-1:0] : i_adr), .b_sel_i(init_q ? 4'hF : i_sel),
        .b_dat_i(init_q ? INIT_CTRL : i_wdat), .b_dat_o(b_rdat), .b_ack_o(b_ack)
    );

    // producer: value pub_q while an Export is under way, word k = pub_q * (k + 1)
    reg  [31:0] pub_q = 32'd0;
    reg         publish = 1'b0, valid = 1'b1;
    wire        e_busy, e_done, e_corrupt, e_ready;
    wire [15:0] e_index;
    albatross_export_endpoint #(.ADDR_WIDTH(AW), .BASE(BASE), .WORDS(WORDS)) u_export (
        .clk_i(clk), .rst_i(ep_rst),
        .publish_i(publish), .taken_at_i(32'd0), .busy_o(e_busy), .done_o(e_done), .corrupt_o(e_corrupt),
        .word_i(pub_q * ({16'd0, e_index} + 32'd1)), .word_valid_i(valid), .word_ready_o(e_ready),
        .word_index_o(e_index),
        .wb_cyc_o(a_cyc), .wb_stb_o(a_stb), .wb_we_o(a_we), .wb_adr_o(a_adr), .wb_sel_o(a_sel),
        .wb_dat_o(a_wdat), .wb_dat_i(a_rdat), .wb_ack_i(a_ack), .wb_err_i(1'b0)
    );

    wire        unused = &{1'b0, e_ready};  // a flat value: word_i is there whenever the engine asks

    // consumer
    reg         imp = 1'b0, ready = 1'b1;
    wire        c_busy, c_done, c_new, c_corrupt, c_valid;
    wire [31:0] c_word;
    wire [15:0] c_index;
    albatross_import_endpoint #(.ADDR_WIDTH(AW), .BASE(BASE), .WORDS(WORDS)) u_import (
        .clk_i(clk), .rst_i(ep_rst),
        .import_i(imp), .busy_o(c_busy), .done_o(c_done), .new_o(c_new), .corrupt_o(c_corrupt),
        .word_o(c_word), .word_valid_o(c_valid), .word_ready_i(ready), .word_index_o(c_index),
        .wb_cyc_o(i_cyc), .wb_stb_o(i_stb), .wb_we_o(i_we), .wb_adr_o(i_adr), .wb_sel_o(i_sel),
        .wb_dat_o(i_wdat), .wb_dat_i(b_rdat), .wb_ack_i(b_ack), .wb_err_i(1'b0)
    );

    // pacing: a 32-bit xorshift (lfsr), gaps of 0..15 clocks (producer) and 0..31 (consumer)
    reg [31:0] lfsr = 32'h1234_5678;
    reg [4:0]  e_gap = 5'd0, c_gap = 5'd0;
    integer    cycles = 0, errors = 0, imports = 0, news = 0, olds = 0, exports = 0;
    integer    last_s = -1, s = 0, k_next = 0, k;
    reg [31:0] got [0:WORDS-1];

    function [31:0] xorshift;
        input [31:0] x;
        reg   [31:0] y;
        begin
            y = x ^ (x << 13);
            y = y ^ (y >> 17);
            xorshift = y ^ (y << 5);
        end
    endfunction

    task fail_check;
        input [8*24-1:0] what;
        input [31:0]     expected;
        input [31:0]     value;
        begin
            $display("FAIL %0s at Import %0d (clock %0d): expected %0d, got %0d", what, imports, cycles, expected, value);
            errors = errors + 1;
        end
    endtask

    initial begin
        repeat (3) @(posedge clk);
        rst <= 1'b0;
        @(posedge clk);
        init_q <= 1'b1;                       // store the first control word through port B
        @(posedge clk);
        while (!b_ack) @(posedge clk);
        init_q <= 1'b0;
        @(posedge clk);
        ep_rst <= 1'b0;
    end

    always @(posedge clk) begin
        cycles = cycles + 1;
        lfsr <= xorshift(lfsr);
        if (!ep_rst) begin
            // producer: publish pub_q + 1 after a gap
            publish <= 1'b0;
            valid   <= lfsr[12:11] != 2'b00;
            if (e_done) begin exports = exports + 1; e_gap <= {1'b0, lfsr[3:0]}; end
            else if (!e_busy && !publish) begin
                if (e_gap != 5'd0) e_gap <= e_gap - 5'd1;
                else begin publish <= 1'b1; pub_q <= pub_q + 32'd1; end
            end
            if (e_corrupt) fail_check("export corrupt_o", 32'd0, 32'd1);
            // consumer: an Import after a gap; words taken when ready
            imp <= 1'b0;
            ready  <= lfsr[9:8] != 2'b00;
            if (c_valid && ready) begin
                if (c_index != k_next[15:0]) fail_check("word order", k_next, {16'd0, c_index});
                got[c_index[1:0]] = c_word;
                k_next = k_next + 1;
            end
            if (c_done) begin
                imports = imports + 1;
                c_gap <= lfsr[20:16];
                if (c_corrupt) fail_check("import corrupt_o", 32'd0, 32'd1);
                else begin
                    if (k_next != WORDS) fail_check("words per Import", WORDS, k_next);
                    if (^got[0] === 1'bx) fail_check("word 0 known", 0, got[0]);
                    s = got[0];
                    for (k = 1; k < WORDS; k = k + 1)
                        if (got[k] !== s * (k + 1)) fail_check("untorn word", s * (k + 1), got[k]);
                    if (s < last_s) fail_check("back in time (s >= last)", last_s, s);
                    if (s > pub_q) fail_check("value from the future", pub_q, s);
                    if (c_new != (s != last_s)) fail_check("new_o when newer", {31'd0, s != last_s}, {31'd0, c_new});
                    if (c_new) news = news + 1; else olds = olds + 1;
                    last_s = s;
                end
                k_next = 0;
            end else if (!c_busy && !imp && exports > 0) begin
                if (c_gap != 5'd0) c_gap <= c_gap - 5'd1;
                else imp <= 1'b1;
            end
        end
        if (errors > 20) begin
            $display("FAIL: more than 20 errors, stopped");
            $finish;
        end
        if (imports >= IMPORTS) begin
            if (errors == 0 && olds > 0 && news >= MIN_NEW)
                $display("PASS tb_endpoint_loop: %0d Imports checked (%0d New, %0d Old), %0d Exports, %0d clocks",
                         imports, news, olds, exports, cycles);
            else if (errors == 0)
                $display("FAIL tb_endpoint_loop: expected at least %0d New and 1 Old Imports, got %0d New and %0d Old",
                         MIN_NEW, news, olds);
            else
                $display("FAIL tb_endpoint_loop: %0d errors in %0d Imports", errors, imports);
            $finish;
        end
        if (cycles >= MAX_CYCLES) begin
            $display("FAIL tb_endpoint_loop: watchdog, expected %0d Imports in %0d clocks, got %0d", IMPORTS, MAX_CYCLES, imports);
            $finish;
        end
    end

endmodule

`default_nettype wire
