// albatross_sequencer -- the controller's schedule sequencer: the schedule
// ROM, the cycle and slot timing, the deadline and the global time
// (docs/controller.md "Execution").
// Rules:
//   * Global time, time within a cycle (rel, TIME_BITS wide, from the cycle
//     start), S, D and the deadline check: rtl/albatross_slot_timing.v.  The
//     header's cycle length and every slot's start and length must fit in
//     TIME_BITS bits (higher bits set: the header, or the entry, is invalid).
//   * ROM format (rtl/albatross_contract.toml): header H0..H3, entry k at
//     word 4 + 8k; an image with modes starts in mode 0 (entries 0 ..
//     H2.start_end - 1, else 0 .. NE - 1).  The parts keep their own rules:
//     the ROM and the word read in each clock rtl/albatross_schedule_rom.v,
//     the header's checks rtl/albatross_header_check.v, the start-up CRC,
//     the prefix signatures and the background re-check (a part's first
//     mismatch adds 1 to rom_errors and marks it bad: a bad entry is skipped
//     as an invalid one) rtl/albatross_rom_check.v, the mode switch (loaded
//     in ST_CYCLE_END, taken at a cycle boundary only, which waits for a
//     load that has begun) rtl/albatross_mode_switch.v.
//   * Start-up (after enable_i): read the header (5 clocks), then one CRC
//     pass over the image (its first read issued in the header's last
//     clock).  An invalid header or a CRC other than 0 raises error_o for
//     good: the sequencer never starts a slot or a poll.
//   * Slot timing: S = cycle start + start (E1).  The entry is fetched in
//     clocks S .. S+FETCH_CYCLES-2 (FETCH_CYCLES = 7) and go_o is high in
//     clock S+FETCH_CYCLES-1 with its fields: an engine started by go_o puts its
//     first access on the bus in clock S+FETCH_CYCLES.  slot_time_o = S
//     (global time): TIME publishes it.  An entry found invalid while it is
//     fetched (rtl/albatross_entry_check.v: fields as docs/controller.md
//     "Validation" lists, the slot order, the cycle end, a bad mark) gets
//     no go_o and adds 1 to rom_errors, once per cycle; an IDLE entry gets
//     no go_o.
//   * Minor cycles (HAS_MULTIRATE; the count and the due test:
//     rtl/albatross_minor_cycles.v): every entry, due or not, is fetched in
//     every cycle exactly as above, and only a due one gets go_o: a non-due
//     entry costs its fetch (clocks S .. S+6, no bus access, no rom_errors,
//     no slot end for the order check), like an IDLE one.  The due test is
//     needed from FETCH clock 1 on (the entry check) and in FETCH clock 5
//     (go_q), so E6 is read ahead: entry 0's in the clock after the start-up
//     pass, entry k's in FETCH clock 6 of the entry before it, the new mode's
//     first entry's in the mode load.  The entry register ent_q moves on to
//     the next entry in FETCH clock 5 (E6 of the next entry is {ent_q + 1,
//     010}: the ROM's one incrementer), where the count steps if it wraps to
//     the mode's first; last_q and ent0_q keep what the rest of the slot
//     needs of the entry that runs.
//   * E7 (HAS_FRAGMENTS; rtl/albatross_entry_fields.v): read in the first
//     clock of the entry's transfer (a main read: the background check waits
//     a clock), frag_on_o (its frag field is not 0) from the clock after,
//     held until the next transfer's.
//   * Deadline D = cycle start + start + length.  may_access_o is high in a
//     clock c of a slot when an access put on the bus in clock c+1 ends
//     before D even if it times out: c + 1 <= D - TIMEOUT - 2.  go_o and
//     the deadline check are registers, decided in the clock before.
//   * The slot ends at slot_done_i; the next entry waits for its start.
//     After the last entry: time-rigid, the next cycle starts at cycle start
//     + H1; position-synchronised (H0 flag, entry 0 a valid SYNC COPY), the
//     sequencer loads the SYNC source's control word every POLL clocks on the
//     poll port, and the next cycle starts in the clock after a poll's ack
//     that shows a valid Actual other than sync_rl_i, or at cycle start + H1
//     (a poll still on the bus is then dropped).  cycle_o pulses at each cycle
//     start; cycles_o counts them (16-bit, saturating: rtl/albatross_seq_status.v).
//   * Reset (synchronous) clears control state; RAMs are never reset.
`default_nettype none

module albatross_sequencer #(
    parameter NB         = 4,    // boards on the system bus, 1..16
    parameter ADDR_WIDTH = 10,   // word-address bits of a board RAM, 3..12
    parameter N_CHAN     = 32,   // channel ids, 1..128
    parameter ROM_WORDS  = 1024, // schedule ROM depth in 32-bit words, >= 12
    parameter ROM_FILE   = "",   // $readmemh image; simulation: +rom=FILE overrides
    parameter TIME_BITS  = 16,   // bits of time within a cycle, 4..31
    parameter TIMEOUT    = 8,    // clocks before a silent access fails (the deadline margin)
    parameter POLL       = 16,   // sync mode: clocks from one poll's start to the next, >= 2
    parameter HAS_SYNC   = 1,    // 1: position-synchronised mode polls; 0: every cycle is H1 long
    parameter HAS_ROM_RECHECK = 1, // 1: the background re-check of the ROM; 0: the start-up CRC only
    parameter HAS_ENTRY_CHECK = 1, // 1: the entry field checks at fetch; 0: none
    parameter CRC_BITS   = 4,    // bits of a ROM word the ROM check's CRC takes in a clock (albatross_rom_check)
    parameter HAS_MODES  = 1,    // 1: mode switches on request (albatross_mode_switch); 0: the start-up mode only
    parameter HAS_MULTIRATE = 1, // 1: entries run in the minor cycles of their E6 (base, rep); 0: every entry in every cycle
    parameter CLUSTER_BITS  = 15, // bits of the minor-cycle count: reps up to CLUSTER_BITS (1..15)
    parameter HAS_FRAGMENTS = 1  // 1: E7.frag != 0 of the running entry on frag_on_o; 0: frag_on_o is 0
) (
    input  wire                    clk_i,
    input  wire                    rst_i,          // synchronous, active high
    input  wire                    enable_i,       // the channel state is cleared: start up
    // slot command
    output wire                    go_o,           // one clock: start the entry's transfer
    output wire [1:0]              kind_o,         // ALB_KIND_* (low bits)
    output wire [6:0]              chan_o,         // channel id (valid from FETCH clock 2 on)
    output wire [2:0]              nd_o,           // destinations 1..4
    output wire [11:0]             words_o,        // W
    output wire [3:0]              src_board_o,
    output wire [ADDR_WIDTH-1:0]   src_base_o,
    output wire [15:0]             dst_board_o,    // destination d at [4d +: 4]
    output wire [4*ADDR_WIDTH-1:0] dst_base_o,     // destination d at [d*ADDR_WIDTH +: ADDR_WIDTH]
    output wire [31:0]             slot_time_o,    // S, the slot's nominal start
    output wire                    frag_on_o,      // E7.frag != 0 for the running entry, valid from 2 clocks after go_o
    output wire                    sync_entry_o,   // the entry is the SYNC COPY (entry 0, sync mode)
    output wire                    four_o,         // E0 flag FOUR_SLOT: the channel is of the four-slot kind
    output wire                    request_o,      // E0 flag REQUEST: a COPY whose New value is a mode request
    output wire                    mode_info_o,    // E0 flag MODE: a STATUS of {mode_o, mode_since_o}
    output wire                    may_access_o,   // an access begun next clock ends before D
    input  wire                    slot_done_i,    // one clock: the transfer is over
    // sync-mode poll: a Wishbone B4 classic read of the SYNC source's control word
    output wire                    poll_cyc_o,
    output wire [3:0]              poll_board_o,
    output wire [ADDR_WIDTH-1:0]   poll_adr_o,
    input  wire [31:0]             poll_dat_i,     // only the Actual byte is read
    input  wire                    poll_ack_i,
    input  wire                    poll_err_i,
    input  wire [1:0]              sync_rl_i,      // the SYNC channel's ReadLocked copy (0: unknown)
    // status
    output wire [31:0]             time_o,
    output wire                    cycle_o,        // one clock: a cycle starts
    output wire                    error_o,        // the ROM is invalid: idle for good
    output wire [15:0]             rom_errors_o,   // skipped entries and background mismatches
    output wire [15:0]             cycles_o,
    output wire [7:0]              drop_run_o,     // the running mode's drop run K (H2, or its descriptor)
    // schedule modes (rtl/albatross_mode_switch.v; images without modes: none)
    input  wire                    mode_req_i,     // one clock: a request for mode mode_req_mode_i
    input  wire [3:0]              mode_req_mode_i,
    output wire [3:0]              mode_o,         // the running mode
    output wire [31:0]             mode_since_o,   // time_o in the first clock of the first cycle in it
    output wire                    mode_reject_o   // one clock: a request was rejected
);

`include "albatross_contract.vh"

    localparam FETCH_CYCLES = 7;                // slot start to the first access on the bus
    localparam MARGIN       = TIMEOUT + 2;      // an access on the bus in clock p needs p <= D - MARGIN
    localparam ROM_AW  = $clog2(ROM_WORDS);
    localparam TB      = TIME_BITS;
    localparam integer        MIN_LEN_I   = FETCH_CYCLES + MARGIN;

    generate
        if (NB < 1 || NB > 16 || ADDR_WIDTH < 3 || ADDR_WIDTH > ALB_ROM_PLACE_BASE_W || N_CHAN < 1 ||
            N_CHAN > 128 || ROM_WORDS < 12 || TIME_BITS < 4 || TIME_BITS > 31 || TIMEOUT < 2 || POLL < 2 ||
            CLUSTER_BITS < 1 || CLUSTER_BITS > 15 ||
            ALB_ROM_HEADER_WORDS != 4 || ALB_ROM_ENTRY_WORDS != 8) begin : g_param_check
            albatross_sequencer_parameter_out_of_range u_error ();
        end
    endgenerate

    // Contract check: the decoder takes these widths and positions from
    // rtl/albatross_contract.toml as literals (12-bit W, 8-bit id, 4-bit kind
    // and ND, places of {board[3:0], base[11:0]} in the low and high halves,
    // time fields at least TIME_BITS wide); a definition without them stops
    // elaboration.
    generate
        if (ALB_ROM_E0_W_W != 12 || ALB_ROM_E0_ID_W != 8 || ALB_ROM_E0_KIND_W != 4 || ALB_ROM_E0_ND_W != 4 ||
            ALB_ROM_PLACE_BOARD_W != 4 || ALB_ROM_PLACE_BASE_W != 12 || ALB_ROM_E3_SRC_LSB != 0 ||
            ALB_ROM_E4_DST0_LSB != 0 || ALB_ROM_E4_DST1_LSB != 16 || ALB_ROM_E5_DST2_LSB != 0 ||
            ALB_ROM_E5_DST3_LSB != 16 || ALB_ROM_H0_MAGIC_W != 16 || ALB_ROM_H0_NE_W != 8 ||
            ALB_ROM_TIME_BITS < TIME_BITS || ALB_ROM_CRC_WORD != 3 || ALB_ROM_E1_START_LSB != 0 ||
            ALB_ROM_E2_LENGTH_LSB != 0 || ALB_ROM_H1_CYCLE_LSB != 0 || ALB_ROM_H2_DROP_RUN_W != 8 ||
            ALB_ROM_E6_BASE_W != 15 || ALB_ROM_E6_REP_W != 4) begin : g_contract_check
            albatross_sequencer_contract_mismatch u_error ();
        end
    endgenerate

    // States of the sequencer.
    localparam [2:0] ST_HEADER    = 3'd0,  // read H0, H1, H2 and entry 0's start
                     ST_CHECK     = 3'd1,  // start-up CRC pass over the image
                     ST_ERROR     = 3'd2,  // the ROM is invalid: idle for good
                     ST_WAIT      = 3'd3,  // wait for the start of entry ent_q
                     ST_FETCH     = 3'd4,  // fetch entry ent_q (step_q = clock of the fetch)
                     ST_TRANSFER  = 3'd5,  // the engines run the entry's transfer
                     ST_CYCLE_END = 3'd6;  // after the last entry: wait (or poll) for the next cycle

    reg [2:0]          state_q;
    reg [2:0]          step_q;        // clock within ST_HEADER, ST_FETCH
    wire [7:0]         ne_q;          // H0's NE and sync flag (u_hdr, below)
    wire               smode_q;
    wire               hdr_bad;       // a header word is invalid
    reg [7:0]          ent_q;         // the entry fetched; from FETCH clock 6 on, the next one
    reg                last_q;        // the entry that runs is its mode's last (from FETCH clock 6 on)
    reg                ent0_q;        // the entry that runs is entry 0 (from FETCH clock 6 on)
    reg                bad_q;         // the entry being fetched is invalid
    reg                err_q;         // the start-up CRC failed
    reg                cycle_q1;      // cycle_o

    // The clocks (u_time, below): time_q is time_o; start_now the clock S of
    // a slot; start_q is E1 of entry ent_q, from FETCH clock 6 on of entry
    // ent_q + 1 (of entry 0 after the last entry and after the header); end_q
    // is D in rel; cycle_end: rel >= H1 - 1 (late only if a slot overran).
    wire [31:0]        time_q;
    wire [TB-1:0]      start_q;
    wire               start_bad_q, start_now, cycle_end;
    wire [TB:0]        end_q;
    wire [TB-1:0]      prev_end_q;    // end_q of the last slot that ran (a valid end: below 2^TB)

    // ------------------------------------------------------------ ROM and its read port
    wire               main_rom;      // a main read: the background check waits
    wire [31:0]        rom_q;         // the word read in the previous clock
    // The start-up pass issues its first read in the header's last clock
    // (step 4, which reads no header word): its CRC is compared a clock
    // after its last word's check (a register compare), and the first
    // cycle still starts in the clock it would with the compare in the
    // check's own clock.
    wire               hdr_last  = state_q == ST_HEADER && step_q == 3'd4;
    wire               bg_on     = state_q == ST_CHECK || hdr_last || (HAS_ROM_RECHECK != 0 && (state_q == ST_WAIT ||
                                   state_q == ST_TRANSFER || state_q == ST_CYCLE_END));
    /* verilator lint_off UNUSEDSIGNAL */
    wire [ROM_AW+11:0] last_wide = {{ROM_AW{1'b0}}, 1'b0, ne_q, 3'b011}; // 4 + 8*NE - 1
    /* verilator lint_on UNUSEDSIGNAL */
    wire [ROM_AW-1:0]  last_word = last_wide[ROM_AW-1:0];
    wire [ROM_AW-1:0]  bg_adr;        // the ROM check's next word
    wire [7:0]         ent_inc   = ent_q + 8'd1;
    wire               last_ent  = ent_inc == m_end;
    wire               pass_done, crc_ok, mism_new, bad_mark;   // (the ROM check, below)
    wire               e7_rd;         // E7 of the entry that runs is read now (u_fields, below) ...
    wire [7:0]         e7_ent;        // ... at {e7_ent, 011}
    // E6 of entry 0 ({ent_q + 1, 010}, ent_q 0 since reset) is read in the
    // clock after the start-up pass (its CRC compare; the check issues no read
    // then) and taken in the first clock of the first cycle: the due test needs
    // it from FETCH clock 1 on, so even an entry at start 0 has it in time.
    wire               hdr_e6    = state_q == ST_CHECK && pass_done && crc_ok;
    albatross_schedule_rom #(.ROM_WORDS(ROM_WORDS), .ROM_FILE(ROM_FILE),
                             .HAS_E6(HAS_MULTIRATE != 0 || HAS_ENTRY_CHECK != 0)) u_rom (
        .clk_i(clk_i), .time_i(time_q), .header_i(state_q == ST_HEADER && !hdr_last), .start_i(start_now),
        .fetch_i(state_q == ST_FETCH), .step_i(step_q), .ent_i(ent_q), .ent_inc_i(ent_inc), .last_i(last_ent),
        .first_i(m_first), .mode_rd_i(mode_rd), .mode_adr_i(mode_adr), .e1_i(mode_e1_rd), .e6_i(mode_e6_rd || hdr_e6),
        .e7_i(e7_rd && state_q == ST_TRANSFER), .e7_ent_i(e7_ent),
        .bg_adr_i(bg_adr),
        .main_o(main_rom), .dat_o(rom_q));

    // The header's fields and checks (rtl/albatross_header_check.v).
    albatross_header_check #(.ROM_WORDS(ROM_WORDS), .TIME_BITS(TB)) u_hdr (
        .clk_i(clk_i), .rst_i(rst_i), .hdr_i(state_q == ST_HEADER), .step_i(step_q), .rom_i(rom_q),
        .ne_o(ne_q), .smode_o(smode_q), .bad_o(hdr_bad));

    // ------------------------------------------------------------ the running schedule and its modes
    // The cycle's entries (m_first .. m_end - 1), its length and drop run come
    // from the header and change at a mode switch, at a cycle boundary only
    // (rtl/albatross_mode_switch.v); a request is loaded while the sequencer
    // waits for the cycle end, and the boundary waits for a load that has
    // begun (mode_hold).
    wire               mode_rd, mode_e1, mode_hold, mode_commit, mode_first_ld, mode_e1_rd, mode_e6_rd, mode_e6;
    wire               new_cycle;     // the cycle boundary (control, below)
    wire [ROM_AW-1:0]  mode_adr;
    wire [7:0]         m_first, m_end, m_next_first, m_drop;
    wire [TB-1:0]      cycle_q;       // the running mode's cycle length (H1, or its descriptor's)
    wire [3:0]         m_cluster;     // the running mode's cluster c (H2, or its descriptor's D2)
    albatross_mode_switch #(.ROM_AW(ROM_AW), .TIME_BITS(TB), .HAS_MODES(HAS_MODES)) u_mode (
        .clk_i(clk_i), .rst_i(rst_i), .hdr1_i(state_q == ST_HEADER && step_q == 3'd2),
        .hdr2_i(state_q == ST_HEADER && step_q == 3'd3), .ne_i(ne_q), .rom_i(rom_q),
        .req_i(mode_req_i), .req_mode_i(mode_req_mode_i), .idle_i(state_q == ST_CYCLE_END), .switch_i(new_cycle),
        .read_o(mode_rd), .read_adr_o(mode_adr), .first_ld_o(mode_first_ld), .e1_rd_o(mode_e1_rd), .e6_rd_o(mode_e6_rd),
        .e1_o(mode_e1), .e6_o(mode_e6), .hold_o(mode_hold),
        .reject_o(mode_reject_o), .commit_o(mode_commit), .mode_o(mode_o), .first_o(m_first), .end_o(m_end),
        .next_first_o(m_next_first),
        .cycle_o(cycle_q), .drop_o(m_drop), .cluster_o(m_cluster));

    // ------------------------------------------------------------ minor cycles and the due test
    // E6 of entry ent_q, read ahead (after the start-up pass, FETCH clock 6,
    // the mode load), judged in the clock its word is in rom_q
    // (rtl/albatross_minor_cycles.v): due (in the cycle it runs in) and rep
    // for the entry check, held until the next E6.  The count steps when
    // ent_q wraps to the mode's first entry (FETCH clock 5 of the last), and
    // the mode load's new first entry clears it.
    localparam MR = HAS_MULTIRATE != 0;
    wire          due, e6_tick;
    wire [3:0]    e6_rep;
    assign e6_tick = state_q == ST_FETCH && step_q == 3'd5 && last_ent;
    albatross_minor_cycles #(.HAS_MULTIRATE(HAS_MULTIRATE), .HAS_E6_CHECK(HAS_ENTRY_CHECK),
                             .CLUSTER_BITS(CLUSTER_BITS)) u_minor (
        .clk_i(clk_i), .rst_i(rst_i), .step_i(e6_tick), .clear_i(mode_first_ld), .e6_hdr_i(hdr_e6),
        .e6_fetch_i(state_q == ST_FETCH && step_q == 3'd6), .e6_mode_i(mode_e6), .rom_i(rom_q),
        .due_o(due), .rep_o(e6_rep));

    // ------------------------------------------------------------ ROM check
    // The start-up CRC and the background re-check; in the clock S of a
    // fetch it reads the fetched entry's bad mark for FETCH clock 1.
    // (pass_done: the clock after the start-up pass's last check)
    albatross_rom_check #(.ROM_WORDS(ROM_WORDS), .HAS_ROM_RECHECK(HAS_ROM_RECHECK), .CRC_BITS(CRC_BITS)) u_rom_check (
        .clk_i(clk_i), .rst_i(rst_i), .learn_i(state_q == ST_CHECK), .bg_on_i(bg_on),
        .main_rom_i(main_rom), .last_word_i(last_word), .adr_o(bg_adr), .rom_dat_i(rom_q),
        .fetch_i(start_now), .fetch_part_i(ent_inc), .last_o(pass_done), .crc_ok_o(crc_ok),
        .mism_o(mism_new), .bad_o(bad_mark));

    // ------------------------------------------------------------ field checks at fetch
    // The entry's fields, taken in the fetch clocks, and E7 of the entry that runs
    // (rtl/albatross_entry_fields.v), straight on the slot command's ports.
    wire [13:0]         span;          // 3 * W (four-slot: 4 * W)
    albatross_entry_fields #(.ADDR_WIDTH(ADDR_WIDTH), .HAS_MODES(HAS_MODES), .HAS_FRAGMENTS(HAS_FRAGMENTS)) u_fields (
        .clk_i(clk_i), .rst_i(rst_i), .fetch_i(state_q == ST_FETCH), .step_i(step_q), .rom_i(rom_q),
        .ent_inc_i(ent_inc), .go_i(go_now), .e7_rd_o(e7_rd), .e7_ent_o(e7_ent), .frag_on_o(frag_on_o),
        .kind_o(kind_o), .sync_o(sync_entry_o), .four_o(four_o), .request_o(request_o), .mode_info_o(mode_info_o),
        .chan_o(chan_o), .nd_o(nd_o), .words_o(words_o), .span_o(span), .src_board_o(src_board_o),
        .src_base_o(src_base_o), .dst_board_o(dst_board_o), .dst_base_o(dst_base_o));
    wire        bad_now;
    albatross_entry_check #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .N_CHAN(N_CHAN), .TIME_BITS(TB),
                            .MIN_LEN(MIN_LEN_I), .HAS_ENTRY_CHECK(HAS_ENTRY_CHECK),
                            .MAX_REP(MR ? CLUSTER_BITS : 0)) u_entry_check (
        .step_i(step_q), .rom_i(rom_q), .ent0_i(ent_q == 8'd0), .smode_i(smode_q), .bad_mark_i(bad_mark),
        .kind_i(kind_o), .four_i(four_o), .nd_i(nd_o), .e3_i(span), .start_i(start_q), .start_bad_i(start_bad_q),
        .cycle_i(cycle_q), .prev_end_i(prev_end_q), .end_i(end_q), .cluster_i(m_cluster), .due_i(due),
        .rep_i(e6_rep), .bad_o(bad_now));

    // ------------------------------------------------------------ control
    // The global time, rel, S, D and the deadline check (rtl/albatross_slot_timing.v).
    wire fetch6     = state_q == ST_FETCH && (step_q == 3'd0 || step_q >= 3'd6);   // FETCH clock 6 (0, 7: never)
    albatross_slot_timing #(.TIME_BITS(TB), .MARGIN(MARGIN), .D_BOUNDED(HAS_ENTRY_CHECK != 0)) u_time (
        .clk_i(clk_i), .rst_i(rst_i), .rom_i(rom_q), .e1_i(hdr_last || fetch6 || (state_q == ST_CYCLE_END && mode_e1)),
        .e2_i(state_q == ST_FETCH && step_q == 3'd2), .ran_i(fetch6 && !bad_q && due), .wait_i(state_q == ST_WAIT),
        .run_i(state_q == ST_TRANSFER || go_now), .new_cycle_i(new_cycle), .cycle_i(cycle_q),
        .time_o(time_q), .slot_time_o(slot_time_o), .at_start_o(start_now), .cycle_end_o(cycle_end),
        .may_access_o(may_access_o), .start_o(start_q), .start_bad_o(start_bad_q), .end_o(end_q), .prev_end_o(prev_end_q));
    wire poll_hit;     // a poll shows a new position (u_poll, below)
    wire entry_over = (state_q == ST_FETCH && step_q == 3'd6 && !go_now) ||     // invalid, IDLE or not due
                      (state_q == ST_TRANSFER && slot_done_i);
    assign new_cycle = (state_q == ST_CYCLE_END && (cycle_end || poll_hit) && !mode_hold) ||
                      (entry_over && last_q && cycle_end && !mode_hold) ||     // the last slot ends at H1 - 1
                      (state_q == ST_CHECK && pass_done && crc_ok);
    // The sync-mode poll (rtl/albatross_sync_poll.v): entry 0's place, taken
    // in its fetch's last clock, is loaded every POLL clocks while the
    // sequencer waits for the cycle end.
    albatross_sync_poll #(.ADDR_WIDTH(ADDR_WIDTH), .POLL(POLL), .HAS_SYNC(HAS_SYNC)) u_poll (
        .clk_i(clk_i), .rst_i(rst_i), .capture_i(fetch6 && ent0_q),
        .sync_i(!bad_q && sync_entry_o), .board_i(src_board_o), .base_i(src_base_o), .smode_i(smode_q),
        .wait_i(state_q == ST_CYCLE_END), .entry_over_i(entry_over), .new_cycle_i(new_cycle),
        .poll_dat_i(poll_dat_i), .poll_ack_i(poll_ack_i), .poll_err_i(poll_err_i), .sync_rl_i(sync_rl_i),
        .poll_cyc_o(poll_cyc_o), .poll_board_o(poll_board_o), .poll_adr_o(poll_adr_o), .hit_o(poll_hit));
    // go is a register, decided a clock ahead (as the deadline check, u_time),
    // so that the transfer's decisions start at registers: go_q in FETCH clock
    // 5 from the entry's kind and the due test (go = go_q and not bad_q: the
    // entry's checks are all in bad_q in clock 6).
    reg         go_q;
    wire        go_now   = go_q && !bad_q;
    always @(posedge clk_i)
        go_q      <= !rst_i && state_q == ST_FETCH && step_q == 3'd5 && kind_o != ALB_KIND_IDLE[1:0] && due;

    // rom_errors, cycles (saturating) and the running mode's since (rtl/albatross_seq_status.v).
    albatross_seq_status u_status (
        .clk_i(clk_i), .rst_i(rst_i), .err_i(mism_new | (entry_over && state_q == ST_FETCH && bad_q)),
        .cycle_i(new_cycle), .commit_i(mode_commit), .time_i(time_q),
        .rom_errors_o(rom_errors_o), .cycles_o(cycles_o), .since_o(mode_since_o));

    always @(posedge clk_i) begin
        cycle_q1 <= 1'b0;
        if (rst_i) begin
            state_q   <= ST_HEADER;
            step_q    <= 3'd0;
            err_q     <= 1'b0;
            ent_q     <= 8'd0;            // (E6 of entry 0 is read as {ent_q + 1, 010})
        end else begin
            case (state_q)
                ST_HEADER: if (enable_i || step_q != 3'd0) begin
                    step_q <= step_q + 3'd1;
                    if (step_q == 3'd4) state_q <= hdr_bad ? ST_ERROR : ST_CHECK;  // u_time takes E1 of entry 0 (E6 read now)
                end
                ST_CHECK: if (pass_done) begin
                    if (!crc_ok) begin                                    // else new_cycle
                        state_q <= ST_ERROR;
                        err_q   <= 1'b1;
                    end
                end
                ST_WAIT: if (start_now) begin
                    state_q     <= ST_FETCH;
                    step_q      <= 3'd1;
                    bad_q       <= 1'b0;
                end
                ST_FETCH: begin
                    step_q <= step_q + 3'd1;
                    if (bad_now) bad_q <= 1'b1;
                    case (step_q)
                        3'd1, 3'd2, 3'd3, 3'd4: ;                               // E0, E2..E4: u_fields, u_time (D)
                        3'd5: begin                                             // E5: u_fields; on to the next entry
                            ent_q  <= last_ent ? m_next_first : ent_inc;     // (the mode's first: no switch mid-cycle)
                            last_q <= last_ent;
                            ent0_q <= ent_q == 8'd0;
                        end
                        default: if (go_now) state_q <= ST_TRANSFER;            // u_time takes E1 of the next entry (its E6 read now)
                    endcase
                end
                ST_CYCLE_END: if (mode_first_ld) ent_q <= m_next_first;    // the new first entry (its E6 read next; u_time its E1)
                default: ;
            endcase
            if (entry_over) state_q <= last_q ? ST_CYCLE_END : ST_WAIT;
            if (new_cycle) begin
                ent_q       <= m_next_first;
                state_q     <= ST_WAIT;
                cycle_q1    <= 1'b1;
            end
        end
    end

    assign go_o         = go_now;
    assign time_o       = time_q;
    assign cycle_o      = cycle_q1;
    assign error_o      = err_q || hdr_bad;
    assign drop_run_o   = m_drop;

endmodule

`default_nettype wire
