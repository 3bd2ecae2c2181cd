// albatross_export_endpoint -- a hardware producer of one channel: the
// Export engine (albatross_export) with the channel fixed by parameters and
// its Actual copy kept in the engine's own registers, for a user's RTL block
// (a sensor interface, say) that publishes a channel into a DPRAM port
// without a CPU (the paper, section 3.1, figure 4).  Connect the Wishbone port straight to
// an albatross_dpram port (or any Wishbone B4 classic slave; tie wb_err_i 0
// if it has none).
// Rules:
//   * publish_i is taken in a clock where busy_o is low; the Export's first
//     access is on the bus in the next clock.  At reset the Actual copy is
//     unknown: the first Export reads Actual back first (1 access more).  The
//     RAM must hold valid control bytes (the compiler's RAM image: Buffer1)
//     or the consumer must initialise ReadLocked; an invalid Actual or
//     ReadLocked sets corrupt_o, and the value is published all the same.
//   * The value is taken word by word after the ReadLocked load: word
//     word_index_o in a clock where word_ready_o and word_valid_i are both
//     high.  A block with a flat value drives word_i = value[32*word_index_o
//     +: 32] and word_valid_i = 1, and holds the value from publish_i to
//     done_o.  Undisturbed, one Export takes WORDS + TAKEN_AT + 2 accesses
//     (2 clocks each on albatross_dpram, back to back while word_valid_i is
//     high when asked).
//   * TAKEN_AT = 1 stores taken_at_i (sampled at publish_i) after the value:
//     the channel's buffers are then WORDS + 1 words (the controller's
//     destination layout, struct { value; uint32_t taken_at; }).
//   * done_o is high for one clock after the store of Actual: the value is
//     published; corrupt_o holds until the next Export.
//   * An access answered with err is repeated (never given up).
//   * FOUR_SLOT = 1: the channel is of the four-slot kind (4 buffers; its
//     consumer a four-slot one): one control-word load, the value, a Slot
//     byte store and the Actual store: WORDS + TAKEN_AT + 3 accesses, no
//     read-back of Actual after reset.
`default_nettype none

module albatross_export_endpoint #(
    parameter ADDR_WIDTH = 10, // word-address bits of the DPRAM port
    parameter BASE       = 0,  // the channel's base, word address in that RAM
    parameter WORDS      = 4,  // W, the value's words (>= 1)
    parameter TAKEN_AT   = 0,  // 1: a taken_at word follows the value in each buffer
    parameter FOUR_SLOT  = 0   // 1: the channel is of the four-slot kind
) (
    input  wire                  clk_i,
    input  wire                  rst_i,        // synchronous, active high
    // user side
    input  wire                  publish_i,    // start an Export (taken when !busy_o)
    input  wire [31:0]           taken_at_i,   // TAKEN_AT = 1: stored after the value
    output wire                  busy_o,       // an Export is under way
    output wire                  done_o,       // one clock: the value is published
    output wire                  corrupt_o,    // Actual or ReadLocked named no buffer
    input  wire [31:0]           word_i,       // the value, word by word
    input  wire                  word_valid_i,
    output wire                  word_ready_o,
    output wire [15:0]           word_index_o, // 0..WORDS-1: the word taken next
    // Wishbone B4 classic master to a DPRAM port
    output wire                  wb_cyc_o,
    output wire                  wb_stb_o,
    output wire                  wb_we_o,
    output wire [ADDR_WIDTH-1:0] wb_adr_o,
    output wire [3:0]            wb_sel_o,
    output wire [31:0]           wb_dat_o,
    input  wire [31:0]           wb_dat_i,
    input  wire                  wb_ack_i,
    input  wire                  wb_err_i
);

    localparam [ADDR_WIDTH-1:0] BASE_W  = BASE[ADDR_WIDTH-1:0];
    localparam [15:0]           WORDS_W = WORDS[15:0];

    generate
        if (WORDS < 1 || WORDS > 65534 || (FOUR_SLOT != 0 && FOUR_SLOT != 1) || BASE < 0 || BASE >= (1 << ADDR_WIDTH)) begin : g_param_check
            albatross_export_endpoint_parameter_out_of_range u_error ();
        end
    endgenerate

    wire       idle, act_known, published, cut;
    wire [1:0] act, dest;
    wire [2:0] tried;
    wire [7:0] fails;
    wire       unused = &{1'b0, published, cut, fails, dest};

    albatross_export #(.ADDR_WIDTH(ADDR_WIDTH), .WORDS_WIDTH(16), .COUNT_WIDTH(8), .TAKEN_AT(TAKEN_AT),
                       .DESTS(1)) u_export (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(publish_i), .drop_run_i(8'd0), .four_i(FOUR_SLOT != 0), .base_i(BASE_W), .need_i(1'b1), .words_i(WORDS_W),
        .taken_at_i(taken_at_i),
        .act_known_i(act_known), .act_i(act),       // the copy stays in the engine
        .tried_i(tried),
        .may_access_i(1'b1), .idle_o(idle),
        .word_i(word_i), .word_valid_i(word_valid_i), .word_ready_o(word_ready_o),
        .word_index_o(word_index_o),
        .done_o(done_o), .published_o(published), .corrupt_o(corrupt_o), .cut_o(cut), .fails_o(fails),
        .act_known_o(act_known), .act_o(act), .tried_o(tried), .dest_o(dest),
        .wb_cyc_o(wb_cyc_o), .wb_stb_o(wb_stb_o), .wb_we_o(wb_we_o), .wb_adr_o(wb_adr_o),
        .wb_sel_o(wb_sel_o), .wb_dat_o(wb_dat_o), .wb_dat_i(wb_dat_i), .wb_ack_i(wb_ack_i),
        .wb_err_i(wb_err_i)
    );

    assign busy_o = !idle;

endmodule

`default_nettype wire
