// fdpram -- proof harness of albatross_dpram (formal/dpram/dpram.sby,
// docs/verification.md "Formal proofs (RTL)").
//
// Both ports are driven by free Wishbone B4 classic masters, constrained only
// by formal/wb/fwb_slave.v (which asserts the slave's answers, with the answer
// bound of docs/rtl.md "Never blocked": ack 1 or 2 clocks after the request,
// MAX_WAIT = 2), plus reset in the first clock only (a reset later would
// cancel an ack whose write has landed, which the shadow below cannot tell
// apart from a torn write).  The design under proof is the module named by
// the macro DUT (default albatross_dpram), so the same harness proves the
// broken fixtures tb/dpram/dpram_*.v.  ADDR_WIDTH is 3 (8 words) for
// tractability: no rule of the RAM depends on its size.
// Properties besides the Wishbone set (labels):
//   atomicity_a/b  docs/rtl.md "Byte atomicity", by a shadow of one symbolic
//                  word (address fa, any the solver picks; each byte lane on
//                  its own): the byte's value is the data of the last write
//                  to it acknowledged in an earlier clock (accesses take
//                  effect whole, in ack order, which is slot order).  A read
//                  acknowledged now returns exactly that value in every lane:
//                  the whole old or the whole new byte, never a mix.  If a read
//                  and a write of the byte are acked in the same clock
//                  (impossible in albatross_dpram, which acks one port per
//                  clock) the read may return either whole value.  The array
//                  is never reset, so the first read of a lane defines it.
//   one_ack        acks of the two ports never in one clock (one access per
//                  clock; the atomicity argument above rests on it).
// Induction strengthening (white-box): with -DF_PROBE the script connects
// f_mem_word, f_slot and f_rdata to the RAM's word fa, slot and read register
// (Yosys has no hierarchical references: the .sby script joins the wires after
// flatten), and the invariants inv_* tie the shadow and the acks to them.
`default_nettype none

`ifndef DUT
`define DUT albatross_dpram
`endif

