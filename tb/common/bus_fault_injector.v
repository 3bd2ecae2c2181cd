// bus_fault_injector -- test fixture between albatross_controller and albatross_bus.
//
// Injects system-bus faults into the controller's requests, one request at a
// time.  Rules and timing:
//   * A new request is c_cyc & c_stb while the injector is idle.  It is idle
//     after reset, in the clock after it answered the controller (ack or err),
//     and while the controller holds cyc or stb low.  A request the controller
//     presents right after an answer (back to back) is therefore new.
//   * Kind: fi_dead_i[board] ? 2 : fi_kind_i, sampled in the first clock of
//     the request and kept until the request ends.  The request is forwarded
//     from that same first clock, so kind 0 adds no latency.
//       0  none: forward; ack, err and data come back unchanged.
//       1  err after performing: forward; the bus's ack (or err) reaches the
//          controller as err, in the same clock.
//       2  timeout without performing: never forward, never answer.
//       3  timeout after performing: forward until the bus answers, swallow
//          the answer, then never answer.
//   * Once the bus has answered a forwarded request of kind 1 or 3, the
//     injector stops forwarding it from the next clock on.  Otherwise
//     albatross_dpram would perform the access again while the controller
//     still holds stb.  In the clock of the bus's answer the request is still
//     forwarded, so the RAM's port B shows the access as performed.
//   * An answer from the bus reaches the controller only while the request is
//     forwarded: a late ack of an abandoned request is dropped.
//   * fi_new_o is high in the first clock of each new request (the clock in
//     which fi_kind_i is sampled), fi_dead_o with it if the request goes to a
//     dead board (kind 2 whatever fi_kind_i).  The fault rate is a property
//     of ACCESSES, not of clocks: a harness draws the kind of the next access
//     once per fi_new_o to a live board and holds it on fi_kind_i until then
//     (docs/verification.md, "Fault injection"), so how often and at which
//     phase the controller starts accesses cannot change the share faulted.
`default_nettype none

module bus_fault_injector #(
    parameter NB         = 4,   // boards; fi_dead_i has one bit per board
    parameter ADDR_WIDTH = 10   // word-address bits of a board RAM
) (
    input  wire                  clk_i,
    input  wire                  rst_i,        // synchronous, active high
    input  wire [1:0]            fi_kind_i,    // fault kind for the next new request
    input  wire [NB-1:0]         fi_dead_i,    // board links that are down (kind 2)
    output wire                  fi_new_o,     // a new request samples fi_kind_i in this clock
    output wire                  fi_dead_o,    // ... and goes to a dead board (valid with fi_new_o)
    // controller side: Wishbone B4 classic slave
    input  wire                  c_cyc_i,
    input  wire                  c_stb_i,
    input  wire                  c_we_i,
    input  wire [ADDR_WIDTH+3:0] c_adr_i,      // {board[3:0], word}
    input  wire [3:0]            c_sel_i,
    input  wire [31:0]           c_dat_i,
    output wire [31:0]           c_dat_o,
    output wire                  c_ack_o,
    output wire                  c_err_o,
    // bus side: Wishbone B4 classic master
    output wire                  b_cyc_o,
    output wire                  b_stb_o,
    output wire                  b_we_o,
    output wire [ADDR_WIDTH+3:0] b_adr_o,
    output wire [3:0]            b_sel_o,
    output wire [31:0]           b_dat_o,
    input  wire [31:0]           b_dat_i,
    input  wire                  b_ack_i,
    input  wire                  b_err_i
);

    // kinds: 0 none, 1 err after performing, 2 lost (never performed), 3 lost after performing
    localparam [1:0] F_NONE = 2'd0, F_ERR = 2'd1, F_LOST = 2'd2;

    reg       busy_q;   // a request is in progress
    reg [1:0] kind_q;   // its fault kind
    reg       done_q;   // the bus has answered it: forward no more

    wire [3:0] board = c_adr_i[ADDR_WIDTH +: 4];
    reg        dead;
    integer    b;
    always @* begin
        dead = 1'b0;
        for (b = 0; b < NB; b = b + 1)
            if ({1'b0, board} == b[4:0]) dead = fi_dead_i[b];
    end

    wire       req     = c_cyc_i & c_stb_i;
    wire [1:0] kind    = busy_q ? kind_q : (dead ? F_LOST : fi_kind_i);
    wire       fwd     = req & (kind != F_LOST) & ~done_q;
    wire       b_done  = fwd & (b_ack_i | b_err_i);
    wire       ack     = fwd & (kind == F_NONE) & b_ack_i;
    wire       err     = fwd & ((kind == F_NONE & b_err_i) | (kind == F_ERR & (b_ack_i | b_err_i)));

    always @(posedge clk_i) begin
        if (rst_i || !req) begin
            busy_q <= 1'b0;
            done_q <= 1'b0;
        end else begin
            busy_q <= ~(ack | err);
            done_q <= ~(ack | err) & (done_q | b_done);
            if (!busy_q) kind_q <= kind;
        end
    end

    assign fi_new_o  = req & ~busy_q;
    assign fi_dead_o = dead;
    assign b_cyc_o = fwd;
    assign b_stb_o = fwd;
    assign b_we_o  = c_we_i;
    assign b_adr_o = c_adr_i;
    assign b_sel_o = c_sel_i;
    assign b_dat_o = c_dat_i;
    assign c_dat_o = b_dat_i;
    assign c_ack_o = ack;
    assign c_err_o = err;

endmodule

`default_nettype wire
