// albatross_controller -- the ALBATROSS communication controller (paper
// sections 3.2-3.4).
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
//   albatross_transfer    the one transfer datapath: the source's Import
//                         (figure 3), the Export (figure 4) to up to 4
//                         destinations, TIME and STATUS, on one requester
//   albatross_bus_master  the one bus port: board field, timeout; its
//                         requesters are the datapath (0) and the poll (1);
//                         every field passes through (HOLD_FIELDS 0: both
//                         keep we, address, sel and store data stable
//                         until the answer)
//   albatross_counters    per-channel counters and the STATUS words
//                         (HAS_STATUS)
// Rules:
//   * Per-channel state (one RAM word per channel id, read while the entry is
//     fetched; cleared after reset, never reset): the source ReadLocked copy
//     (0 unknown; four-slot: L, the buffer read last), the destinations that
//     still need the current value and the buffer of each destination's
//     failed Actual store (0 none), all written back when the slot ends (no
//     copy of a destination's Actual: the Export loads it with ReadLocked);
//     and the current value's taken_at, written with time_o in the clock a
//     New value is chosen (the datapath's taken_at stores read it back from
//     the RAM).
//   * Fragments (HAS_FRAGMENTS): the state word also keeps whether a value
//     carried over several runs goes on and its progress (the first word
//     not yet stored to every destination in it), each written at a slot's
//     end where it changes and cleared with the rest after
//     reset (a value cut by a reset restarts with a fresh Import; nothing
//     partial is published); a mode switch keeps it (the value goes on
//     whole when its channel next runs).  The source buffer held is the
//     ReadLocked copy, the destinations still in the value are the need
//     field and their picked buffers the tried field.  A slot that ends
//     with its value going on counts only the destinations it dropped as
//     abandoned.
//   * The datapath's rules (order, retries, drop, cut-off) are in
//     rtl/albatross_transfer_fsm.v.  A destination it published leaves need; at
//     the slot's end each destination still in need counts as abandoned, and
//     a later slot of the channel delivers it.  A value is published to a
//     destination at most once, so redundant slots never show one value as
//     New twice.
//   * Optional parts (parameters HAS_*, default 1): the counters and STATUS
//     words, the sync-mode poll, the background ROM re-check, the entry field
//     checks, the schedule modes' switches, values in fragments.  With all
//     six 0 this is the core configuration.
//   * No bus access is ever made while the ROM is invalid (error_o): the
//     sequencer then never starts a slot or a poll.
// Adding a channel kind touches the datapath and the sequencer's decode.
`default_nettype none

module albatross_controller #(
    parameter NB         = 4,     // boards on the system bus, 1..16
    parameter ADDR_WIDTH = 10,    // word-address bits of a board RAM, 3..12
    parameter N_CHAN     = 32,    // channel ids with state and counters, 1..128
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in 32-bit words, at least 12
    parameter ROM_FILE   = "",    // $readmemh image of the ROM; "" leaves it zero (invalid header); simulation: +rom=FILE overrides
    parameter TIMEOUT    = 8,     // clocks of cyc without ack/err before an access fails, 3..60
    parameter POLL       = 16,    // sync mode: clocks from the start of one poll to the next, >= 2
    parameter TIME_BITS  = 16,    // bits of time within a cycle (the compiler's [bus] time_bits), 4..16
    parameter HAS_STATUS = 1,     // 1: per-channel counters and STATUS words; 0: STATUS entries send zeros
    parameter HAS_SYNC   = 1,     // 1: position-synchronised mode polls; 0: every cycle is H1 long
    parameter HAS_ROM_RECHECK = 1, // 1: the background re-check of the ROM; 0: the start-up CRC only
    parameter HAS_ENTRY_CHECK = 1, // 1: the entry field checks at fetch ("Validation"); 0: none
    parameter HAS_MODES  = 1,     // 1: schedule modes switch on request; 0: an image's start-up mode runs for good
    parameter HAS_FRAGMENTS = 1,  // 1: a COPY's value may go in fragments (E7.frag); 0: one slot carries a whole value
    parameter HAS_MULTIRATE = 1,  // 1: an entry runs in the minor cycles its E6 gives (multi-rate); 0: every entry in every cycle (E6 must be 0)
    parameter CLUSTER_BITS = 15,  // bits of the minor-cycle count: the largest rep (E6) it runs, 1..15
    parameter ROM_CRC_BITS = 4    // bits of a ROM word the CRC check takes a clock: 1, 2, 4, 8, 16, 32 (smaller is smaller, start-up 32/ROM_CRC_BITS clocks a word)
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
    localparam ST_W    = 1 + 12 + 12 + 4 + 3 + 32;      // {goes on, progress, tried, need, rl, taken}
    // The state RAM has at least 32 words from N_CHAN = 4 up (Yosys maps a RAM
    // of only a few words to flip-flops; 32 x 64 bits is block RAM, 4 iCE40
    // RAM blocks of 16 bits as 51 bits were; without HAS_FRAGMENTS the
    // fragment fields are never written nor read), a power
    // of two above 32; fewer channels (the formal harness) keep N_CHAN words.
    localparam ST_DEPTH = (N_CHAN > 32) ? (1 << CH_BITS) : (N_CHAN >= 4) ? 32 : N_CHAN;
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
    wire          go, may_access, sync_entry, poll_cyc, cycle_start, four, request, mode_info;
    wire [31:0]   mode_since;
    wire          tr_mode_req;
    wire [3:0]    tr_mode_req_mode;
    wire [1:0]    kind;
    wire [6:0]    chan7;
    wire [2:0]    nd;
    wire [11:0]   words;
    wire [3:0]    src_board, poll_board;
    wire [AW-1:0] src_base, poll_adr;
    wire [15:0]   dst_board, cycles;
    wire [7:0]    drop_run;     // the running mode's drop run K (ROM H2 or its mode descriptor)
    wire [3:0]    mode;
    wire          mode_reject;
    wire [4*AW-1:0] dst_base;
    wire [31:0]   slot_time;
    wire [31:0]   bus_rdat;
    wire [1:0]    r_ack, r_err;
    reg           slot_end;
    reg [1:0]     sync_rl_q;
    reg           ready_q;                                 // channel state cleared
    wire          cnt_ready;

    albatross_sequencer #(.NB(NB), .ADDR_WIDTH(AW), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS), .ROM_FILE(ROM_FILE),
                          .TIME_BITS(TIME_BITS), .TIMEOUT(TIMEOUT), .POLL(POLL), .HAS_SYNC(HAS_SYNC),
                          .HAS_ROM_RECHECK(HAS_ROM_RECHECK), .HAS_ENTRY_CHECK(HAS_ENTRY_CHECK), .CRC_BITS(ROM_CRC_BITS),
                          .HAS_MODES(HAS_MODES), .HAS_FRAGMENTS(HAS_FRAGMENTS), .HAS_MULTIRATE(HAS_MULTIRATE),
                          .CLUSTER_BITS(CLUSTER_BITS)) u_seq (
        .clk_i(clk_i), .rst_i(rst_i), .enable_i(ready_q && cnt_ready),
        .go_o(go), .kind_o(kind), .chan_o(chan7), .nd_o(nd), .words_o(words),
        .src_board_o(src_board), .src_base_o(src_base), .dst_board_o(dst_board), .dst_base_o(dst_base),
        .slot_time_o(slot_time), .frag_on_o(frag_on), .sync_entry_o(sync_entry), .four_o(four), .request_o(request), .mode_info_o(mode_info),
        .may_access_o(may_access), .slot_done_i(slot_end),
        .poll_cyc_o(poll_cyc), .poll_board_o(poll_board), .poll_adr_o(poll_adr), .poll_dat_i(bus_rdat),
        .poll_ack_i(r_ack[1]), .poll_err_i(r_err[1]), .sync_rl_i(sync_rl_q),
        .time_o(time_o), .cycle_o(cycle_start), .error_o(error_o), .rom_errors_o(rom_errors_o), .cycles_o(cycles),
        .drop_run_o(drop_run), .mode_req_i(tr_mode_req), .mode_req_mode_i(tr_mode_req_mode), .mode_o(mode),
        .mode_since_o(mode_since),
        .mode_reject_o(mode_reject));

    wire [CH_BITS-1:0] chan   = chan7[CH_BITS-1:0];
    wire [3:0]         active = {nd[2], nd >= 3'd3, nd >= 3'd2, nd != 3'd0};   // destinations 0..ND-1 (ND 0: a REQUEST COPY)
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
    wire              st_wr   = !ready_q || slot_end || tr_new;
    wire [ST_AW-1:0]  st_wa   = ready_q ? st_ix : clr_ix;
    wire              wr_exp, wr_imp, wr_tkn, wr_frg, wr_on;
    always @(posedge clk_i) begin
        if (st_wr) begin
            if (wr_tkn) st_mem[st_wa][31:0]  <= st_d[31:0];
            if (wr_imp) st_mem[st_wa][34:32] <= st_d[34:32];
            if (wr_exp) st_mem[st_wa][50:35] <= st_d[50:35];
            if (wr_frg) st_mem[st_wa][62:51] <= st_d[62:51];
            if (wr_on)  st_mem[st_wa][63]    <= st_d[63];
        end else begin
            st_q <= st_mem[st_ix];
        end
    end
    wire [11:0] st_tried = st_q[50:39];
    wire [3:0]  st_need  = st_q[38:35];
    wire [2:0]  st_rl    = st_q[34:32];
    wire [31:0] st_taken = st_q[31:0];

    // Fragments: whether a value goes on and its progress, fields of the
    // state word each written where it changes (wr_on, wr_frg); the
    // destination buffers of a run that goes on are the tried field (the
    // picks of the value's first run).
    wire [11:0] st_prog, tr_prog;
    wire        st_on, tr_on, tr_on_wr, tr_prog_wr;
    generate
        if (HAS_FRAGMENTS != 0) begin : g_frag_state
            assign st_on   = st_q[63];
            assign st_prog = st_q[62:51];
            assign wr_on   = !ready_q || (slot_end && tr_on_wr);     // (clearing: tr_on is 0 after reset)
            assign wr_frg  = !ready_q || (slot_end && tr_prog_wr);   // (clearing: tr_prog is 0 after reset)
        end else begin : g_no_frag_state
            assign st_on   = 1'b0;
            assign st_prog = 12'd0;
            assign wr_on   = 1'b0;
            assign wr_frg  = 1'b0;
            wire unused_frag = &{1'b0, st_q[63:51], tr_on_wr, tr_prog_wr};
        end
    endgenerate

    // ------------------------------------------------------------ transfer datapath
    // A MODE entry (a STATUS of W 2) publishes {the running mode, the time its
    // first cycle began} instead of the counters' words.
    wire [31:0] tr_status;
    wire        tr_status_valid;
    wire        tr_done, tr_imp, tr_exp, tr_new;
    wire [3:0]  tr_aband;
    wire        frag_on;        // E7.frag != 0 for the running entry (from 2 clocks after go)
    wire [2:0]  tr_rl, tr_xfers, tr_corrupt;
    wire [3:0]  tr_need;
    wire [11:0] tr_tried, tr_index;
    wire [31:0] status_word;
    wire        status_valid;
    wire        cnt_busy;
    // Requesters of the bus master: 0 the transfer datapath, 1 the poll.
    wire [1:0]  r_cyc, r_we;
    wire [2*AW-1:0] r_adr;
    wire [7:0]  r_sel, r_board;
    wire [63:0] r_wdat;

    albatross_transfer #(.ADDR_WIDTH(AW), .HAS_FRAGMENTS(HAS_FRAGMENTS)) u_transfer (
        .clk_i(clk_i), .rst_i(rst_i),
        .go_i(go), .copy_i(k_copy), .time_kind_i(k_time), .four_i(four), .request_i(request), .active_i(active),
        .words_i(words), .frag_on_i(frag_on),
        .src_board_i(src_board), .src_base_i(src_base), .dst_board_i(dst_board), .dst_base_i(dst_base),
        .slot_time_i(slot_time), .may_access_i(may_access), .drop_run_i(drop_run),
        .st_rl_i(st_rl), .st_need_i(st_need), .st_tried_i(st_tried), .st_taken_i(st_taken),
        .st_on_i(st_on), .st_prog_i(st_prog), .on_o(tr_on), .on_wr_o(tr_on_wr), .prog_o(tr_prog), .prog_wr_o(tr_prog_wr), .aband_o(tr_aband),
        .status_i(tr_status), .status_valid_i(tr_status_valid), .index_o(tr_index),
        .done_o(tr_done), .imp_run_o(tr_imp), .exp_run_o(tr_exp), .new_o(tr_new), .rl_o(tr_rl),
        .need_o(tr_need), .tried_o(tr_tried),
        .transfers_o(tr_xfers), .corrupt_o(tr_corrupt), .mode_req_o(tr_mode_req), .mode_req_mode_o(tr_mode_req_mode),
        .cyc_o(r_cyc[0]), .we_o(r_we[0]), .adr_o(r_adr[0 +: AW]), .board_o(r_board[3:0]), .sel_o(r_sel[3:0]),
        .dat_o(r_wdat[31:0]), .dat_i(bus_rdat), .ack_i(r_ack[0]), .err_i(r_err[0]));

    // The sync-mode poll: a load of the SYNC source's control word.
    assign r_cyc[1]        = poll_cyc;
    assign r_we[1]         = 1'b0;
    assign r_adr[AW +: AW] = poll_adr;
    assign r_board[7:4]    = poll_board;
    assign r_sel[7:4]      = 4'b0001 << ALB_CH_OFF_ACTUAL;
    assign r_wdat[63:32]   = 32'd0;

    // ------------------------------------------------------------ bus master
    wire        fail;
    wire [15:0] fails_total;
    wire        overlap;
    albatross_bus_master #(.ADDR_WIDTH(AW), .BOARD_BITS(4), .REQS(2), .TIMEOUT(TIMEOUT), .HOLD_FIELDS(0)) u_bus (
        .clk_i(clk_i), .rst_i(rst_i),
        .r_cyc_i(r_cyc), .r_we_i(r_we), .r_adr_i(r_adr), .r_board_i(r_board),
        .r_sel_i(r_sel), .r_dat_i(r_wdat), .r_dat_o(bus_rdat), .r_ack_o(r_ack), .r_err_o(r_err),
        .m_cyc_o(m_cyc_o), .m_stb_o(m_stb_o), .m_we_o(m_we_o), .m_adr_o(m_adr_o), .m_sel_o(m_sel_o),
        .m_dat_o(m_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i), .m_err_i(m_err_i),
        .fail_o(fail), .fails_o(fails_total), .overlap_o(overlap));

    // ------------------------------------------------------------ slot end and write-back
    always @* begin
        slot_end    = tr_done;
        st_d[31:0]  = time_o;                            // taken_at, written when New is chosen
        st_d[34:32] = tr_rl;
        st_d[38:35] = tr_need;
        st_d[50:39] = tr_tried;
        st_d[62:51] = tr_prog;
        st_d[63]    = tr_on;
    end
    assign wr_exp = !ready_q || (slot_end && tr_exp);
    assign wr_imp = !ready_q || (slot_end && tr_imp);
    assign wr_tkn = !ready_q || tr_new;

    always @(posedge clk_i) begin
        if (rst_i) begin
            ready_q   <= 1'b0;
            clr_q     <= {CH_BITS{1'b0}};
            sync_rl_q <= 2'd0;
        end else begin
            if (!ready_q) begin
                clr_q <= clr_q + 1'b1;
                if (clr_q == LAST_CH) ready_q <= 1'b1;
            end
            if (slot_end && sync_entry) sync_rl_q <= tr_rl[1:0];   // (SYNC is never four-slot: entry_check)
        end
    end

    // ------------------------------------------------------------ counters
    // need after the slot: the state RAM's copy if the Export did not run.
    // (a value that goes on: the destinations dropped in this slot.)
    wire [3:0] need_end = tr_exp ? tr_aband : st_need;
    wire [2:0] abandons = popcount4(need_end & active);
    // A rejected mode request (the clock of its REQUEST slot's end) counts as
    // a corrupt value of the request channel.
    wire [2:0] corrupts = slot_end ? tr_corrupt + {2'd0, mode_reject} : 3'd0;
    generate
        if (HAS_STATUS != 0) begin : g_counters
            albatross_counters #(.N_CHAN(N_CHAN), .INDEX_WIDTH(12)) u_counters (
                .clk_i(clk_i), .rst_i(rst_i), .ready_o(cnt_ready),
                .retry_i(fail), .transfers_i(tr_xfers), .abandoned_i(abandons), .corrupt_i(corrupts),
                .commit_i(slot_end), .chan_i(chan7), .busy_o(cnt_busy),
                .rom_errors_i(rom_errors_o), .cycles_i(cycles),
                .status_index_i(tr_index), .status_o(status_word), .status_valid_o(status_valid));
        end else begin : g_no_counters
            // No counters: a STATUS entry publishes zeros (the channel
            // id's bits above CH_BITS only ever went to the counters).
            wire unused_chan    = &{1'b0, chan7};
            assign cnt_ready    = 1'b1;
            assign cnt_busy     = 1'b0;
            assign status_word  = 32'd0;
            assign status_valid = 1'b1;
            wire unused_cnt = &{1'b0, fail, tr_xfers, abandons, corrupts, cycles, tr_index};
        end
    endgenerate

    // Signals kept for waveforms and proofs only.
    assign tr_status       = !mode_info ? status_word : tr_index[0] ? mode_since : {28'd0, mode};
    assign tr_status_valid = mode_info || status_valid;
    wire unused = &{1'b0, fails_total, overlap, cycle_start, cnt_busy};

endmodule

`default_nettype wire
