// import_pico -- test top of the Import endpoint (tb/endpoint/import): a
// PicoRV32 producer feeding an RTL consumer through one albatross_dpram.
//   port A: a PicoRV32 (board_core, CORE 0: firmware +fw0=FILE) running
//           tb/pico/firmware/producer.c with the real driver: it writes the
//           channel's start image and the start flag, then exports seq 1..N;
//   port B: albatross_import_endpoint (channel at word BASE, WORDS words),
//           driven by the harness (import_i, word_ready_i), which checks every
//           value it hands out.
// Both ports' Wishbone signals are brought out (mon_*) for the harness's
// protocol checker; an access completes in a clock where its ack is high.
// core_stall_i holds the core's local RAM.
`default_nettype none

module import_pico #(
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM
    parameter RAM_WORDS  = 4096,  // words of the core's local RAM
    parameter BASE       = 0,     // the channel's base (word address)
    parameter WORDS      = 4      // the value's words (pair_value_t)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,        // synchronous, active high
    input  wire                  core_stall_i, // hold the core's local RAM this clock
    output wire                  done_o,       // the core stored to TOHOST
    output wire [31:0]           code_o,       // its exit code
    output wire [127:0]          stat_o,       // its STAT 0..3
    output wire                  trap_o,
    output wire                  bus_err_o,
    // the Import endpoint's user side
    input  wire                  import_i,
    input  wire                  word_ready_i,
    output wire                  imp_busy_o,
    output wire                  imp_done_o,
    output wire                  imp_new_o,
    output wire                  imp_corrupt_o,
    output wire [31:0]           imp_word_o,
    output wire                  imp_word_valid_o,
    output wire [15:0]           imp_word_index_o,
    // monitors: port A (core) and port B (endpoint)
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
    wire                    ev_valid;
    wire [31:0]             ev_data, ev_arg;
    wire                    unused = &{1'b0, ev_valid, ev_data, ev_arg, cyc};

    albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH)) u_dpram (
        .clk_i  (clk_i),
        .rst_i  (rst_i),
        .a_cyc_i(cyc[0]), .a_stb_i(stb[0]), .a_we_i(we[0]), .a_adr_i(adr[0 +: ADDR_WIDTH]),
        .a_sel_i(sel[0 +: 4]), .a_dat_i(wdat[0 +: 32]), .a_dat_o(rdat[0 +: 32]), .a_ack_o(ack[0]),
        .b_cyc_i(cyc[1]), .b_stb_i(stb[1]), .b_we_i(we[1]), .b_adr_i(adr[ADDR_WIDTH +: ADDR_WIDTH]),
        .b_sel_i(sel[4 +: 4]), .b_dat_i(wdat[32 +: 32]), .b_dat_o(rdat[32 +: 32]), .b_ack_o(ack[1])
    );

    board_core #(.SERV(0), .CORE(0), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS)) u_core (
        .clk_i(clk_i), .rst_i(rst_i), .stall_i(core_stall_i),
        .wb_cyc_o(cyc[0]), .wb_stb_o(stb[0]), .wb_we_o(we[0]), .wb_adr_o(adr[0 +: ADDR_WIDTH]),
        .wb_sel_o(sel[0 +: 4]), .wb_dat_o(wdat[0 +: 32]), .wb_dat_i(rdat[0 +: 32]), .wb_ack_i(ack[0]),
        .done_o(done_o), .code_o(code_o), .stat_o(stat_o), .ev_valid_o(ev_valid), .ev_data_o(ev_data),
        .ev_arg_o(ev_arg), .trap_o(trap_o), .bus_err_o(bus_err_o)
    );

    albatross_import_endpoint #(.ADDR_WIDTH(ADDR_WIDTH), .BASE(BASE), .WORDS(WORDS)) u_import (
        .clk_i(clk_i), .rst_i(rst_i),
        .import_i(import_i), .busy_o(imp_busy_o), .done_o(imp_done_o), .new_o(imp_new_o),
        .corrupt_o(imp_corrupt_o),
        .word_o(imp_word_o), .word_valid_o(imp_word_valid_o), .word_ready_i(word_ready_i),
        .word_index_o(imp_word_index_o),
        .wb_cyc_o(cyc[1]), .wb_stb_o(stb[1]), .wb_we_o(we[1]), .wb_adr_o(adr[ADDR_WIDTH +: ADDR_WIDTH]),
        .wb_sel_o(sel[4 +: 4]), .wb_dat_o(wdat[32 +: 32]), .wb_dat_i(rdat[32 +: 32]), .wb_ack_i(ack[1]),
        .wb_err_i(1'b0)
    );

    assign mon_stb_o  = stb;
    assign mon_we_o   = we;
    assign mon_adr_o  = adr;
    assign mon_sel_o  = sel;
    assign mon_wdat_o = wdat;
    assign mon_rdat_o = rdat;
    assign mon_ack_o  = ack;

endmodule

`default_nettype wire
