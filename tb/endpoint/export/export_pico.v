// export_pico -- test top of the Export endpoint (tb/endpoint/export): an RTL
// producer feeding a PicoRV32 consumer through one albatross_dpram.
//   port A: albatross_export_endpoint (channel at word BASE, WORDS words, no
//           taken_at: the C driver's layout), fed by pair_source, which
//           publishes seq 1..VALUES as fast as the endpoint takes them,
//           held by gen_stall_i (the harness's random stalls);
//   port B: a PicoRV32 (board_core, CORE 1: firmware +fw1=FILE) running
//           tb/pico/firmware/consumer.c with the real driver.
// The RAM starts from INIT_FILE: the channel with both control bytes Buffer1
// and value 0 in Buffer1, and the consumer's start flag (what the pair
// test's producer writes).  Both ports' Wishbone signals are brought out
// (mon_*) for the harness's protocol checker; an access completes in a
// clock where its ack is high.  core_stall_i holds the core's local RAM.
`default_nettype none

module export_pico #(
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM
    parameter RAM_WORDS  = 4096,  // words of the core's local RAM
    parameter BASE       = 0,     // the channel's base (word address)
    parameter WORDS      = 4,     // the value's words (pair_value_t)
    parameter VALUES     = 1000,  // values pair_source publishes
    parameter INIT_FILE  = ""     // $readmemh image of the DPRAM
) (
    input  wire                  clk_i,
    input  wire                  rst_i,        // synchronous, active high
    input  wire                  gen_stall_i,  // hold pair_source this clock
    input  wire                  core_stall_i, // hold the core's local RAM this clock
    output wire                  done_o,       // the core stored to TOHOST
    output wire [31:0]           code_o,       // its exit code
    output wire [127:0]          stat_o,       // its STAT 0..3
    output wire                  trap_o,
    output wire                  bus_err_o,
    output wire [31:0]           seq_o,        // pair_source: the value taken last
    output wire                  finished_o,   // pair_source: all values taken
    output wire                  exp_busy_o,   // the endpoint's busy_o, done_o, corrupt_o
    output wire                  exp_done_o,
    output wire                  exp_corrupt_o,
    output wire                  exp_word_ready_o, // it asks for a word ...
    output wire                  exp_word_valid_o, // ... and one is offered
    // monitors: port A (endpoint) and port B (core)
    output wire [1:0]            mon_stb_o,
    output wire [1:0]            mon_we_o,
    output wire [2*ADDR_WIDTH-1:0] mon_adr_o,
    output wire [7:0]            mon_sel_o,
    output wire [63:0]           mon_wdat_o,
    output wire [63:0]           mon_rdat_o,
    output wire [1:0]            mon_ack_o
);

    wire [1:0]              cyc, stb, we, ack;
    wire [2*ADDR_WIDTH-1:0] adr;
    wire [7:0]              sel;
    wire [63:0]             wdat, rdat;
    wire                    publish, word_valid, word_ready;
    wire [31:0]             word;
    wire [15:0]             word_index;
    wire                    ev_valid;
    wire [31:0]             ev_data, ev_arg;
    wire                    unused = &{1'b0, ev_valid, ev_data, ev_arg, cyc};

    albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH), .INIT_FILE(INIT_FILE)) u_dpram (
        .clk_i  (clk_i),
        .rst_i  (rst_i),
        .a_cyc_i(cyc[0]), .a_stb_i(stb[0]), .a_we_i(we[0]), .a_adr_i(adr[0 +: ADDR_WIDTH]),
        .a_sel_i(sel[0 +: 4]), .a_dat_i(wdat[0 +: 32]), .a_dat_o(rdat[0 +: 32]), .a_ack_o(ack[0]),
        .b_cyc_i(cyc[1]), .b_stb_i(stb[1]), .b_we_i(we[1]), .b_adr_i(adr[ADDR_WIDTH +: ADDR_WIDTH]),
        .b_sel_i(sel[4 +: 4]), .b_dat_i(wdat[32 +: 32]), .b_dat_o(rdat[32 +: 32]), .b_ack_o(ack[1])
    );

    pair_source #(.VALUES(VALUES)) u_source (
        .clk_i(clk_i), .rst_i(rst_i), .stall_i(gen_stall_i), .busy_i(exp_busy_o),
        .publish_o(publish), .word_o(word), .word_valid_o(word_valid), .word_index_i(word_index),
        .seq_o(seq_o), .finished_o(finished_o)
    );

    albatross_export_endpoint #(.ADDR_WIDTH(ADDR_WIDTH), .BASE(BASE), .WORDS(WORDS), .TAKEN_AT(0)) u_export (
        .clk_i(clk_i), .rst_i(rst_i),
        .publish_i(publish), .taken_at_i(32'd0), .busy_o(exp_busy_o), .done_o(exp_done_o),
        .corrupt_o(exp_corrupt_o),
        .word_i(word), .word_valid_i(word_valid), .word_ready_o(word_ready), .word_index_o(word_index),
        .wb_cyc_o(cyc[0]), .wb_stb_o(stb[0]), .wb_we_o(we[0]), .wb_adr_o(adr[0 +: ADDR_WIDTH]),
        .wb_sel_o(sel[0 +: 4]), .wb_dat_o(wdat[0 +: 32]), .wb_dat_i(rdat[0 +: 32]), .wb_ack_i(ack[0]),
        .wb_err_i(1'b0)
    );

    board_core #(.SERV(0), .CORE(1), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS)) u_core (
        .clk_i(clk_i), .rst_i(rst_i), .stall_i(core_stall_i),
        .wb_cyc_o(cyc[1]), .wb_stb_o(stb[1]), .wb_we_o(we[1]), .wb_adr_o(adr[ADDR_WIDTH +: ADDR_WIDTH]),
        .wb_sel_o(sel[4 +: 4]), .wb_dat_o(wdat[32 +: 32]), .wb_dat_i(rdat[32 +: 32]), .wb_ack_i(ack[1]),
        .done_o(done_o), .code_o(code_o), .stat_o(stat_o), .ev_valid_o(ev_valid), .ev_data_o(ev_data),
        .ev_arg_o(ev_arg), .trap_o(trap_o), .bus_err_o(bus_err_o)
    );

    assign exp_word_ready_o = word_ready;
    assign exp_word_valid_o = word_valid;
    assign mon_stb_o  = stb;
    assign mon_we_o   = we;
    assign mon_adr_o  = adr;
    assign mon_sel_o  = sel;
    assign mon_wdat_o = wdat;
    assign mon_rdat_o = rdat;
    assign mon_ack_o  = ack;

endmodule

`default_nettype wire
