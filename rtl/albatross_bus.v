// albatross_bus -- the ALBATROSS system bus: one Wishbone master, NB slaves.
//
// Connects albatross_controller (the only master) to port B of each board's
// albatross_dpram.  Rules and timing:
//   * The master address is {board[BOARD_BITS-1:0], word[ADDR_WIDTH-1:0]}, with
//     BOARD_BITS = 4.  cyc and stb go only to the addressed board, in the same
//     clock (no added latency).  we, adr, sel and dat go to every board, and a
//     board ignores them unless it is selected.
//   * Boards answer registered: ack (or err) comes in a clock after the one
//     in which the request began, never in that first clock (albatross_dpram's
//     port B takes 1 or 2 clocks).  The master holds its request until the
//     answer (Wishbone classic).
//   * The answer (dat, ack, err) is taken from the board that was requested
//     in the previous clock (answer_q, the one register here); by the two
//     rules above that is the board addressed now whenever a board answers.
//     So the answer path starts at a register and the board's outputs, not
//     at the master's address: a master that computes its address in the
//     clock of the request does not find the bus's decode in its read path.
//     A board that was not requested in the previous clock is not heard: a
//     late ack from another board is never taken, and neither is an answer
//     in a request's first clock (outside this bus's contract).
//   * An access to a board >= NB is answered with err in its second clock,
//     like a registered board (answer_q's top bit: the previous clock
//     requested an absent board and got no answer; the err goes out only
//     while the request is still on the bus).  So no answer depends on this
//     clock's address.
//   * answer_q is a pure function of the previous clock's request and needs
//     no reset.
// Slave vectors are flattened: board b uses bits [b*w +: w] of a w-bit field.
`default_nettype none

module albatross_bus #(
    parameter NB         = 4,   // boards (slaves), 1..16
    parameter ADDR_WIDTH = 10   // word-address bits of a board RAM
) (
    input  wire                     clk_i,     // the bus clock (the controller's and port B's)
    // master side (the controller)
    input  wire                     m_cyc_i,
    input  wire                     m_stb_i,
    input  wire                     m_we_i,
    input  wire [ADDR_WIDTH+3:0]    m_adr_i,   // {board[3:0], word}
    input  wire [3:0]               m_sel_i,
    input  wire [31:0]              m_dat_i,
    output wire [31:0]              m_dat_o,
    output wire                     m_ack_o,
    output wire                     m_err_o,
    // slave side: port B of board b at bit b / bits [b*w +: w]
    output wire [NB-1:0]            s_cyc_o,
    output wire [NB-1:0]            s_stb_o,
    output wire [NB-1:0]            s_we_o,
    output wire [NB*ADDR_WIDTH-1:0] s_adr_o,
    output wire [NB*4-1:0]          s_sel_o,
    output wire [NB*32-1:0]         s_dat_o,
    input  wire [NB*32-1:0]         s_dat_i,
    input  wire [NB-1:0]            s_ack_i,
    input  wire [NB-1:0]            s_err_i
);

    localparam BOARD_BITS = 4;   // board field of the master address

    generate
        if (NB < 1 || NB > 16) begin : g_nb_check
            albatross_bus_NB_must_be_1_to_16 u_error ();
        end
    endgenerate

    wire [BOARD_BITS-1:0] board = m_adr_i[ADDR_WIDTH +: BOARD_BITS];
    wire                  req   = m_cyc_i & m_stb_i;

    // One-hot select of the addressed board; none if board >= NB.
    reg [NB-1:0] sel_b;
    integer s;
    always @* begin
        for (s = 0; s < NB; s = s + 1)
            sel_b[s] = {1'b0, board} == s[BOARD_BITS:0];
    end
    wire none = ~|sel_b;

    // The board requested in the previous clock: the one whose answer is
    // taken ([NB]: an absent board, unanswered in that clock: err now).
    reg [NB:0] answer_q;
    wire       absent_err = answer_q[NB] & req;
    always @(posedge clk_i) answer_q <= {req & none & ~absent_err, sel_b & {NB{req}}};

    assign s_cyc_o = {NB{m_cyc_i}} & sel_b;
    assign s_stb_o = {NB{m_stb_i}} & sel_b;
    assign s_we_o  = {NB{m_we_i}};
    assign s_adr_o = {NB{m_adr_i[ADDR_WIDTH-1:0]}};
    assign s_sel_o = {NB{m_sel_i}};
    assign s_dat_o = {NB{m_dat_i}};

    // Read data, ack and err of that board (AND-OR of the one-hot answer_q).
    reg [31:0] dat_r;
    integer b;
    always @* begin
        dat_r = 32'd0;
        for (b = 0; b < NB; b = b + 1)
            dat_r = dat_r | (s_dat_i[b*32 +: 32] & {32{answer_q[b]}});
    end

    assign m_dat_o = dat_r;
    assign m_ack_o = |(s_ack_i & answer_q[NB-1:0]);
    assign m_err_o = |(s_err_i & answer_q[NB-1:0]) | absent_err;

endmodule

`default_nettype wire