module fdpram #(
    parameter ADDR_WIDTH = 3   // word-address bits of the RAM under proof
) (
    input  wire                  clk_i,
    input  wire                  rst_i,
    input  wire                  a_cyc_i,
    input  wire                  a_stb_i,
    input  wire                  a_we_i,
    input  wire [ADDR_WIDTH-1:0] a_adr_i,
    input  wire [3:0]            a_sel_i,
    input  wire [31:0]           a_dat_i,
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i
);

    wire [31:0] a_dat_o, b_dat_o;
    wire        a_ack_o, b_ack_o;

    `DUT #(.ADDR_WIDTH(ADDR_WIDTH)) dut (
        .clk_i(clk_i), .rst_i(rst_i),
        .a_cyc_i(a_cyc_i), .a_stb_i(a_stb_i), .a_we_i(a_we_i), .a_adr_i(a_adr_i),
        .a_sel_i(a_sel_i), .a_dat_i(a_dat_i), .a_dat_o(a_dat_o), .a_ack_o(a_ack_o),
        .b_cyc_i(b_cyc_i), .b_stb_i(b_stb_i), .b_we_i(b_we_i), .b_adr_i(b_adr_i),
        .b_sel_i(b_sel_i), .b_dat_i(b_dat_i), .b_dat_o(b_dat_o), .b_ack_o(b_ack_o)
    );

`ifdef FORMAL
    // ---------------------------------------------------------------- reset
    reg init_q = 1'b1;   // high in the first clock only
    always @(posedge clk_i) init_q <= 1'b0;
    always @* assume(rst_i == init_q);

    // --------------------------------------------- Wishbone classic, both ports
    wire       a_past_valid, a_out, a_rack, b_past_valid, b_out, b_rack;
    wire [3:0] a_wait, b_wait;
    fwb_slave #(.AW(ADDR_WIDTH), .DW(32), .MAX_WAIT(2)) wb_a (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(a_cyc_i), .stb_i(a_stb_i), .we_i(a_we_i),
        .adr_i(a_adr_i), .sel_i(a_sel_i), .wdat_i(a_dat_i), .rdat_i(a_dat_o),
        .ack_i(a_ack_o), .err_i(1'b0),
        .f_past_valid_o(a_past_valid), .f_outstanding_o(a_out), .f_wait_o(a_wait), .f_read_ack_o(a_rack));
    fwb_slave #(.AW(ADDR_WIDTH), .DW(32), .MAX_WAIT(2)) wb_b (
        .clk_i(clk_i), .rst_i(rst_i), .cyc_i(b_cyc_i), .stb_i(b_stb_i), .we_i(b_we_i),
        .adr_i(b_adr_i), .sel_i(b_sel_i), .wdat_i(b_dat_i), .rdat_i(b_dat_o),
        .ack_i(b_ack_o), .err_i(1'b0),
        .f_past_valid_o(b_past_valid), .f_outstanding_o(b_out), .f_wait_o(b_wait), .f_read_ack_o(b_rack));

    always @* if (!init_q) one_ack: assert(!(a_ack_o && b_ack_o));

    // --------------------------------------------------------- byte atomicity
    (* anyconst *) reg [ADDR_WIDTH-1:0] fa;   // the symbolic word
    reg [3:0]  sh_valid = 4'd0;
    reg [31:0] sh_word;
    wire a_hit = a_ack_o && a_adr_i == fa;
    wire b_hit = b_ack_o && b_adr_i == fa;
    wire [3:0] a_wr = {4{a_hit && a_we_i}} & a_sel_i;   // lanes written, acked now
    wire [3:0] b_wr = {4{b_hit && b_we_i}} & b_sel_i;
    wire a_rd = a_hit && !a_we_i;
    wire b_rd = b_hit && !b_we_i;
    wire [3:0] a_ok, b_ok;   // per lane: the read (if any) returns a whole allowed byte
    genvar l;
    generate for (l = 0; l < 4; l = l + 1) begin : lane
        wire [7:0] sh = sh_word[8*l +: 8];
        wire [7:0] ar = a_dat_o[8*l +: 8];
        wire [7:0] br = b_dat_o[8*l +: 8];
        assign a_ok[l] = !(a_rd && sh_valid[l]) || ar == sh || (b_wr[l] && ar == b_dat_i[8*l +: 8]);
        assign b_ok[l] = !(b_rd && sh_valid[l]) || br == sh || (a_wr[l] && br == a_dat_i[8*l +: 8]);
        always @(posedge clk_i) begin
            if (!init_q) begin
                if (a_wr[l] || b_wr[l]) begin
                    sh_valid[l]       <= 1'b1;   // same clock (broken RAMs only): A's
                    sh_word[8*l +: 8] <= a_wr[l] ? a_dat_i[8*l +: 8] : b_dat_i[8*l +: 8];
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
    (* keep *) wire [32*(1<<ADDR_WIDTH)-1:0] f_mem;   // dut.u_core.mem[0..], joined by the script
    (* keep *) wire        f_slot;       // dut.slot_q
    (* keep *) wire [31:0] f_rdata;      // dut.rdata_q
    wire [31:0] f_mem_word = f_mem[32*fa +: 32];
    // the word the acked access of this clock has written (lanes of a write ack)
    wire [3:0]  ack_wr  = a_wr | b_wr;
    wire [31:0] ack_dat = a_ack_o ? a_dat_i : b_dat_i;
    wire [3:0] sh_ok;   // per lane: a valid shadow lane is the RAM's lane, except in
                        // the clock of the write ack that already wrote it (the
                        // shadow catches up at its edge)
    generate for (l = 0; l < 4; l = l + 1) begin : inv_lane
        assign sh_ok[l] = !sh_valid[l] ||
                          f_mem_word[8*l +: 8] == (ack_wr[l] ? ack_dat[8*l +: 8] : sh_word[8*l +: 8]);
    end endgenerate
    always @* begin
        if (!init_q) begin
            // an ack answers a request pending from the last clock, in the slot
            // after its own; a read's data is the word read at that edge
            inv_ack_a:   assert(!a_ack_o || (a_out && f_slot));
            inv_ack_b:   assert(!b_ack_o || (b_out && !f_slot));
            // a request that waited 2 clocks is acked now; one that waited 1
            // clock and is not acked now goes at this edge (its own slot)
            inv_wait_a:  assert(a_wait <= 4'd2 && (a_wait != 4'd2 || a_ack_o) && (a_wait != 4'd1 || a_ack_o || !f_slot));
            inv_wait_b:  assert(b_wait <= 4'd2 && (b_wait != 4'd2 || b_ack_o) && (b_wait != 4'd1 || b_ack_o || f_slot));
            inv_shadow:  assert(&sh_ok);
            inv_rdata_a: assert(!a_rd || f_rdata == f_mem_word);
            inv_rdata_b: assert(!b_rd || f_rdata == f_mem_word);
        end
    end
`endif

    // ------------------------------------------------------ non-vacuity covers
    // (task cover): a waiting request on each port, and a checked read right
    // after the other port's write of the same word.
    reg [3:0] a_wr_q = 4'd0, b_wr_q = 4'd0;
    always @(posedge clk_i) begin
        a_wr_q <= a_wr;
        b_wr_q <= b_wr;
    end
    always @* begin
        if (!init_q) begin
            cover_wait_a: cover(a_cyc_i && a_stb_i && a_wait == 4'd2);
            cover_wait_b: cover(b_cyc_i && b_stb_i && b_wait == 4'd2);
            cover_read_a: cover(a_rd && sh_valid == 4'hF && b_wr_q == 4'hF);
            cover_read_b: cover(b_rd && sh_valid == 4'hF && a_wr_q == 4'hF);
        end
    end
`endif

endmodule

`default_nettype wire
