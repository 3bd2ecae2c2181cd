// fseq_contract -- the sequencer's contract as a free environment, put in the
// place of albatross_sequencer inside albatross_controller by
// formal/ctrl/ctrl.sby (Yosys renames it before elaborating the controller),
// so that the controller's own top (its glue, engines, bus master, state RAM
// and counters) is the device under test of formal/ctrl/fctrl.v.  The
// sequencer's side of the contract (ROM checks, slot start times, the
// deadline margin of may_access) is proved on albatross_sequencer itself by
// formal/sequencer.  Same parameters and ports as albatross_sequencer.
// The schedule is one COPY entry (channel 0, ND = 2, source and destination
// places, W, the four-slot flag and the drop run K as free constants e_*,
// joined by the script to the harness's observers; with F_FIXED one fixed
// image: W = 2, every base 0, K = 2; F_FRAG: E7.frag != 0, the value over
// several runs, cut by the free deadline); time-rigid only (no
// SYNC entry, no poll).  Rules of the environment (the sequencer's
// guarantees, assumed):
//   * go_o only after enable_i has been high, never while a slot runs (from
//     go_o to slot_done_i), and at least FETCH_CYCLES - 1 = 6 clocks after
//     the previous slot_done_i (the next entry's fetch);
//   * may_access_o is high in the go_o clock (every valid slot is at least
//     FETCH_CYCLES + TIMEOUT + 2 clocks long), then high until it falls at
//     any clock (the deadline), and low from then until the next go_o;
//   * the entry's fields are constant; time_o and slot_time_o are free.
`default_nettype none

module fseq_contract #(
    parameter NB         = 4,    // boards on the system bus (unused: the fields are free)
    parameter ADDR_WIDTH = 10,   // word-address bits of a board RAM
    parameter N_CHAN     = 32,   // channel ids (unused)
    parameter ROM_WORDS  = 1024, // schedule ROM depth (unused)
    parameter ROM_FILE   = "",   // unused
    parameter TIME_BITS  = 16,   // unused
    parameter TIMEOUT    = 8,    // unused (the harness checks the bus master's)
    parameter POLL       = 16,   // unused
    parameter HAS_SYNC        = 1,  // unused (the controller's configuration parameters, where it passes them)
    parameter HAS_ROM_RECHECK = 1,  // unused
    parameter HAS_ENTRY_CHECK = 1,  // unused
    parameter CRC_BITS        = 4,  // unused
    parameter HAS_MODES       = 1,  // unused (no mode request: no REQUEST entry)
    parameter HAS_FRAGMENTS   = 1,  // unused (E7.frag != 0: frag_on_o, below)
    parameter HAS_MULTIRATE   = 1,  // unused (every go_o is the entry's: the sequencer's proof covers the due rule)
    parameter CLUSTER_BITS    = 15  // unused
) (
    input  wire                    clk_i,
    input  wire                    rst_i,
    input  wire                    enable_i,
    output wire                    go_o,
    output wire [1:0]              kind_o,
    output wire [6:0]              chan_o,         // (7 bits: a 5-bit connection takes the low bits)
    output wire [2:0]              nd_o,
    output wire [11:0]             words_o,
    output wire [3:0]              src_board_o,
    output wire [ADDR_WIDTH-1:0]   src_base_o,
    output wire [15:0]             dst_board_o,
    output wire [4*ADDR_WIDTH-1:0] dst_base_o,
    output wire [31:0]             slot_time_o,
    output wire                    frag_on_o,      // E7.frag != 0: 0, with F_FRAG 1 (a constant: valid from go_o on, earlier than the 2 clocks after go_o the contract gives)
    output wire                    sync_entry_o,
    output wire                    four_o,
    output wire                    request_o,      // (modes: not modelled, no REQUEST entry)
    output wire                    mode_info_o,    // (no MODE entry)
    output wire [31:0]             mode_since_o,
    output wire                    may_access_o,
    input  wire                    slot_done_i,
    output wire                    poll_cyc_o,
    output wire [3:0]              poll_board_o,
    output wire [ADDR_WIDTH-1:0]   poll_adr_o,
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [31:0]             poll_dat_i,
    input  wire                    poll_ack_i,
    input  wire                    poll_err_i,
    input  wire [1:0]              sync_rl_i,
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [31:0]             time_o,
    output wire                    cycle_o,
    output wire                    error_o,
    output wire [15:0]             rom_errors_o,
    output wire [15:0]             cycles_o,
    output wire [7:0]              drop_run_o,
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire                    mode_req_i,     // (modes: not modelled; the controller ties them off)
    input  wire [3:0]              mode_req_mode_i,
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [3:0]              mode_o,
    output wire                    mode_reject_o
);
    assign request_o     = 1'b0;
    assign mode_info_o   = 1'b0;
    assign mode_since_o  = 32'd0;
    assign mode_o        = 4'd0;
    assign mode_reject_o = 1'b0;
    localparam AW = ADDR_WIDTH;
    // the entry (free constants; the harness joins its observers to them)
`ifdef F_FIXED
    // one fixed image (the negatives: a broken variant needs only be caught):
    // W = 2 (a word count of 1 hides the word-count mutants), every base 0,
    // K = 2, the kind still free
    (* keep *) wire [11:0]   e_words     = 12'd2;
    (* anyconst, keep *) reg e_four;
    (* keep *) wire [AW-1:0] e_src_base  = {AW{1'b0}};
    (* keep *) wire [AW-1:0] e_dst_base0 = {AW{1'b0}};
    (* keep *) wire [AW-1:0] e_dst_base1 = {AW{1'b0}};
    (* keep *) wire [7:0]    e_drop_run  = 8'd2;
`else
    (* anyconst, keep *) reg [11:0]   e_words;
    (* anyconst, keep *) reg          e_four;
    (* anyconst, keep *) reg [AW-1:0] e_src_base, e_dst_base0, e_dst_base1;
    (* anyconst, keep *) reg [7:0]    e_drop_run;
`endif
    (* anyseq *)         reg          f_go, f_may;
    (* anyseq *)         reg [31:0]   f_time, f_slot_time;

    reg       en_q, run_q, live_q;
    reg [2:0] gap_q;                             // clocks since slot_done_i, saturating at 6
    always @(posedge clk_i) begin
        if (rst_i) begin
            en_q   <= 1'b0;
            run_q  <= 1'b0;
            live_q <= 1'b0;
            gap_q  <= 3'd6;
        end else begin
            if (enable_i) en_q <= 1'b1;
            if (go_o) run_q <= 1'b1;
            else if (slot_done_i) run_q <= 1'b0;
            live_q <= go_o ? f_may : live_q && f_may;
            gap_q  <= slot_done_i ? 3'd0 : (gap_q == 3'd6 ? gap_q : gap_q + 3'd1);
        end
    end
    assign go_o         = f_go && !rst_i && en_q && !run_q && gap_q == 3'd6 && !slot_done_i;
    assign may_access_o = go_o || live_q;
    assign kind_o       = 2'd1;                  // ALB_KIND_COPY
    assign chan_o       = 7'd0;
    assign nd_o         = 3'd2;
    assign words_o      = e_words;
    assign src_board_o  = 4'd1;
    assign src_base_o   = e_src_base;
    assign dst_board_o  = {8'd0, 4'd3, 4'd2};
    assign dst_base_o   = {{(2*AW){1'b0}}, e_dst_base1, e_dst_base0};
    assign slot_time_o  = f_slot_time;
`ifdef F_FRAG
    assign frag_on_o    = 1'b1;                  // (F_FIXED: W = 2) the value may go over several runs
`else
    assign frag_on_o    = 1'b0;                  // every value in one run
`endif
    assign sync_entry_o = 1'b0;
    assign four_o       = e_four;
    assign poll_cyc_o   = 1'b0;
    assign poll_board_o = 4'd0;
    assign poll_adr_o   = {AW{1'b0}};
    assign time_o       = f_time;
    assign cycle_o      = 1'b0;
    assign error_o      = 1'b0;
    assign rom_errors_o = 16'd0;
    assign cycles_o     = 16'd0;
    assign drop_run_o   = e_drop_run;
endmodule

`default_nettype wire
