// albatross_controller -- the ALBATROSS communication controller (seed 3.2-3.4).
//
// The only master of the system bus (Wishbone B4 classic, address {board[3:0],
// word}).  It runs the cyclic schedule of a ROM ($readmemh ROM_FILE; in
// simulation +rom=FILE overrides it) as docs/controller.md specifies.  This
// module only composes the parts and keeps the per-channel state:
//   albatross_sequencer   ROM, cycle and slot timing, the deadline
//                         (may_access), TIME's time, the sync-mode poll; it
//                         holds albatross_rom_check (start-up and background
//                         CRC check) and albatross_entry_check (field checks
//                         at fetch)
//   albatross_import      the source's Import (seed figure 3)
//   albatross_export      the destinations' Export (figure 4), to up to 4
//                         destinations in lockstep
//   albatross_bus_master  the one bus port: board field, timeout, arbitration
//   albatross_counters    per-channel counters and the STATUS words
// Rules:
//   * Per-channel state (one RAM word per channel id, read while the entry is
//     fetched, written back when its slot ends; cleared after reset, never
//     reset): the source ReadLocked copy (0 unknown; four-slot: L, the buffer
//     read last), the destinations that still need the current value, each
//     destination's Actual copy (0 unknown; four-slot: not used) and the
//     buffer of its failed Actual store (0 none), and the current value's
//     taken_at.
//   * Four-slot (E0 flag FOUR_SLOT, any kind but SYNC): both engines run the
//     four-slot side for the entry (the source's Import, every destination's
//     Export); the glue is the same.
//   * COPY: the Import runs; when it has chosen (the ack clock of its last
//     Actual load) the destinations that need the value are those in need,
//     or all of them if the value is New (taken_at := time_o of that clock).
//     If none does, the Import ends; else the Export starts in that clock and
//     the Import streams the value to it word by word (one source load, then
//     one store per destination).  TIME and STATUS start the Export at go
//     with every destination and a fresh value: TIME's is the slot's nominal
//     start (value and taken_at), STATUS's the counters' words.
//   * A destination published by the Export leaves need; at the slot's end
//     each destination still in need counts as abandoned, and a later slot of
//     the channel delivers it.  A value is published to a destination at most
//     once, so redundant slots never show one value as New twice.
//   * No bus access is ever made while the ROM is invalid (error_o): the
//     sequencer then never starts a slot or a poll.
// Adding a channel kind touches the engines and the sequencer's decode, and
// the word-source multiplexer below.
`default_nettype none

module albatross_controller #(
    parameter NB         = 4,     // boards on the system bus, 1..16
    parameter ADDR_WIDTH = 10,    // word-address bits of a board RAM, 3..12
    parameter N_CHAN     = 32,    // channel ids with state and counters, 1..32
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in 32-bit words, at least 12
    parameter ROM_FILE   = "",    // $readmemh image of the ROM; "" leaves it zero (invalid header); simulation: +rom=FILE overrides
    parameter TIMEOUT    = 8,     // clocks of cyc without ack/err before an access fails, 3..60
    parameter POLL       = 16,    // sync mode: clocks from the start of one poll to the next, >= 2
    parameter TIME_BITS  = 16     // bits of time within a cycle (the compiler's [bus] time_bits), 4..16
) (
    input  wire                  clk_i,
    input  wire                  rst_i,          // synchronous, active high
    // system bus: Wishbone B4 classic master, address {board[3:0], word}
    output wire                  m_cyc_o,
    output wire                  m_stb_o,
    output wire                  m_we_o,
    output wire [ADDR_WIDTH+3:0] m_adr_o,
    output wire [3:0]            m_sel_o,
    output wire [31:0]           m_dat_o,
    input  wire [31:0]           m_dat_i,
    input  wire                  m_ack_i,
    input  wire                  m_err_i,
    // status
    output wire [31:0]           time_o,         // global time: clocks since reset
    output wire                  error_o,        // the ROM is invalid (header or CRC)
    output wire [15:0]           rom_errors_o    // entries skipped and ROM upsets (saturating)
);

`include "albatross_contract.vh"

    localparam AW      = ADDR_WIDTH;
    localparam CH_BITS = (N_CHAN > 1) ? $clog2(N_CHAN) : 1;
    localparam ST_W    = 12 + 8 + 4 + 3 + 32;           // {tried, act, need, rl, taken}
    // The state RAM has 32 words from N_CHAN = 4 up (Yosys maps a RAM of only
    // a few words to flip-flops; 32 x 59 bits is block RAM); fewer channels
    // (the formal harness) keep N_CHAN words.
    localparam ST_DEPTH = (N_CHAN >= 4) ? 32 : N_CHAN;
    localparam ST_AW    = (ST_DEPTH > 1) ? $clog2(ST_DEPTH) : 1;
    localparam integer       LAST_CH_I = N_CHAN - 1;
    localparam [CH_BITS-1:0] LAST_CH   = LAST_CH_I[CH_BITS-1:0];

    generate
        if (TIME_BITS > ALB_ROM_TIME_BITS || TIMEOUT < 3 || TIMEOUT > 60) begin : g_param_check
            albatross_controller_parameter_out_of_range u_error ();
        end
    endgenerate

    function [2:0] popcount4;
        input [3:0] m;
        popcount4 = {2'd0, m[0]} + {2'd0, m[1]} + {2'd0, m[2]} + {2'd0, m[3]};
    endfunction

    // ------------------------------------------------------------ sequencer
    wire          go, may_access, sync_entry, poll_cyc, cycle_start, four;
    wire [1:0]    kind;
    wire [4:0]    chan5;
    wire [2:0]    nd;
    wire [11:0]   words;
    wire [3:0]    src_board, poll_board;
    wire [AW-1:0] src_base, poll_adr;
    wire [15:0]   dst_board, cycles;
    wire [7:0]    drop_run;     // ROM H2: the Export engine's drop run K
    wire [4*AW-1:0] dst_base;
    wire [31:0]   slot_time;
    wire [31:0]   bus_rdat;
    wire [2:0]    r_ack, r_err;
    reg           slot_end;
    reg [1:0]     sync_rl_q;
    reg           ready_q;                                 // channel state cleared
    wire          cnt_ready;

    albatross_sequencer #(.NB(NB), .ADDR_WIDTH(AW), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS), .ROM_FILE(ROM_FILE),
                          .TIME_BITS(TIME_BITS), .TIMEOUT(TIMEOUT), .POLL(POLL)) u_seq (
        .clk_i(clk_i), .rst_i(rst_i), .enable_i(ready_q && cnt_ready),
        .go_o(go), .kind_o(kind), .chan_o(chan5), .nd_o(nd), .words_o(words),
        .src_board_o(src_board), .src_base_o(src_base), .dst_board_o(dst_board), .dst_base_o(dst_base),
        .slot_time_o(slot_time), .sync_entry_o(sync_entry), .four_o(four), .may_access_o(may_access), .slot_done_i(slot_end),
        .poll_cyc_o(poll_cyc), .poll_board_o(poll_board), .poll_adr_o(poll_adr), .poll_dat_i(bus_rdat),
        .poll_ack_i(r_ack[2]), .poll_err_i(r_err[2]), .sync_rl_i(sync_rl_q),
        .time_o(time_o), .cycle_o(cycle_start), .error_o(error_o), .rom_errors_o(rom_errors_o), .cycles_o(cycles),
        .drop_run_o(drop_run));

    wire [CH_BITS-1:0] chan   = chan5[CH_BITS-1:0];
    wire [3:0]         active = (nd == 3'd1) ? 4'b0001 : (nd == 3'd2) ? 4'b0011 : (nd == 3'd3) ? 4'b0111 : 4'b1111;
    wire               k_copy = kind == ALB_KIND_COPY[1:0];
    wire               k_time = kind == ALB_KIND_TIME[1:0];

    // ------------------------------------------------------------ per-channel state
    reg [ST_W-1:0]    st_mem [0:ST_DEPTH-1];
    reg [ST_W-1:0]    st_q;
    reg [CH_BITS-1:0] clr_q;
    reg [ST_W-1:0]    st_d;                               // written back at slot_end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [31:0]       ch32   = {{(32-CH_BITS){1'b0}}, chan};
    wire [31:0]       clr32  = {{(32-CH_BITS){1'b0}}, clr_q};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [ST_AW-1:0]  st_ix  = ch32[ST_AW-1:0];
    wire [ST_AW-1:0]  clr_ix = clr32[ST_AW-1:0];
    // Each field is written only when its slot changed it (write enables,
    // not a read-modify-write multiplexer); the clearing writes zeros, which
    // is what st_d holds after reset (its sources are reset).
    wire              st_wr   = !ready_q || slot_end;
    wire [ST_AW-1:0]  st_wa   = ready_q ? st_ix : clr_ix;
    wire              wr_exp  = !ready_q || exp_run_q;
    wire              wr_imp  = !ready_q || imp_run_q;
    wire              wr_tkn  = !ready_q || (chosen_q && new_q);
    always @(posedge clk_i) begin
        if (st_wr) begin
            if (wr_tkn) st_mem[st_wa][31:0]  <= st_d[31:0];
            if (wr_imp) st_mem[st_wa][34:32] <= st_d[34:32];
            if (wr_exp) st_mem[st_wa][58:35] <= st_d[58:35];
        end else begin
            st_q <= st_mem[st_ix];
        end
    end
    wire [11:0] st_tried = st_q[58:47];
    wire [7:0]  st_act   = st_q[46:39];
    wire [3:0]  st_need  = st_q[38:35];
    wire [2:0]  st_rl    = st_q[34:32];
    wire [31:0] st_taken = st_q[31:0];

    // ------------------------------------------------------------ engines
    reg         imp_run_q;         // the Import runs (or ran) in this slot
    reg         exp_run_q;         // the Export runs (or ran) in this slot
    reg         chosen_q;          // the Import has chosen
    reg         new_q;             // ... a New value
    reg [3:0]   need_q;            // destinations the Export serves
    reg [31:0]  taken_q;           // taken_at of the slot's value
    wire        imp_idle, imp_sel, imp_done, imp_new, imp_corrupt, imp_cut, imp_rl_known, imp_fails;
    wire [2:0]  imp_rl;
    wire [31:0] imp_word;
    wire        imp_word_valid;
    wire [11:0] imp_index;
    wire        exp_idle, exp_done, exp_cut, exp_fails, exp_ready;
    wire [3:0]  exp_published, exp_corrupt, exp_known;
    wire [7:0]  exp_act;
    wire [11:0] exp_tried;
    wire [1:0]  exp_dest;
    wire [11:0] exp_index;
    wire [2:0]  r_cyc, r_we;
    wire [3*AW-1:0] r_adr;
    wire [11:0] r_sel;
    wire [95:0] r_wdat;
    wire [31:0] status_word;
    wire        status_valid;
    wire        imp_stb, exp_stb, cnt_busy;     // cyc = stb in both engines

    // The Import has chosen: the destinations that need the value.
    wire        choose     = imp_run_q && !chosen_q && imp_sel;
    wire [3:0]  need_now   = (imp_new ? 4'hF : st_need) & active;
    wire        exp_start  = (go && !k_copy) || (choose && need_now != 4'd0);
    wire [3:0]  exp_need   = go ? active : need_now;
    wire [11:0] exp_tried_in = (go || imp_new) ? 12'd0 : st_tried;
    wire [31:0] exp_taken  = go ? slot_time : imp_new ? time_o : st_taken;
    wire [7:0]  act_known_in;
    genvar g;
    generate
        for (g = 0; g < 4; g = g + 1) begin : g_known
            assign act_known_in[2*g +: 2] = {1'b0, st_act[2*g +: 2] != 2'd0};
        end
    endgenerate
    wire [3:0]  known_in = {act_known_in[6], act_known_in[4], act_known_in[2], act_known_in[0]};

    // The value's words: the Import's stream, TIME's time, the STATUS words.
    wire [31:0] word     = k_copy ? imp_word : k_time ? slot_time : status_word;
    wire        word_ok  = k_copy ? imp_word_valid : k_time ? 1'b1 : status_valid;

    albatross_import #(.ADDR_WIDTH(AW), .WORDS_WIDTH(12), .COUNT_WIDTH(1), .PULL(1)) u_import (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(go && k_copy), .four_i(four), .base_i(src_base), .words_i(words), .rl_known_i(st_rl != 3'd0),
        .rl_i(st_rl),
        .may_access_i(may_access), .idle_o(imp_idle),
        .selected_o(imp_sel), .stream_i(choose && need_now != 4'd0),
        .skip_i((choose && need_now == 4'd0) || (exp_run_q && exp_done)),   // nothing needed; the Export gave up
        .word_o(imp_word), .word_valid_o(imp_word_valid), .word_ready_i(exp_ready), .word_index_o(imp_index),
        .done_o(imp_done), .new_o(imp_new), .corrupt_o(imp_corrupt), .cut_o(imp_cut), .fails_o(imp_fails),
        .rl_known_o(imp_rl_known), .rl_o(imp_rl),
        .wb_cyc_o(r_cyc[0]), .wb_stb_o(imp_stb), .wb_we_o(r_we[0]), .wb_adr_o(r_adr[0 +: AW]), .wb_sel_o(r_sel[0 +: 4]),
        .wb_dat_o(r_wdat[0 +: 32]), .wb_dat_i(bus_rdat), .wb_ack_i(r_ack[0]), .wb_err_i(r_err[0]));

    albatross_export #(.ADDR_WIDTH(AW), .WORDS_WIDTH(12), .COUNT_WIDTH(1), .TAKEN_AT(1), .DESTS(4), .DROP(1)) u_export (
        .clk_i(clk_i), .rst_i(rst_i),
        .start_i(exp_start), .drop_run_i(drop_run), .four_i(four), .base_i(dst_base), .need_i(exp_need), .words_i(words), .taken_at_i(exp_taken),
        .act_known_i(known_in), .act_i(st_act), .tried_i(exp_tried_in),
        .may_access_i(may_access), .idle_o(exp_idle),
        .word_i(word), .word_valid_i(word_ok), .word_ready_o(exp_ready), .word_index_o(exp_index),
        .done_o(exp_done), .published_o(exp_published), .corrupt_o(exp_corrupt), .cut_o(exp_cut),
        .fails_o(exp_fails), .act_known_o(exp_known), .act_o(exp_act), .tried_o(exp_tried), .dest_o(exp_dest),
        .wb_cyc_o(r_cyc[1]), .wb_stb_o(exp_stb), .wb_we_o(r_we[1]), .wb_adr_o(r_adr[AW +: AW]), .wb_sel_o(r_sel[4 +: 4]),
        .wb_dat_o(r_wdat[32 +: 32]), .wb_dat_i(bus_rdat), .wb_ack_i(r_ack[1]), .wb_err_i(r_err[1]));

    // The sync-mode poll: a load of the SYNC source's control word.
    assign r_cyc[2]          = poll_cyc;
    assign r_we[2]           = 1'b0;
    assign r_adr[2*AW +: AW] = poll_adr;
    assign r_sel[8 +: 4]     = 4'b0001 << ALB_CH_OFF_ACTUAL;
    assign r_wdat[64 +: 32]  = 32'd0;

    // ------------------------------------------------------------ bus master
    wire        fail;
    wire [15:0] fails_total;
    wire        overlap;
    albatross_bus_master #(.ADDR_WIDTH(AW), .BOARD_BITS(4), .REQS(3), .TIMEOUT(TIMEOUT)) u_bus (
        .clk_i(clk_i), .rst_i(rst_i),
        .r_cyc_i(r_cyc), .r_we_i(r_we), .r_adr_i(r_adr),
        .r_board_i({poll_board, dst_board[4*exp_dest +: 4], src_board}),
        .r_sel_i(r_sel), .r_dat_i(r_wdat), .r_dat_o(bus_rdat), .r_ack_o(r_ack), .r_err_o(r_err),
        .m_cyc_o(m_cyc_o), .m_stb_o(m_stb_o), .m_we_o(m_we_o), .m_adr_o(m_adr_o), .m_sel_o(m_sel_o),
        .m_dat_o(m_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i), .m_err_i(m_err_i),
        .fail_o(fail), .fails_o(fails_total), .overlap_o(overlap));

    // ------------------------------------------------------------ slot end and write-back
    // The slot ends with the Export, or with the Import if no Export started.
    wire [7:0] act_after;
    generate
        for (g = 0; g < 4; g = g + 1) begin : g_act
            assign act_after[2*g +: 2] = exp_known[g] ? exp_act[2*g +: 2] : 2'd0;
        end
    endgenerate
    always @* begin
        slot_end    = (exp_run_q && exp_done) || (imp_run_q && !exp_run_q && imp_done);
        st_d[31:0]  = taken_q;
        st_d[34:32] = imp_rl_known ? imp_rl : 3'd0;
        st_d[38:35] = need_q & ~exp_published;
        st_d[46:39] = act_after;
        st_d[58:47] = exp_tried;
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            ready_q   <= 1'b0;
            clr_q     <= {CH_BITS{1'b0}};
            imp_run_q <= 1'b0;
            exp_run_q <= 1'b0;
            chosen_q  <= 1'b0;
            new_q     <= 1'b0;
            need_q    <= 4'd0;
            taken_q   <= 32'd0;
            sync_rl_q <= 2'd0;
        end else begin
            if (!ready_q) begin
                clr_q <= clr_q + 1'b1;
                if (clr_q == LAST_CH) ready_q <= 1'b1;
            end
            if (go) begin
                imp_run_q <= k_copy;
                exp_run_q <= !k_copy;
                chosen_q  <= 1'b0;
                new_q     <= 1'b0;
                need_q    <= active;
            end
            // exp_taken is slot_time at go: one load, no multiplexer.
            if (go || choose) taken_q <= exp_taken;
            if (choose) begin
                chosen_q <= 1'b1;
                new_q    <= imp_new;
                need_q   <= need_now;
                if (need_now != 4'd0) exp_run_q <= 1'b1;
            end
            if (slot_end) begin
                imp_run_q <= 1'b0;
                exp_run_q <= 1'b0;
                if (sync_entry) sync_rl_q <= st_d[33:32];      // (SYNC is never four-slot: entry_check)
            end
        end
    end

    // ------------------------------------------------------------ counters
    // Totals of the slot (the counters sample them with slot_end).
    wire [2:0] xfers    = exp_run_q ? popcount4(exp_published) : 3'd0;
    wire [2:0] corrupts = ((imp_run_q && imp_done && imp_corrupt) ? 3'd1 : 3'd0) +
                          ((exp_run_q && exp_done) ? popcount4(exp_corrupt) : 3'd0);
    // need after the slot: the state RAM's copy if the Export did not run.
    wire [3:0] need_end = exp_run_q ? st_d[38:35] : st_need;
    wire [2:0] abandons = popcount4(need_end & active);
    albatross_counters #(.N_CHAN(N_CHAN), .INDEX_WIDTH(12)) u_counters (
        .clk_i(clk_i), .rst_i(rst_i), .ready_o(cnt_ready),
        .retry_i(fail), .transfers_i(xfers), .abandoned_i(abandons), .corrupt_i(corrupts),
        .commit_i(slot_end), .chan_i(chan5), .busy_o(cnt_busy),
        .rom_errors_i(rom_errors_o), .cycles_i(cycles),
        .status_index_i(exp_index), .status_o(status_word), .status_valid_o(status_valid));

    // Signals kept for waveforms and proofs only.
    wire unused = &{1'b0, imp_idle, imp_cut, imp_fails, imp_index, exp_idle, exp_cut, exp_fails,
                    fails_total, overlap, cycle_start, imp_stb, exp_stb, cnt_busy, act_known_in[7], act_known_in[5], act_known_in[3],
                    act_known_in[1]};

endmodule

`default_nettype wire
