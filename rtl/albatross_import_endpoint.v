// albatross_import_endpoint -- a hardware consumer of one channel: the
// Import engine (albatross_import) with the channel fixed by parameters and
// its ReadLocked copy kept in the engine's own registers, for a user's RTL
// block that reads a channel through a DPRAM port without a CPU (the paper, section 3.1,
// figure 3).  Connect the Wishbone port straight to an albatross_dpram port
// (or any Wishbone B4 classic slave; tie wb_err_i 0 if it has none).
// Rules:
//   * import_i is taken in a clock where busy_o is low; the Import's first
//     access is on the bus in the next clock.  At reset the ReadLocked copy is
//     unknown: the first Import stores ReadLocked before it reads.
//   * Every Import reads the value (it never skips): the W words of the
//     buffer it locked, in order, each handed out on word_o with
//     word_valid_o, index word_index_o, taken in a clock where word_ready_i
//     is high.  A consumer that takes every word at once (word_ready_i tied
//     1) sees one word every 2 clocks on albatross_dpram: 2 (Old) or 6 (New)
//     clocks of control accesses, then 2 clocks a word.  A consumer that wants
//     a flat value writes word_o into its own register word_index_o; the
//     value is complete, and one whole exported value, at done_o.
//   * done_o is high for one clock after the last word was taken; new_o and
//     corrupt_o hold until the next Import.  new_o: the value was never read
//     before (figure 3's New).  corrupt_o: Actual named no buffer, nothing
//     was read (the channel is not initialised or the RAM is upset).
//   * An access answered with err is repeated (never given up).
//   * FOUR_SLOT = 1: the channel is of the four-slot kind (4 buffers, its
//     producer a four-slot one): wait-free, 2 (Old) or 6 (New) clocks of
//     control accesses whatever the producer does; at reset the copy (the
//     buffer read last) is unknown, so the first Import is New.
`default_nettype none

module albatross_import_endpoint #(
    parameter ADDR_WIDTH = 10, // word-address bits of the DPRAM port
    parameter BASE       = 0,  // the channel's base, word address in that RAM
    parameter WORDS      = 4,  // W, the value's words (>= 1)
    parameter FOUR_SLOT  = 0   // 1: the channel is of the four-slot kind
) (
    input  wire                  clk_i,
    input  wire                  rst_i,        // synchronous, active high
    // user side
    input  wire                  import_i,     // start an Import (taken when !busy_o)
    output wire                  busy_o,       // an Import is under way
    output wire                  done_o,       // one clock: the Import is over
    output wire                  new_o,        // the value was never read before
    output wire                  corrupt_o,    // Actual named no buffer: nothing read
    output wire [31:0]           word_o,       // the value, word by word
    output wire                  word_valid_o,
    input  wire                  word_ready_i,
    output wire [15:0]           word_index_o, // 0..WORDS-1
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
        if (WORDS < 1 || WORDS > 65535 || (FOUR_SLOT != 0 && FOUR_SLOT != 1) || BASE < 0 || BASE >= (1 << ADDR_WIDTH)) begin : g_param_check
            albatross_import_endpoint_parameter_out_of_range u_error ();
        end
    endgenerate

    wire       idle, selected, rl_known, cut;
    wire [2:0] rl;
    wire [7:0] fails;
    wire       unused = &{1'b0, selected, cut, fails};

    albatross_import #(.ADDR_WIDTH(ADDR_WIDTH), .WORDS_WIDTH(16), .COUNT_WIDTH(8)) u_import (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(import_i), .base_i(BASE_W), .words_i(WORDS_W),
        .four_i(FOUR_SLOT != 0), .rl_known_i(rl_known), .rl_i(rl),          // the copy stays in the engine
        .may_access_i(1'b1), .idle_o(idle),
        .selected_o(selected), .stream_i(1'b1), .skip_i(1'b0),
        .word_o(word_o), .word_valid_o(word_valid_o), .word_ready_i(word_ready_i),
        .word_index_o(word_index_o),
        .done_o(done_o), .new_o(new_o), .corrupt_o(corrupt_o), .cut_o(cut), .fails_o(fails),
        .rl_known_o(rl_known), .rl_o(rl),
        .wb_cyc_o(wb_cyc_o), .wb_stb_o(wb_stb_o), .wb_we_o(wb_we_o), .wb_adr_o(wb_adr_o),
        .wb_sel_o(wb_sel_o), .wb_dat_o(wb_dat_o), .wb_dat_i(wb_dat_i), .wb_ack_i(wb_ack_i),
        .wb_err_i(wb_err_i)
    );

    assign busy_o = !idle;

endmodule

`default_nettype wire
