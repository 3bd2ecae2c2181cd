// formal_dpram -- property wrapper of albatross_dpram for the bounded proofs
// (tools/mk/formal_rtl.mk, docs/verification.md "Formal proofs (RTL)").
//
// Both ports are driven by unconstrained Wishbone B4 classic masters: the only
// assumptions are reset in the first clock with no request during it, and the
// classic handshake (once cyc & stb is raised, cyc, stb, we, adr, sel and dat
// stay stable until the clock in which ack is high).  The design under proof
// is the module named by the macro DUT (default albatross_dpram), so the same
// wrapper proves the deliberately broken fixtures tb/rtl/dpram_*.v.
// Properties (assertion labels, each reported by name on failure):
//   access_time  docs/rtl.md "Never blocked": a new request (cyc & stb in a clock
//                whose previous clock had no pending request, or had its ack)
//                is acknowledged exactly 1 or 2 clocks later, whatever the
//                other port does.  Asserted as: a pending request never waits
//                a third clock.
//   no_spurious  ack is high only in the clock after a clock with a pending
//                request of that port (one ack per request).
//   atomicity    docs/rtl.md "Byte atomicity", as a shadow model of one symbolic
//                word (address fa, chosen freely by the solver; each byte
//                lane checked on its own):
//                the byte's value is the data of the last write to it
//                acknowledged in an earlier clock (every access takes effect
//                as a whole, in the order of the acks: a request performed
//                at a slot's edge is acked in the clock after it, so ack order
//                is slot order).  A read acknowledged in clock t returns, in
//                lane fl, exactly that value -- a whole old or whole new byte,
//                never a mix.  If a read and a write of the byte are acked in
//                the same clock (impossible in albatross_dpram, which acks one
//                port per clock) the read may return either whole value.  The
//                array is never reset, so until the first write or read of
//                the byte the shadow is unknown; the first read defines it.
// Counterexample: yosys-smtbmc --dump-vcd shows the two ports and the shadow
// (sh_valid, sh_byte) clock by clock.
`default_nettype none

`ifndef DUT
`define DUT albatross_dpram
`endif

module formal_dpram #(
    parameter ADDR_WIDTH = 2
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
    always @* begin
        assume(rst_i == init_q);
        if (rst_i) begin
            assume(!a_stb_i);
            assume(!b_stb_i);
        end
    end

    // ------------------------------------------- Wishbone B4 classic masters
    wire a_req = a_cyc_i & a_stb_i;
    wire b_req = b_cyc_i & b_stb_i;
    // a request is pending in a clock if it is on the bus and not acked in it
    reg  a_pend_q = 1'b0, b_pend_q = 1'b0;   // pending in the previous clock
    reg  [1:0] a_wait_q = 2'd0, b_wait_q = 2'd0;  // clocks the request has waited
    always @(posedge clk_i) begin
        a_pend_q <= a_req & ~a_ack_o;
        b_pend_q <= b_req & ~b_ack_o;
        a_wait_q <= (a_req & ~a_ack_o) ? ((a_wait_q == 2'd3) ? 2'd3 : a_wait_q + 2'd1) : 2'd0;
        b_wait_q <= (b_req & ~b_ack_o) ? ((b_wait_q == 2'd3) ? 2'd3 : b_wait_q + 2'd1) : 2'd0;
    end
    reg [ADDR_WIDTH+38:0] a_hold_q, b_hold_q;   // cyc, stb, we, adr, sel, dat
    always @(posedge clk_i) begin
        a_hold_q <= {a_cyc_i, a_stb_i, a_we_i, a_adr_i, a_sel_i, a_dat_i};
        b_hold_q <= {b_cyc_i, b_stb_i, b_we_i, b_adr_i, b_sel_i, b_dat_i};
    end
    always @* begin
        if (!init_q && a_pend_q) assume({a_cyc_i, a_stb_i, a_we_i, a_adr_i, a_sel_i, a_dat_i} == a_hold_q);
        if (!init_q && b_pend_q) assume({b_cyc_i, b_stb_i, b_we_i, b_adr_i, b_sel_i, b_dat_i} == b_hold_q);
    end

    // ------------------------------------------------------ fixed access time
    // a_wait_q = clocks this request has been on the bus without ack before
    // this clock; ack must come in the request's 2nd or 3rd clock.
    always @* begin
        if (!init_q) begin
            access_time_a: assert(!(a_req && !a_ack_o && a_wait_q >= 2'd2));
            access_time_b: assert(!(b_req && !b_ack_o && b_wait_q >= 2'd2));
            no_spurious_a: assert(!a_ack_o || a_pend_q);
            no_spurious_b: assert(!b_ack_o || b_pend_q);
        end
    end

    // --------------------------------------------------------- byte atomicity
    // The shadow holds the whole word at the symbolic address fa, with one
    // valid bit per byte lane; every lane is checked on its own.
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
                    sh_valid[l]      <= 1'b1;   // same clock (broken RAMs only): A's
                    sh_word[8*l +: 8] <= a_wr[l] ? a_dat_i[8*l +: 8] : b_dat_i[8*l +: 8];
                end else if (!sh_valid[l] && (a_rd || b_rd)) begin
                    sh_valid[l]      <= 1'b1;
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

    // ------------------------------------------------------ non-vacuity covers
    // yosys-smtbmc -c must reach each: the assumptions allow waiting requests,
    // checked reads on both ports, and a read acked right after a write of the
    // same word by the other port.
    reg [3:0] a_wr_q = 4'd0, b_wr_q = 4'd0;
    always @(posedge clk_i) begin
        a_wr_q <= a_wr;
        b_wr_q <= b_wr;
    end
    always @* begin
        if (!init_q) begin
            cover_wait_a: cover(a_req && a_wait_q == 2'd1);
            cover_wait_b: cover(b_req && b_wait_q == 2'd1);
            cover_read_a: cover(a_rd && sh_valid == 4'hF && b_wr_q == 4'hF);
            cover_read_b: cover(b_rd && sh_valid == 4'hF && a_wr_q == 4'hF);
        end
    end
`endif

endmodule

`default_nettype wire
