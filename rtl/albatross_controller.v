// albatross_controller -- the ALBATROSS communication controller (seed 3.2-3.4).
//
// The only master of the system bus (Wishbone B4 classic, address {board[3:0],
// word}).  It runs the cyclic schedule of a ROM ($readmemh ROM_FILE; in
// simulation +rom=FILE overrides it) as docs/controller.md
// specifies.  COPY runs the source's Import (seed figure 3) and each
// destination's Export (figure 4) in hardware, and streams every source word
// once to all destinations that need it.  TIME and STATUS publish the
// controller's time and counters.  Rules and timing (times are time_o values):
//   * Start-up: INIT clears the per-channel memories (2*N_CHAN clocks).  HDR
//     checks the header (TIMEOUT+5 clocks); if it is invalid, error_o goes high
//     and the bus is never touched.  SCAN checks every entry once
//     (max(TIMEOUT+6, 10) clocks each) and links the valid ones into a ring.
//     Cycle 0 starts (rel = 0) at
//         T0 = 2*N_CHAN + TIMEOUT + 8 + NE * max(TIMEOUT+6, 10).
//     At run time an invalid entry takes no clock; rom_errors goes up by 1 for
//     it once per cycle.  Every fetched entry's checksum is checked again, so
//     a ROM upset is flagged and the entry skipped.
//   * Slot timing (S = cycle start + E1): the entry is fetched in clocks
//     S..S+9, and its first access is on the bus in clock S+FETCH_CYCLES.
//     Every access holds cyc/stb until ack.  If no fault occurs, the next
//     access is on the bus in the clock right after the ack clock.  With
//     albatross_dpram, whose port B is served every other clock, the ack of
//     access k (1-based) is sampled at the edge that starts clock
//         S + FETCH_CYCLES + 2k + phi,  phi = 0 or 1: port-B phase, fixed in a slot.
//     So the first source Actual load completes at S + FETCH_CYCLES + 2 + phi
//     and the last of A accesses at S + FETCH_CYCLES + 2A + phi.  A new COPY of
//     W words to ND destinations with known Actual copies takes A = 3 + W +
//     ND*(W+3) accesses (TIME, STATUS: ND*(W+3)), plus 1 per destination whose
//     Actual copy is unknown (cold start, or after a failed Actual store).  It
//     takes 1 access if nothing is new and nothing is needed.  taken_at is
//     time_o in the ack clock of the final source Actual load; a TIME value
//     and the taken_at of TIME and STATUS are S.
//   * Deadline D = cycle start + E1 + E2.  An access goes on the bus in clock
//     p only if p <= D - TIMEOUT - 2, so a timed-out access and the wrap-up
//     clock both end before D.  A fault-free slot needs
//     E2 >= FETCH_CYCLES + 2A + TIMEOUT + phi.  SCAN rejects E2 <= FETCH_CYCLES.
//   * A failed access (err, or no ack in TIMEOUT clocks of cyc) adds 1 to
//     retries, drops cyc/stb for one clock, and is tried again while the
//     deadline allows.  Exception: a destination whose accesses fail twice in
//     one slot is dropped for the rest of that slot, so a dead board never
//     blocks the others.  Source accesses are retried until the deadline.
//     A failed ReadLocked store forgets the ReadLocked copy.  A failed Actual
//     store forgets the Actual copy and remembers the buffer it tried; the
//     read-back before the next Export then shows whether the store landed.
//     If it did, the value counts as delivered and is not published again.
//   * A destination that still needs the current value when its slot ends
//     counts as abandoned, and a later slot of the channel delivers it.
//   * Cycle end: after the last entry the controller waits until rel == H1.
//     In sync mode with a valid SYNC entry 0, it first fetches entry 0 again;
//     the first poll (a load of that source's Actual) is on the bus
//     FETCH_CYCLES+1 clocks after the last wrap-up clock, and the next ones
//     follow every POLL clocks, measured start to start.  The next cycle starts in the clock after a poll's ack
//     that shows a valid Actual other than the ReadLocked copy, or at rel ==
//     H1, whichever comes first.  A poll still on the bus then is abandoned
//     (it is a load).
//   * Memories: block RAM, synchronous read, read only in clocks without a
//     write.  They hold the ROM, the ring of valid entries, the per-channel
//     state (ReadLocked copy, Actual copies, need bits, buffer tried, taken_at)
//     and the per-channel counters.  Counters are updated in place, one lane
//     per clock and a lane at most every other clock; a second copy of them is
//     ordered as the STATUS words.  No multiplier: a buffer offset is 0, S or
//     2S (shift and add).
//   * Reset (synchronous, active high) clears control state only.
`default_nettype none

module albatross_controller #(
    parameter NB         = 4,     // boards on the system bus, 1..16
    parameter ADDR_WIDTH = 10,    // word-address bits of a board RAM, 3..12
    parameter N_CHAN     = 32,    // channel ids with state and counters, 1..32
    parameter ROM_WORDS  = 1024,  // schedule ROM depth in 32-bit words, at least 12
    parameter ROM_FILE   = "",    // $readmemh image of the ROM; "" leaves it zero (invalid header); simulation: +rom=FILE overrides
    parameter TIMEOUT    = 8,     // clocks of cyc without ack/err before an access fails, 3..60
    parameter POLL       = 16     // sync mode: clocks from the start of one poll to the next, >= 1
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
    output wire                  error_o,        // the ROM header is invalid
    output wire [15:0]           rom_errors_o    // entries skipped (saturating)
);

    // The contract (ROM fields and constants, channel layout): generated from
    // rtl/albatross_contract.toml (make contract); ALB_* below come from it.
`include "albatross_contract.vh"

    function integer clog2;
        input integer v;
        integer r;
        begin
            r = 0;
            while ((1 << r) < v) r = r + 1;
            clog2 = r;
        end
    endfunction

    // Comparisons with a constant are look-ups in a constant mask: Yosys maps a
    // comparison to a carry chain, a look-up to a few LUTs.
    function [255:0] ge_mask;             // bit i set when i >= lo
        input integer lo;
        integer i;
        begin
            for (i = 0; i < 256; i = i + 1) ge_mask[i] = (i >= lo);
        end
    endfunction

    localparam AW           = ADDR_WIDTH;
    localparam BOARD_BITS   = 4;                    // m_adr_o = {board[3:0], word}
    localparam FETCH_CYCLES = 10;                   // slot start to the first access on the bus
    localparam K            = TIMEOUT + 3;          // deadline margin: dl = E1 + E2 - K
    localparam NE_FIT       = (ROM_WORDS - 4) / 8;  // entries the ROM can hold
    localparam NE_MAX       = (NE_FIT > 255) ? 255 : NE_FIT;
    localparam CYC          = NE_MAX;               // index of the cycle node in the entry ring
    localparam LB           = clog2(NE_MAX + 1);    // entry index bits
    localparam ROM_AW       = clog2(ROM_WORDS);
    localparam CH_BITS      = (N_CHAN > 1) ? clog2(N_CHAN) : 1;
    localparam CB_BITS      = CH_BITS + 1;          // STATUS copy of the counters: 2 words a channel
    localparam HDR_LAST     = K + 1;                // last clock of HDR
    localparam SCAN_LAST    = (K + 2 > 9) ? K + 2 : 9;   // last clock of one entry's SCAN
    localparam FC_BITS      = clog2(SCAN_LAST + 1);
    localparam TMO_BITS     = clog2(TIMEOUT);
    localparam PC_BITS      = (POLL > 1) ? clog2(POLL) : 1;
    localparam integer        TMO_LAST_I = TIMEOUT - 1;
    localparam integer        PC_LAST_I  = POLL - 1;
    localparam integer        II_LAST_I  = 2 * N_CHAN - 1;
    localparam [TMO_BITS-1:0] TMO_LAST  = TMO_LAST_I[TMO_BITS-1:0];  // last clock of an access
    localparam [PC_BITS-1:0]  PC_LAST   = PC_LAST_I[PC_BITS-1:0];    // last clock of a poll interval
    localparam [CB_BITS-1:0]  II_LAST   = II_LAST_I[CB_BITS-1:0];    // last clock of INIT
    localparam [LB-1:0]       CYC_IDX   = CYC[LB-1:0];
    localparam [33:0]         PRE       = 34'd1 - K;                  // HDR accumulator start
    localparam [33:0]         PRE_S     = 34'd0 - K;                  // SCAN accumulator start
    localparam [31:0]         CK_INIT   = ALB_ROM_CHECKSUM_SEED;
    localparam                CK_ROT    = ALB_ROM_CHECKSUM_ROTATE;
    localparam [11:0]         W_STATUS  = 2 * N_CHAN + 1;
    localparam [255:0]        M_FC_HOLD = ge_mask(K + 2);                  // fc >= K + 2
    localparam [255:0]        M_FC_WORD = ge_mask(1) & ~ge_mask(9);        // 1 <= fc <= 8
    localparam [255:0]        M_FC_H3   = ge_mask(1) & ~ge_mask(4);        // 1 <= fc <= 3
    localparam [255:0]        M_FC_E7   = ge_mask(1) & ~ge_mask(8);        // 1 <= fc <= 7
    localparam [255:0]        M_ND_BAD  = ~ge_mask(1) | ge_mask(5);        // ND not in 1..4
    localparam [255:0]        M_CH_BAD  = ge_mask(N_CHAN);                 // channel id >= N_CHAN
    localparam [255:0]        M_NE_BAD  = ~ge_mask(1) | ge_mask(NE_MAX + 1); // NE not in 1..NE_MAX
    localparam [255:0]        M_LE_FC   = ~ge_mask(FETCH_CYCLES + 1);      // <= FETCH_CYCLES
    // ROM fields (ALB_ROM_*): the source place of E3 and the low destination
    // places of E4 and E5 share one set of field checks (LO), the high places
    // another (HI); the contract check below makes sure they line up.
    localparam                LO_BRD    = ALB_ROM_E4_DST0_BOARD_LSB;
    localparam                LO_BASE   = ALB_ROM_E4_DST0_BASE_LSB;
    localparam                HI_BRD    = ALB_ROM_E4_DST1_BOARD_LSB;
    localparam                HI_BASE   = ALB_ROM_E4_DST1_BASE_LSB;
    localparam                BRD_W     = ALB_ROM_PLACE_BOARD_W;
    localparam                FLAG_SYNC = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_SYNC;     // bit of E0
    localparam                HFLAG_SYNC = ALB_ROM_H0_FLAGS_LSB + ALB_ROM_HFLAG_SYNC_MODE; // bit of H0
    // Channel layout (ALB_CH_*): control bytes in word 0, their byte lanes;
    // Buffer1 at word BUF_WORD; a destination buffer holds W + TAKEN words.
    localparam integer        BUF_WORD_I = ALB_CH_OFF_BUFFERS / ALB_CH_WORD_BYTES;
    localparam integer        TAKEN_I    = ALB_CH_TAKEN_AT_WORDS;
    localparam [AW-1:0]       BUF_WORD   = BUF_WORD_I[AW-1:0];
    localparam [AW-1:0]       TAKEN_W    = TAKEN_I[AW-1:0];
    localparam                ACT_BIT    = 8 * ALB_CH_OFF_ACTUAL;       // Actual: m_dat_i[ACT_BIT +: 8]
    localparam                RL_BIT     = 8 * ALB_CH_OFF_READLOCKED;   // ReadLocked
    localparam [3:0]          SEL_ACT    = 4'b0001 << ALB_CH_OFF_ACTUAL;
    localparam [3:0]          SEL_RL     = 4'b0001 << ALB_CH_OFF_READLOCKED;

    // States.
    localparam [4:0] S_INIT   = 5'd0,   // clear the per-channel memories
                     S_HDR    = 5'd1,   // fetch and check the header
                     S_SCAN   = 5'd2,   // check entry cur_q
                     S_RING   = 5'd3,   // close the ring of valid entries, start cycle 0
                     S_ERR    = 5'd4,   // invalid header: idle for ever
                     S_CYCW   = 5'd5,   // wait for the end of the cycle
                     S_WAIT   = 5'd6,   // wait for the slot start of entry ent_q
                     S_FETCH  = 5'd7,   // fetch entry cur_q (pmode_q: for polling)
                     S_SA_LD  = 5'd8,   // load source Actual
                     S_SRL_ST = 5'd9,   // store source ReadLocked
                     S_DA_LD  = 5'd10,  // load destination Actual (read back)
                     S_DRL_LD = 5'd11,  // load destination ReadLocked
                     S_SW_LD  = 5'd12,  // load source value word wi_q
                     S_DW_ST  = 5'd13,  // store destination word wi_q (wi_q == W: taken_at)
                     S_DA_ST  = 5'd14,  // store destination Actual
                     S_WRAP   = 5'd15,  // write back the channel state, count abandoned
                     S_POLLW  = 5'd16,  // sync mode: wait for the next poll
                     S_POLL   = 5'd17;  // sync mode: load the SYNC source's Actual

    localparam [1:0] K_IDLE = ALB_KIND_IDLE[1:0], K_COPY = ALB_KIND_COPY[1:0],
                     K_TIME = ALB_KIND_TIME[1:0], K_STATUS = ALB_KIND_STATUS[1:0];
    // counter lanes: [16*lane +: 16] of a channel's counter word
    localparam [1:0] L_CORRUPT = 2'd0, L_ABANDON = 2'd1, L_RETRY = 2'd2, L_XFER = 2'd3;

    // Control codes from the FSM to the data path.
    localparam [1:0] FC_INC = 2'd0, FC_0 = 2'd1, FC_1 = 2'd2;
    localparam [2:0] R_INC = 3'd0, R_HOLD = 3'd1, R_ZERO = 3'd2, R_PRE = 3'd3, R_PRE_S = 3'd4;
    localparam [1:0] E_HOLD = 2'd0, E_NEXT = 2'd1, E_CYC = 2'd2;
    localparam [1:0] C_HOLD = 2'd0, C_ENT = 2'd1, C_ZERO = 2'd2, C_INC = 2'd3;
    localparam [1:0] RL_HOLD = 2'd0, RL_APEND = 2'd1, RL_ZERO = 2'd2;
    localparam [1:0] N_HOLD = 2'd0, N_ALL = 2'd1, N_CLR = 2'd2;
    localparam [1:0] A_HOLD = 2'd0, A_BYTE = 2'd1, A_ZERO = 2'd2, A_WBUF = 2'd3;
    localparam [1:0] TR_HOLD = 2'd0, TR_ALL0 = 2'd1, TR_CLR = 2'd2, TR_SET = 2'd3;
    localparam [2:0] D_HOLD = 3'd0, D_ZERO = 3'd1, D_FIRST = 3'd2, D_NEXT = 3'd3,
                     D_FIRST_IMP = 3'd4, D_FIRST_CLR = 3'd5;
    localparam [1:0] W_HOLD = 2'd0, W_ZERO = 2'd1, W_INC = 2'd2;
    localparam [1:0] P_INC = 2'd0, P_ZERO = 2'd1, P_LAST = 2'd2, P_SAT = 2'd3;
    localparam [2:0] DS_NONE = 3'd0, DS_IN = 3'd1, DS_TAKEN = 3'd2, DS_ST0 = 3'd3,
                     DS_CTRB = 3'd4, DS_CTRL_A = 3'd5, DS_CTRL_W = 3'd6;
    localparam [1:0] RE_NONE = 2'd0, RE_SKIP = 2'd1, RE_ONE = 2'd2;

    // Parameter checks: stop elaboration on an unsupported value.
    generate
        if (NB < 1 || NB > (1 << BRD_W) || AW < 3 || AW > ALB_ROM_PLACE_BASE_W || N_CHAN < 1 || N_CHAN > 32 ||
            ROM_WORDS < ALB_ROM_HEADER_WORDS + ALB_ROM_ENTRY_WORDS || TIMEOUT < 3 || TIMEOUT > 60 ||
            POLL < 1) begin : g_param_check
            albatross_controller_parameter_out_of_range u_error ();
        end
    endgenerate

    // Contract check: the decoder relies on these properties of
    // rtl/albatross_contract.toml; a definition without them stops elaboration.
    //   ewa(), the HDR/SCAN/FETCH clocks: 4 header words, 8 words an entry;
    //   one set of place checks for E3..E5; kind codes in kind_q's 2 bits;
    //   vidx(), pick(): buffer indices 1..3 in 2 bits; the extent check
    //   (base + 1 + 3*stride) and the word sequence: Buffer1 at word 1, one
    //   taken_at word, 3 buffers, both control bytes in word 0.
    generate
        if (ALB_ROM_HEADER_WORDS != 4 || ALB_ROM_ENTRY_WORDS != 8 ||
            ALB_ROM_E3_SRC_BOARD_LSB != LO_BRD || ALB_ROM_E3_SRC_BASE_LSB != LO_BASE ||
            ALB_ROM_E5_DST2_BOARD_LSB != LO_BRD || ALB_ROM_E5_DST2_BASE_LSB != LO_BASE ||
            ALB_ROM_E5_DST3_BOARD_LSB != HI_BRD || ALB_ROM_E5_DST3_BASE_LSB != HI_BASE ||
            ALB_KIND_IDLE > 3 || ALB_KIND_COPY > 3 || ALB_KIND_TIME > 3 || ALB_KIND_STATUS > 3 ||
            ALB_CH_BUFFER1 != 1 || ALB_CH_BUFFER_LAST != 3 || ALB_CH_BUFFERS != 3 ||
            BUF_WORD_I != 1 || TAKEN_I != 1 || ALB_CH_OFF_ACTUAL > 3 || ALB_CH_OFF_READLOCKED > 3) begin : g_contract_check
            albatross_controller_contract_mismatch u_error ();
        end
    endgenerate

    // ------------------------------------------------------------ registers
    // control (reset)
    reg [4:0]          state_q;
    reg [FC_BITS-1:0]  fc_q;              // clock within HDR, SCAN, RING, FETCH
    reg [31:0]         time_q;
    reg [CB_BITS-1:0]  ii_q;              // INIT index
    reg                err_q;
    reg                sync_ok_q;         // entry 0 is a valid SYNC COPY
    reg                cyc_q;             // bus cycle (cyc = stb)
    reg [15:0]         rerr_q;            // rom_errors
    reg [15:0]         cycles_q;          // cycles begun
    // schedule
    reg [33:0]         rel_q;             // signed: clocks since the cycle start; SCAN accumulator
    reg [33:0]         dl_q;              // signed: an access may be decided while rel <= dl
    reg                c2_q;              // rel_q <= dl_q (from RING on; set a clock ahead)
    reg                c1w_q;             // rel_q >= rom_q if rel and rom_q did not jump (a clock ahead)
    reg                rel0_q;            // rel_q was zeroed (a cycle start)
    reg                rel_acc_q;         // HDR fc 2, SCAN fc 2..3: rel_sum adds rom_q
    reg                rel_two_q;         // SCAN fc 4: rel_sum adds 2
    reg [LB-1:0]       ent_q;             // next entry of the ring (CYC: the cycle node)
    reg [LB-1:0]       cur_q;             // entry being checked or fetched
    reg [LB-1:0]       lv_q;              // SCAN: last valid entry (CYC: none yet)
    reg [7:0]          sk_q;              // SCAN: invalid entries since lv_q
    reg [7:0]          ne_q;              // header: number of entries
    reg                smode_q;           // header: position-synchronised mode
    reg                pmode_q;           // the fetch is for polling
    reg [31:0]         ck_q;              // checksum
    reg                ck_ok_q;
    reg                bad_q;             // HDR/SCAN: a field is invalid
    // entry
    reg [1:0]          kind_q;
    reg                sflag_q;           // SYNC flag
    reg [2:0]          nd_q;              // destinations, 1..4
    reg [11:0]         w_q;               // value words
    reg [CH_BITS-1:0]  chan_q;
    reg [3:0]          sbrd_q;
    reg [AW-1:0]       sbase_q;
    reg [15:0]         dbrd_q;            // destination d: [4d +: 4]
    reg [4*AW-1:0]     dbase_q;           // destination d: [AW*d +: AW]
    // working copy of the channel state
    reg [1:0]          rl_q;              // source ReadLocked copy (0: unknown)
    reg                imp_open_q;        // ReadLocked stored, not yet confirmed by a load of Actual
    reg [3:0]          need_q;            // destination d has not got the current value
    reg [7:0]          act_q;             // destination Actual copies (0: unknown)
    reg [7:0]          tried_q;           // buffer of a failed Actual store (0: none)
    reg [31:0]         taken_q;           // taken_at of the current value; TIME/STATUS: slot time
    reg [7:0]          wbuf_q;            // buffer chosen for each destination
    reg [3:0]          fl1_q;             // destination d had a failed access in this slot
    reg [3:0]          out_q;             // destination d failed twice: dropped for this slot
    reg                newv_q;            // the Import stored ReadLocked: the value is new
    reg [1:0]          apend_q;           // value being stored into ReadLocked
    reg [1:0]          di_q;              // destination of the access
    reg [AW-1:0]       wi_q;              // word of the access
    reg [AW-1:0]       w1_q;              // W + 1: destination buffer stride (a clock after w_q)
    reg [PC_BITS-1:0]  pc_q;              // poll interval
    // bus
    reg                we_q;
    reg [AW+3:0]       adr_q;
    reg [3:0]          sel_q;
    reg [31:0]         dat_q;
    reg [TMO_BITS-1:0] tmo_q;

    // ------------------------------------------------------------ memories
    reg [31:0]   rom [0:ROM_WORDS-1];
    reg [31:0]   rom_q;
    reg [33:0]   dlm_dl [0:NE_MAX];       // entry: dl; cycle node: H1 - 2
    reg [33:0]   dlm_dl_q;
    reg [LB+7:0] dlm_lk [0:NE_MAX];       // valid entry, cycle node: {next valid, invalid skipped}
    reg [LB+7:0] dlm_lk_q;
    reg [53:0]   st_mem [0:N_CHAN-1];     // {tried, act, need, rl, taken}
    reg [53:0]   st_q;
    reg [63:0]   ctra [0:N_CHAN-1];       // {transfers, retries, abandoned, corrupt}
    reg [63:0]   ctra_q;
    reg [31:0]   ctrb [0:2*N_CHAN-1];     // STATUS words 1..2*N_CHAN
    reg [31:0]   ctrb_q;

    // The ROM image: ROM_FILE, or in simulation the plusarg +rom=FILE (the
    // harness picks a schedule at run time); neither: all zero.
    integer ri;
`ifndef SYNTHESIS
    reg [8*1024-1:0] rom_arg;
`endif
    initial begin
        for (ri = 0; ri < ROM_WORDS; ri = ri + 1) rom[ri] = 32'd0;
        if (ROM_FILE != "") $readmemh(ROM_FILE, rom);
`ifndef SYNTHESIS
        if ($value$plusargs("rom=%s", rom_arg)) $readmemh(rom_arg, rom);
`endif
    end

    // ------------------------------------------------------------ helpers
    function [1:0] first4;                // lowest set bit of a non-zero mask
        input [3:0] m;
        first4 = m[0] ? 2'd0 : m[1] ? 2'd1 : (m[2] | ~m[3]) ? 2'd2 : 2'd3;
    endfunction

    function [3:0] above;                 // destinations after d
        input [1:0] d;
        above = {d != 2'd3, d[1] == 1'b0, d == 2'd0, 1'b0};
    endfunction

    function [1:0] pick;                  // last of 1..3 that is neither a nor r
        input [1:0] a;
        input [1:0] r;
        pick = (a != 2'd3 && r != 2'd3) ? 2'd3 : (a != 2'd2 && r != 2'd2) ? 2'd2 : 2'd1;
    endfunction

    function vidx;                        // a control byte names a buffer
        input [7:0] v;
        vidx = v[7:2] == 6'd0 && v[1:0] != 2'd0;
    endfunction

    function [1:0] sel2;                  // 2-bit field d of an 8-bit vector
        input [7:0] v;
        input [1:0] d;
        case (d)
            2'd0:    sel2 = v[1:0];
            2'd1:    sel2 = v[3:2];
            2'd2:    sel2 = v[5:4];
            default: sel2 = v[7:6];
        endcase
    endfunction

    function [7:0] put2;                  // v with 2-bit field d replaced by x
        input [7:0] v;
        input [1:0] d;
        input [1:0] x;
        begin
            put2 = v;
            case (d)
                2'd0:    put2[1:0] = x;
                2'd1:    put2[3:2] = x;
                2'd2:    put2[5:4] = x;
                default: put2[7:6] = x;
            endcase
        end
    endfunction

    // ------------------------------------------------------------ status of the data path
    wire [3:0]  active   = (nd_q == 3'd1) ? 4'b0001 : (nd_q == 3'd2) ? 4'b0011 :
                           (nd_q == 3'd3) ? 4'b0111 : 4'b1111;
    wire [3:0]  dsel     = 4'b0001 << di_q;
    wire [3:0]  ab_m     = need_q & active;                   // not published yet (abandoned at the end)
    wire [3:0]  nm_q     = ab_m & ~out_q;                     // destinations served in this slot
    wire [3:0]  nm_next  = nm_q & above(di_q);                // ... after di_q
    wire [3:0]  nm_clr   = nm_q & ~dsel;                      // ... but di_q
    wire [3:0]  nm_imp   = (newv_q ? 4'hF : need_q) & active & ~out_q; // ... once the Import is done
    wire [1:0]  act_cur  = sel2(act_q, di_q);
    wire        out_cur  = |(out_q & dsel);                   // di_q was dropped
    wire [1:0]  act_nxt  = sel2(act_q, first4(nm_next));      // Actual copy of the next one
    wire [1:0]  act_imp  = sel2(act_q, first4(nm_imp));
    // The FSM sees only registered compare results, computed a clock ahead
    // (see "schedule compares" below).
    wire        c1       = c1w_q | (rel0_q && rom_q == 32'd0);  // WAIT: slot start reached (rel >= E1)
    wire        c2       = c2_q;                                // before the deadline (rel <= dl)
    wire        c1_scan;                                        // SCAN_LAST: rel >= H1
    wire [LB-1:0] lk_next = dlm_lk_q[LB+7:8];
    wire [7:0]  lk_skip  = dlm_lk_q[7:0];
    wire [7:0]  a_byte   = m_dat_i[ACT_BIT +: 8];            // Actual
    wire [7:0]  r_byte   = m_dat_i[RL_BIT +: 8];             // ReadLocked
    wire        acc_ack  = cyc_q & m_ack_i;
    wire        acc_fail = cyc_q & ~m_ack_i & (m_err_i | (tmo_q == TMO_LAST));
    wire        wi_is_w  = {{(16-AW){1'b0}}, wi_q} == {4'd0, w_q};
    wire [AW:0] wi_inc   = {1'b0, wi_q} + {{AW{1'b0}}, 1'b1};  // also the next word (W_INC)
    wire        wi1_is_w = {{(15-AW){1'b0}}, wi_inc} == {4'd0, w_q};
    wire        cur_last = {{(16-LB){1'b0}}, cur_q} + 16'd1 == {8'd0, ne_q};
    wire [7:0]  fc_q8    = {{(8-FC_BITS){1'b0}}, fc_q};
    wire        scan_ok  = !bad_q && ck_ok_q && !c1_scan;    // c1_scan: E1 + E2 - 1 >= H1

    // ------------------------------------------------------------ FSM (control only)
    reg [4:0] state_d;
    reg [1:0] fc_op;
    reg [2:0] rel_op;
    reg       dl_ld;
    reg [1:0] ent_op, cur_op;
    reg       lv_cur, lv_cyc;
    reg [1:0] sk_op;
    reg       sync_set, pmode_set, pmode_clr, err_set;
    reg       taken_time;
    reg [1:0] rl_op, need_op, act_op, tried_op;
    reg       wbuf_we, newv_set, newv_clr, apend_ld;
    reg [2:0] di_op;
    reg [1:0] wi_op, pc_op;
    reg       go_new, go_retry;
    reg [4:0] acc_st;     // go_new: the state of the access (state_d)
    reg [2:0] dat_sel;
    reg       ev_we;
    reg [1:0] ev_lane_f;  // the lane event_inc names (ev_lane decodes it directly)
    reg       cyc_inc;
    reg [1:0] rerr_op;
    reg       st_we;
    reg       dfail;      // an access to destination di_q failed

    always @* begin
        state_d    = state_q;
        fc_op      = FC_INC;
        rel_op     = R_INC;
        dl_ld      = 1'b0;
        ent_op     = E_HOLD;
        cur_op     = C_HOLD;
        lv_cur     = 1'b0;
        lv_cyc     = 1'b0;
        sk_op      = 2'd0;
        sync_set   = 1'b0;
        pmode_set  = 1'b0;
        pmode_clr  = 1'b0;
        err_set    = 1'b0;
        taken_time = 1'b0;
        rl_op      = RL_HOLD;
        need_op    = N_HOLD;
        act_op     = A_HOLD;
        tried_op   = TR_HOLD;
        wbuf_we    = 1'b0;
        newv_set   = 1'b0;
        newv_clr   = 1'b0;
        apend_ld   = 1'b0;
        di_op      = D_HOLD;
        wi_op      = W_HOLD;
        pc_op      = P_INC;
        go_new     = 1'b0;
        go_retry   = 1'b0;
        acc_st     = S_POLL;
        dat_sel    = DS_NONE;
        ev_we      = 1'b0;
        ev_lane_f  = L_RETRY;
        cyc_inc    = 1'b0;
        rerr_op    = RE_NONE;
        st_we      = 1'b0;
        dfail      = 1'b0;

        case (state_q)
            S_INIT: begin
                if (ii_q == II_LAST) begin
                    state_d = S_HDR;
                    fc_op   = FC_0;
                end
            end

            // rom_q: H0..H3 at fc 1..4.  rel: 1-K (fc 2), H1+1-K (fc 3: rel_sum adds
            // H1 at fc 2), +1 to H1-2 (fc K, the cycle node's dl) and H1-1 (fc K+1).
            S_HDR: begin
                if (fc_q == 1)      rel_op = R_PRE;
                if (fc_q == HDR_LAST) begin
                    if (!bad_q && ck_ok_q && !rel_q[33]) begin
                        state_d = S_SCAN;
                        fc_op   = FC_0;
                        cur_op  = C_ZERO;
                        lv_cyc  = 1'b1;
                        sk_op   = 2'd1;
                    end else begin
                        state_d = S_ERR;
                        err_set = 1'b1;
                    end
                end
            end

            // rom_q: E0..E7 at fc 1..8, H1 from fc 9.  rel (rel_sum adds E1 at fc 2,
            // E2 at fc 3, 2 at fc 4): -K (fc 2), E1-K (fc 3: order check against
            // dl_q = the last valid entry's dl), dl = E1+E2-K (fc 4, stored),
            // E1+E2+2-K (fc 5), +1 to E1+E2-1 (fc K+2: c1_scan is the cycle check).
            S_SCAN: begin
                if (fc_q == 1)                        rel_op = R_PRE_S;
                else if (M_FC_HOLD[fc_q8])            rel_op = R_HOLD;
                if (fc_q == SCAN_LAST) begin
                    fc_op = FC_0;
                    if (scan_ok) begin
                        lv_cur = 1'b1;
                        sk_op  = 2'd1;
                        if (cur_q == {LB{1'b0}} && sflag_q) sync_set = 1'b1;
                    end else begin
                        sk_op  = 2'd2;
                    end
                    if (cur_last) state_d = S_RING;
                    else          cur_op  = C_INC;
                end
            end

            // fc 0 writes the ring's last link; fc 2 has the cycle node in dlm_*_q.
            S_RING: begin
                ent_op = E_CYC;
                if (fc_q == 2) begin
                    dl_ld = 1'b1;
                    cycle_start;
                end
            end

            S_ERR: ;

            S_CYCW: if (!c2) cycle_start;

            S_WAIT: begin
                if (c1) begin                   // rel == E1: the slot starts
                    state_d    = S_FETCH;
                    fc_op      = FC_1;
                    pmode_clr  = 1'b1;
                    cur_op     = C_ENT;
                    ent_op     = E_NEXT;
                    rerr_op    = RE_SKIP;
                    dl_ld      = 1'b1;
                    taken_time = 1'b1;          // TIME, STATUS: the slot time
                end
            end

            // rom_q: E0..E7 at fc 1..8; state loaded at fc 2; decision at fc 9.
            S_FETCH: begin
                if (pmode_q && !c2) begin
                    cycle_start;
                end else if (fc_q == FETCH_CYCLES - 1) begin
                    newv_clr = 1'b1;
                    if (pmode_q) begin
                        pc_op   = P_LAST;
                        state_d = ck_ok_q ? S_POLLW : S_CYCW;
                    end else if (!ck_ok_q || kind_q == K_IDLE) begin
                        if (!ck_ok_q) rerr_op = RE_ONE;
                        dl_ld = 1'b1;
                        entry_end;
                    end else if (kind_q == K_COPY) begin
                        access(S_SA_LD);
                    end else begin              // TIME, STATUS: a new value every slot
                        need_op  = N_ALL;
                        tried_op = TR_ALL0;
                        di_op    = D_ZERO;
                        access((act_q[1:0] == 2'd0) ? S_DA_LD : S_DRL_LD);
                    end
                end
            end

            // ---- Import (seed figure 3)
            S_SA_LD: begin
                if (!cyc_q) retry_or_end;
                else if (acc_ack) begin
                    if (!vidx(a_byte)) begin
                        event_inc(L_CORRUPT);
                        end_transfer;
                    end else if (a_byte[1:0] == rl_q) begin   // ReadLocked == Actual: done
                        if (newv_q) begin
                            need_op    = N_ALL;
                            tried_op   = TR_ALL0;
                            taken_time = 1'b1;
                        end
                        if (nm_imp == 4'd0) begin
                            end_transfer;
                        end else begin
                            di_op = D_FIRST_IMP;
                            access((act_imp == 2'd0) ? S_DA_LD : S_DRL_LD);
                        end
                    end else begin                            // ReadLocked := Actual
                        apend_ld = 1'b1;
                        newv_set = 1'b1;
                        dat_sel  = DS_CTRL_A;
                        access(S_SRL_ST);
                    end
                end else if (acc_fail) event_inc(L_RETRY);
            end

            S_SRL_ST: begin
                if (!cyc_q) retry_or_end;
                else if (acc_ack) begin
                    rl_op = RL_APEND;
                    access(S_SA_LD);
                end else if (acc_fail) begin
                    rl_op = RL_ZERO;                          // may or may not have landed
                    event_inc(L_RETRY);
                end
            end

            // ---- Export (seed figure 4), streamed to every destination that needs it
            S_DA_LD: begin
                if (!cyc_q) begin
                    if (out_cur) ctrl_next(1'b0);
                    else         retry_or_end;
                end
                else if (acc_ack) begin
                    tried_op = TR_CLR;
                    if (!vidx(a_byte)) begin
                        event_inc(L_CORRUPT);
                        act_op = A_ZERO;
                        access(S_DRL_LD);
                    end else if (sel2(tried_q, di_q) == a_byte[1:0]) begin
                        act_op  = A_BYTE;               // the failed store had landed
                        need_op = N_CLR;
                        event_inc(L_XFER);
                        ctrl_next(1'b1);
                    end else begin
                        act_op = A_BYTE;
                        access(S_DRL_LD);
                    end
                end else if (acc_fail) dest_failed;
            end

            S_DRL_LD: begin
                if (!cyc_q) begin
                    if (out_cur) ctrl_next(1'b0);
                    else         retry_or_end;
                end else if (acc_ack) begin
                    if (!vidx(r_byte)) event_inc(L_CORRUPT);
                    wbuf_we = 1'b1;
                    ctrl_next(1'b0);
                end else if (acc_fail) dest_failed;
            end

            S_SW_LD: begin
                if (!cyc_q) retry_or_end;
                else if (acc_ack) begin
                    di_op   = D_FIRST;
                    dat_sel = DS_IN;
                    access(S_DW_ST);
                end else if (acc_fail) event_inc(L_RETRY);
            end

            S_DW_ST: begin
                if (!cyc_q) begin
                    if (out_cur) word_next;
                    else         retry_or_end;
                end else if (acc_ack) word_next;
                else if (acc_fail)    dest_failed;
            end

            S_DA_ST: begin
                if (!cyc_q) begin
                    if (out_cur) publish_next;
                    else         retry_or_end;
                end else if (acc_ack) begin
                    act_op   = A_WBUF;
                    tried_op = TR_CLR;
                    need_op  = N_CLR;
                    event_inc(L_XFER);
                    publish_next;
                end else if (acc_fail) begin
                    act_op   = A_ZERO;                  // may or may not have landed
                    tried_op = TR_SET;
                    dest_failed;
                end
            end

            S_WRAP: begin
                st_we = 1'b1;
                if (ab_m != 4'd0) begin
                    event_inc(L_ABANDON);                 // of popcount(ab_m)
                end
                if (ent_q != CYC_IDX) state_d = S_WAIT;
                else if (!c2)         cycle_start;
                else if (sync_ok_q)   poll_fetch;
                else                  state_d = S_CYCW;
            end

            S_POLLW: begin
                if (!c2) cycle_start;
                else if (pc_q == PC_LAST) begin
                    pc_op   = P_ZERO;
                    go_new  = 1'b1;
                    acc_st  = S_POLL;
                    state_d = S_POLL;
                end
            end

            S_POLL: begin
                pc_op = P_SAT;
                if (!c2) cycle_start;                   // abandons a poll still on the bus
                else if (acc_ack) begin
                    if (vidx(a_byte) && a_byte[1:0] != rl_q) cycle_start;
                    else state_d = S_POLLW;
                end else if (acc_fail) begin
                    event_inc(L_RETRY);
                    state_d = S_POLLW;
                end
            end

            default: state_d = S_ERR;
        endcase
    end

    // ---- FSM helpers (called only from the FSM block; they set control codes)

    // Put the access of state s on the bus in the next clock if the deadline allows.
    task access;
        input [4:0] s;
        begin
            acc_st = s;
            if (c2) begin
                go_new  = 1'b1;
                state_d = s;
            end else begin
                end_transfer;
            end
        end
    endtask

    task end_transfer;
        begin
            state_d = S_WRAP;
            dl_ld   = 1'b1;                      // the next entry's dl, or H1 - 2
        end
    endtask

    // One clock after a failed access: the same access again, or the slot is over.
    task retry_or_end;
        begin
            if (c2) go_retry = 1'b1;
            else    end_transfer;
        end
    endtask

    task event_inc;
        input [1:0] lane;
        begin
            ev_we   = 1'b1;
            ev_lane_f = lane;
        end
    endtask

    // After the control loads of destination di_q: the next one, or the words.
    task ctrl_next;
        input landed;                            // di_q no longer needs the value
        begin
            if (nm_next != 4'd0) begin
                di_op = D_NEXT;
                access((act_nxt == 2'd0) ? S_DA_LD : S_DRL_LD);
            end else if ((landed ? nm_clr : nm_q) == 4'd0) begin
                end_transfer;
            end else begin
                wi_op = W_ZERO;
                di_op = landed ? D_FIRST_CLR : D_FIRST;
                if (kind_q == K_COPY) begin
                    access(S_SW_LD);
                end else begin
                    dat_sel = (kind_q == K_TIME) ? DS_TAKEN : DS_ST0;
                    access(S_DW_ST);
                end
            end
        end
    endtask

    // A failed access to destination di_q: retried once in the slot; at its
    // second failure the destination is dropped for the rest of the slot.
    task dest_failed;
        begin
            event_inc(L_RETRY);
            dfail = 1'b1;
        end
    endtask

    // After a word store to di_q (or di_q dropped): the next destination, the
    // next word, the taken_at word, or the Actual stores.
    task word_next;
        begin
            if (nm_next != 4'd0) begin              // same word, next destination
                di_op = D_NEXT;
                access(S_DW_ST);
            end else if (nm_q == 4'd0) begin        // every destination dropped
                end_transfer;
            end else if (!wi_is_w) begin            // next word
                wi_op = W_INC;
                di_op = D_FIRST;
                if (wi1_is_w) begin
                    dat_sel = DS_TAKEN;             // taken_at
                    access(S_DW_ST);
                end else if (kind_q == K_COPY) begin
                    access(S_SW_LD);
                end else begin
                    dat_sel = (kind_q == K_TIME) ? DS_TAKEN : DS_CTRB;
                    access(S_DW_ST);
                end
            end else begin                          // publish
                di_op   = D_FIRST;
                dat_sel = DS_CTRL_W;
                access(S_DA_ST);
            end
        end
    endtask

    // After the Actual store of di_q (or di_q dropped): the next one, or done.
    task publish_next;
        begin
            if (nm_clr != 4'd0) begin
                di_op   = D_FIRST_CLR;
                dat_sel = DS_CTRL_W;
                access(S_DA_ST);
            end else begin
                end_transfer;
            end
        end
    endtask

    task entry_end;
        begin
            if (ent_q != CYC_IDX) state_d = S_WAIT;
            else if (sync_ok_q)   poll_fetch;
            else                  state_d = S_CYCW;
        end
    endtask

    task poll_fetch;
        begin
            state_d   = S_FETCH;
            pmode_set = 1'b1;
            fc_op     = FC_1;
            cur_op    = C_ZERO;
        end
    endtask

    // The next cycle starts in the next clock (rel 0); dlm_lk_q holds the cycle node.
    task cycle_start;
        begin
            rel_op    = R_ZERO;
            cyc_inc   = 1'b1;
            rerr_op   = RE_SKIP;
            ent_op    = E_NEXT;
            pmode_clr = 1'b1;
            state_d   = (lk_next == CYC_IDX) ? S_CYCW : S_WAIT;
        end
    endtask

    // ------------------------------------------------------------ next values used by addresses
    reg [1:0] di_d;
    always @* begin
        case (di_op)
            D_ZERO:      di_d = 2'd0;
            D_FIRST:     di_d = first4(nm_q);
            D_NEXT:      di_d = first4(nm_next);
            D_FIRST_IMP: di_d = first4(nm_imp);
            D_FIRST_CLR: di_d = first4(nm_clr);
            default:     di_d = di_q;
        endcase
    end

    wire [AW-1:0] wi_d   = (wi_op == W_ZERO) ? {AW{1'b0}} :
                           (wi_op == W_INC)  ? wi_inc[AW-1:0] : wi_q;
    wire [1:0]    pick_v = pick(act_cur, vidx(r_byte) ? r_byte[1:0] : 2'd0);
    wire [7:0]    wbuf_d = wbuf_we ? put2(wbuf_q, di_q, pick_v) : wbuf_q;
    wire [LB-1:0] ent_d  = (ent_op == E_NEXT) ? lk_next : (ent_op == E_CYC) ? CYC_IDX : ent_q;
    wire [LB-1:0] cur_d  = (cur_op == C_ENT)  ? ent_q :
                           (cur_op == C_ZERO) ? {LB{1'b0}} :
                           (cur_op == C_INC)  ? cur_q + {{(LB-1){1'b0}}, 1'b1} : cur_q;
    wire [LB-1:0] lv_d   = lv_cyc ? CYC_IDX : lv_cur ? cur_q : lv_q;
    wire          ld_e0  = (state_q == S_SCAN || state_q == S_FETCH) && fc_q == 1;
    wire [CH_BITS-1:0] chan_d = (state_q == S_FETCH && fc_q == 1) ? rom_q[ALB_ROM_E0_ID_LSB +: CH_BITS] : chan_q;

    // ------------------------------------------------------------ bus access parameters
    // Word address of a control byte: base; of word i of buffer b: base + 1 + (b-1)*S + i,
    // with S = W (source) or W + 1 (destination, value and taken_at).
    reg [AW-1:0] d_base;
    reg [3:0]    d_brd;
    always @* begin
        case (di_d)
            2'd0:    begin d_base = dbase_q[AW-1:0];        d_brd = dbrd_q[3:0];   end
            2'd1:    begin d_base = dbase_q[2*AW-1:AW];     d_brd = dbrd_q[7:4];   end
            2'd2:    begin d_base = dbase_q[3*AW-1:2*AW];   d_brd = dbrd_q[11:8];  end
            default: begin d_base = dbase_q[4*AW-1:3*AW];   d_brd = dbrd_q[15:12]; end
        endcase
    end

    // a_src, a_data from acc_st (== state_d whenever go_new), not from the
    // cycle-start logic, so the address arithmetic starts earlier.
    wire          a_src  = acc_st == S_SA_LD || acc_st == S_SRL_ST ||
                           acc_st == S_SW_LD || acc_st == S_POLL;
    wire          a_data = acc_st == S_SW_LD || acc_st == S_DW_ST;
    wire [AW-1:0] a_base = a_src ? sbase_q : d_base;
    wire [BOARD_BITS-1:0] a_brd = a_src ? sbrd_q : d_brd;
    wire [1:0]    a_buf  = a_src ? rl_q : sel2(wbuf_d, di_d);
    wire [AW-1:0] a_str  = a_src ? w_q[AW-1:0] : w1_q;
    wire [AW-1:0] a_off  = (a_buf == 2'd2) ? a_str :
                           (a_buf == 2'd3) ? {a_str[AW-2:0], 1'b0} : {AW{1'b0}};
    wire [AW-1:0] a_word = a_base + (a_data ? a_off + wi_d + BUF_WORD : {AW{1'b0}});
    wire          a_we   = state_d == S_SRL_ST || state_d == S_DW_ST || state_d == S_DA_ST;
    wire [3:0]    a_sel  = (state_d == S_SRL_ST) ? SEL_RL :
                           (state_d == S_DA_ST)  ? SEL_ACT : 4'b1111;

    reg [31:0] dat_n;
    always @* begin
        case (dat_sel)
            DS_IN:     dat_n = m_dat_i;
            DS_TAKEN:  dat_n = taken_q;
            DS_ST0:    dat_n = {rerr_q, cycles_q};
            DS_CTRB:   dat_n = ctrb_q;
            DS_CTRL_A: dat_n = {4{6'd0, a_byte[1:0]}};
            default:   dat_n = {4{6'd0, sel2(wbuf_d, di_d)}};
        endcase
    end

    // ------------------------------------------------------------ ROM and memory addresses
    // Word j of entry e is at 4 + 8e + j.  Memories are read with next-state
    // values, so rom_q (and dlm_*_q, st_q, ctra_q) in a state hold its words.
    function [ROM_AW-1:0] ewa;            // 4 + 8e + j = {e + j[2], ~j[2], j[1:0]}
        input [LB-1:0] e;
        input [2:0]    j;
        ewa = {{(ROM_AW-LB-3){1'b0}}, e + {{(LB-1){1'b0}}, j[2]}, ~j[2], j[1:0]};
    endfunction

    wire [FC_BITS-1:0] fc_d = (fc_op == FC_0) ? {FC_BITS{1'b0}} :
                              (fc_op == FC_1) ? {{(FC_BITS-1){1'b0}}, 1'b1} :
                              fc_q + {{(FC_BITS-1){1'b0}}, 1'b1};
    wire [7:0]    fc_d8   = {{(8-FC_BITS){1'b0}}, fc_d};
    wire          fc_word = M_FC_WORD[fc_d8];            // fetching E(fc_d - 1)
    wire [2:0]    fc_j    = fc_d[2:0] - 3'd1;
    reg [ROM_AW-1:0] rom_ra;
    always @* begin
        rom_ra = {{(ROM_AW-1){1'b0}}, 1'b1};               // H1
        if (state_d == S_HDR)
            rom_ra = {{(ROM_AW-2){1'b0}}, fc_j[1:0]};
        else if ((state_d == S_SCAN || state_d == S_FETCH) && fc_word)
            rom_ra = ewa(cur_d, fc_j);
        else if (state_d != S_SCAN && ent_d != CYC_IDX)
            rom_ra = ewa(ent_d, 3'd1);                     // E1 of the next entry
    end

    always @(posedge clk_i) begin
        rom_q <= rom[rom_ra];
    end

    // Entry ring: dl written at SCAN fc 4 (cycle node: H1 - 2 at HDR fc K); a
    // link when an entry is found valid, and the last one in RING.
    wire          dl_we  = (state_q == S_HDR && fc_q == K) || (state_q == S_SCAN && fc_q == 4);
    wire [LB-1:0] dl_wa  = (state_q == S_HDR) ? CYC_IDX : cur_q;
    wire          lk_we  = (state_q == S_SCAN && fc_q == SCAN_LAST && scan_ok) ||
                           (state_q == S_RING && fc_q == 0);
    wire [LB+7:0] lk_wd  = {(state_q == S_RING) ? CYC_IDX : cur_q, sk_q};
    wire [LB-1:0] dlm_ra = (state_d == S_SCAN) ? lv_d : ent_d;

    always @(posedge clk_i) begin
        if (dl_we) dlm_dl[dl_wa] <= rel_q;
        else       dlm_dl_q      <= dlm_dl[dlm_ra];
    end

    always @(posedge clk_i) begin
        if (lk_we) dlm_lk[lv_q] <= lk_wd;
        else       dlm_lk_q     <= dlm_lk[dlm_ra];
    end

    // Per-channel state: written back in WRAP, cleared in INIT.
    wire               init  = state_q == S_INIT;
    wire [CH_BITS-1:0] ii_ch = ii_q[CB_BITS-1:1];
    // INIT writes the working copy, which it holds at zero.
    always @(posedge clk_i) begin
        // An Import cut off by the deadline between its store of ReadLocked and
        // the load of Actual that confirms it leaves its copy unknown: the
        // next slot must take that buffer as a new value, with a new taken_at.
        if (init || st_we) st_mem[init ? ii_ch : chan_q] <= {tried_q, act_q, need_q,
                                                               imp_open_q ? 2'd0 : rl_q, taken_q};
        else               st_q <= st_mem[chan_d];
    end

    // Counters: lane ev_lane of channel chan_q := saturate(old + 1, or + abandoned).
    // The lane and the amount are decoded straight from state_q and the bus
    // (short paths to the counter write data); they are the lane event_inc
    // names whenever ev_we (checked in simulation): abandoned in WRAP, a retry
    // after a failed access (no ack), a transfer on an ack of a DA_ST or of a
    // DA_LD with a valid Actual, else corrupt.
    wire [1:0] ev_lane = (state_q == S_WRAP) ? L_ABANDON :
                         !m_ack_i ? L_RETRY :
                         (state_q == S_DA_ST || (state_q == S_DA_LD && vidx(a_byte))) ? L_XFER : L_CORRUPT;
    wire       ev_pop  = state_q == S_WRAP;
`ifndef SYNTHESIS
    always @(posedge clk_i) begin
        if (!rst_i && ev_we && ev_lane != ev_lane_f) begin
            $display("albatross_controller: counter lane %0d decoded, %0d named (state %0d)",
                     ev_lane, ev_lane_f, state_q);
            $stop;
        end
    end
`endif
    reg [15:0] ev_old;
    always @* begin
        case (ev_lane)
            L_CORRUPT: ev_old = ctra_q[15:0];
            L_ABANDON: ev_old = ctra_q[31:16];
            L_RETRY:   ev_old = ctra_q[47:32];
            default:   ev_old = ctra_q[63:48];
        endcase
    end
    wire [2:0]  ev_amt = ev_pop ? {2'd0, ab_m[0]} + {2'd0, ab_m[1]} + {2'd0, ab_m[2]} + {2'd0, ab_m[3]}
                                : 3'd1;
    wire [16:0] ev_sum = {1'b0, ev_old} + {14'd0, ev_amt};
    wire [15:0] ev_new = ev_sum[16] ? 16'hFFFF : ev_sum[15:0];

    wire [3:0]         ca_we = init ? 4'hF : ({3'd0, ev_we} << ev_lane);
    wire [CH_BITS-1:0] ca_wa = init ? ii_ch : chan_q;
    wire [15:0]        ca_wd = init ? 16'd0 : ev_new;
    always @(posedge clk_i) begin
        if (ca_we[0]) ctra[ca_wa][15:0]  <= ca_wd;
        if (ca_we[1]) ctra[ca_wa][31:16] <= ca_wd;
        if (ca_we[2]) ctra[ca_wa][47:32] <= ca_wd;
        if (ca_we[3]) ctra[ca_wa][63:48] <= ca_wd;
        if (ca_we == 4'd0) ctra_q <= ctra[chan_d];
    end

    // STATUS copy: word 2c = {transfers, retries}, word 2c+1 = {abandoned, corrupt}.
    wire [1:0]         cb_we = init ? 2'b11 : ({1'b0, ev_we} << ev_lane[0]);
    wire [CB_BITS-1:0] cb_wa = init ? ii_q : {chan_q, ~ev_lane[1]};
    wire [CB_BITS-1:0] cb_ra;                               // word wi_q: STATUS word wi_q + 1
    generate
        if (AW >= CB_BITS) begin : g_cb_ra_narrow
            assign cb_ra = wi_q[CB_BITS-1:0];
        end else begin : g_cb_ra_wide
            assign cb_ra = {{(CB_BITS-AW){1'b0}}, wi_q};
        end
    endgenerate
    always @(posedge clk_i) begin
        if (cb_we[0]) ctrb[cb_wa][15:0]  <= ca_wd;
        if (cb_we[1]) ctrb[cb_wa][31:16] <= ca_wd;
        if (cb_we == 2'd0) ctrb_q <= ctrb[cb_ra];
    end

    // ------------------------------------------------------------ control registers
    wire [7:0]  rerr_add = (rerr_op == RE_SKIP) ? lk_skip : (rerr_op == RE_ONE) ? 8'd1 : 8'd0;
    wire [16:0] rerr_sum = {1'b0, rerr_q} + {9'd0, rerr_add};

    always @(posedge clk_i) begin
        if (rst_i) begin
            state_q   <= S_INIT;
            fc_q      <= {FC_BITS{1'b0}};
            time_q    <= 32'd0;
            ii_q      <= {CB_BITS{1'b0}};
            err_q     <= 1'b0;
            sync_ok_q <= 1'b0;
            cyc_q     <= 1'b0;
            rerr_q    <= 16'd0;
            cycles_q  <= 16'd0;
        end else begin
            state_q <= state_d;
            fc_q    <= fc_d;
            time_q  <= time_q + 32'd1;
            if (init)     ii_q      <= ii_q + {{(CB_BITS-1){1'b0}}, 1'b1};
            if (err_set)  err_q     <= 1'b1;
            if (sync_set) sync_ok_q <= 1'b1;
            if (go_new || go_retry)                          cyc_q <= 1'b1;
            else if (acc_ack || acc_fail || state_d != state_q) cyc_q <= 1'b0;
            if (rerr_op != RE_NONE) rerr_q <= rerr_sum[16] ? 16'hFFFF : rerr_sum[15:0];
            if (cyc_inc && cycles_q != 16'hFFFF) cycles_q <= cycles_q + 16'd1;
        end
    end

    // ------------------------------------------------------------ data path (no reset)
    // rel_sum: the next rel unless zeroed, preset or held.  Its addend comes
    // from registers only: H1 at HDR fc 2, E1 and E2 at SCAN fc 2 and 3, 2 at
    // SCAN fc 4, else 1 (rel_acc_q, rel_two_q: decoded a clock ahead).
    wire [33:0] rel_sum  = rel_q + (rel_acc_q ? {2'b00, rom_q} : {32'd0, rel_two_q, ~rel_two_q});
    wire        ck_first = fc_q == 1;
    wire        ck_acc   = (state_q == S_HDR && M_FC_H3[fc_q8]) ||
                           ((state_q == S_SCAN || state_q == S_FETCH) && M_FC_E7[fc_q8]);
    wire        ck_chk   = (state_q == S_HDR && fc_q == 4) ||
                           ((state_q == S_SCAN || state_q == S_FETCH) && fc_q == 8);
    wire [31:0] ck_base  = ck_first ? CK_INIT : ck_q;
    wire        st_ld    = state_q == S_FETCH && fc_q == 2;
    wire        dl_load  = dl_ld || (state_q == S_SCAN && fc_q == 1) || (st_ld && kind_q == K_IDLE);

    // Schedule compares, a clock ahead.  c2_q: rel <= dl next clock, that is
    // 0 <= dl (rel zeroed) or rel_q < dl (rel + 1), dl being dl_q or the
    // dlm_dl_q it loads; valid from the RING cycle start on (only cycle
    // starts and +1 follow).  c1w_q: rel_sum >= rom_q, which is rel >= rom_q
    // next clock if rel goes up by 1 and rom_q holds: in WAIT, rom_q holds E1
    // of ent_q from the clock before (WRAP, FETCH fc 9, WAIT), except after a
    // cycle start (rel0_q: rel = 0, and c1 is E1 == 0).
    wire        c2_lt    = $signed(rel_q) < $signed(dl_q);           // also SCAN fc 3: E1 < last E1 + E2
    wire        c2_lt_m  = $signed(rel_q) < $signed(dlm_dl_q);
    wire        c2_d     = (rel_op == R_ZERO) ? ~(dl_load ? dlm_dl_q[33] : dl_q[33]) :
                           (rel_op == R_HOLD) ? c2_q : (dl_load ? c2_lt_m : c2_lt);
    wire        c1w_d    = rel_op != R_ZERO && $signed(rel_sum) >= $signed({2'b00, rom_q});
    // SCAN cycle check at SCAN_LAST (rom_q = H1 from fc 9; rel held from fc K+2).
    generate
        if (K >= 8) begin : g_c1_scan_ahead        // SCAN_LAST = K+2, fc K+1 >= 9 has +1 and H1
            assign c1_scan = c1w_q;
        end else begin : g_c1_scan_now
            assign c1_scan = $signed(rel_q) >= $signed({2'b00, rom_q});
        end
    endgenerate

    // Field checks: HDR fc 1; SCAN fc 1 (E0), 3 (order, length), 4 (source), 5, 6 (destinations).
    wire [13:0] e3     = {2'b00, w_q} + {1'b0, w_q, 1'b0};          // 3 * W
    wire [13:0] ext_lo = {2'b00, rom_q[LO_BASE +: ALB_ROM_PLACE_BASE_W]} + e3;  // base + 3 * W
    wire [13:0] ext_hi = {2'b00, rom_q[HI_BASE +: ALB_ROM_PLACE_BASE_W]} + e3;
    wire [15:0] brd_ok = (NB >= 16) ? 16'hFFFF : ((16'd1 << NB) - 16'd1);
    wire [3:0]  lo_brd = rom_q[LO_BRD +: BRD_W];
    wire [3:0]  hi_brd = rom_q[HI_BRD +: BRD_W];
    wire        src_ok = (ext_lo >> AW) == 14'd0 && brd_ok[lo_brd];      // base + 3W < 2^AW
    wire        lo_ok  = (ext_lo >> AW) == 14'd0 && ext_lo[AW-1:2] != {(AW-2){1'b1}} &&
                         brd_ok[lo_brd];                                  // base + 3(W+1) < 2^AW
    wire        hi_ok  = (ext_hi >> AW) == 14'd0 && ext_hi[AW-1:2] != {(AW-2){1'b1}} &&
                         brd_ok[hi_brd];
    wire [3:0]  e0_kind = rom_q[ALB_ROM_E0_KIND_LSB +: ALB_ROM_E0_KIND_W];
    wire [3:0]  e0_nd   = rom_q[ALB_ROM_E0_ND_LSB +: ALB_ROM_E0_ND_W];
    wire [7:0]  e0_id   = rom_q[ALB_ROM_E0_ID_LSB +: ALB_ROM_E0_ID_W];
    wire [11:0] e0_w    = rom_q[ALB_ROM_E0_W_LSB +: ALB_ROM_E0_W_W];
    wire        e0_bad  = e0_kind[3:2] != 2'b00 ||
                          (rom_q[FLAG_SYNC] && !(cur_q == {LB{1'b0}} && smode_q && e0_kind == {2'b00, K_COPY})) ||
                          (e0_kind != {2'b00, K_IDLE} &&
                           (M_ND_BAD[{4'd0, e0_nd}] || M_CH_BAD[e0_id])) ||
                          (e0_kind == {2'b00, K_COPY}   && e0_w == 12'd0) ||
                          (e0_kind == {2'b00, K_TIME}   && e0_w != 12'd1) ||
                          (e0_kind == {2'b00, K_STATUS} && e0_w != W_STATUS);
    wire        nd_ge2  = nd_q[2] | nd_q[1];
    wire        nd_ge3  = nd_q[2] | (nd_q[1] & nd_q[0]);
    reg bad_now;
    always @* begin
        bad_now = 1'b0;
        if (state_q == S_HDR && fc_q == 1)
            bad_now = rom_q[ALB_ROM_H0_MAGIC_LSB +: ALB_ROM_H0_MAGIC_W] != ALB_ROM_MAGIC ||
                      M_NE_BAD[rom_q[ALB_ROM_H0_NE_LSB +: ALB_ROM_H0_NE_W]];
        else if (state_q == S_SCAN)
            case (fc_q)
                1: bad_now = e0_bad;
                3: bad_now = (lv_q != CYC_IDX && c2_lt) || (rom_q[31:8] == 24'd0 && M_LE_FC[rom_q[7:0]]);
                4: bad_now = kind_q == K_COPY && !src_ok;
                5: bad_now = kind_q != K_IDLE && (!lo_ok || (nd_ge2 && !hi_ok));
                6: bad_now = kind_q != K_IDLE && nd_ge3 && (!lo_ok || (nd_q == 3'd4 && !hi_ok));
                default: bad_now = 1'b0;
            endcase
    end

    always @(posedge clk_i) begin
        // schedule
        if (rel_op == R_ZERO)       rel_q <= 34'd0;
        else if (rel_op == R_PRE)   rel_q <= PRE;
        else if (rel_op == R_PRE_S) rel_q <= PRE_S;
        else if (rel_op != R_HOLD)  rel_q <= rel_sum;
        if (dl_load) dl_q <= dlm_dl_q;
        c2_q   <= c2_d;
        c1w_q  <= c1w_d;
        rel0_q <= rel_op == R_ZERO;
        rel_acc_q <= !rst_i && ((state_d == S_HDR && fc_d == 2) ||
                                (state_d == S_SCAN && (fc_d == 2 || fc_d == 3)));
        rel_two_q <= !rst_i && state_d == S_SCAN && fc_d == 4;
        ent_q <= ent_d;
        cur_q <= cur_d;
        lv_q  <= lv_d;
        if (sk_op == 2'd1)      sk_q <= 8'd0;
        else if (sk_op == 2'd2) sk_q <= sk_q + 8'd1;
        if (state_q == S_HDR && fc_q == 1) begin
            ne_q    <= rom_q[ALB_ROM_H0_NE_LSB +: ALB_ROM_H0_NE_W];
            smode_q <= rom_q[HFLAG_SYNC];
        end
        if (pmode_set)      pmode_q <= 1'b1;
        else if (pmode_clr) pmode_q <= 1'b0;
        if (ck_acc)         ck_q    <= {ck_base[31-CK_ROT:0], ck_base[31:32-CK_ROT]} ^ rom_q;
        if (ck_chk)         ck_ok_q <= ck_q == rom_q;
        if ((state_q == S_HDR || state_q == S_SCAN) && fc_q == 0) bad_q <= 1'b0;
        else if (bad_now)                                         bad_q <= 1'b1;
        // entry fields: E0 at fc 1, E3..E5 at fc 4..6
        if (ld_e0) begin
            kind_q  <= e0_kind[1:0];
            sflag_q <= rom_q[FLAG_SYNC];
            nd_q    <= e0_nd[2:0];
            w_q     <= e0_w;
        end
        chan_q <= chan_d;
        if ((state_q == S_SCAN || state_q == S_FETCH) && fc_q == 4) begin
            sbrd_q  <= rom_q[ALB_ROM_E3_SRC_BOARD_LSB +: BRD_W];
            sbase_q <= rom_q[ALB_ROM_E3_SRC_BASE_LSB +: AW];
        end
        if ((state_q == S_SCAN || state_q == S_FETCH) && fc_q == 5) begin
            dbrd_q[7:0]       <= {rom_q[ALB_ROM_E4_DST1_BOARD_LSB +: BRD_W], rom_q[ALB_ROM_E4_DST0_BOARD_LSB +: BRD_W]};
            dbase_q[2*AW-1:0] <= {rom_q[ALB_ROM_E4_DST1_BASE_LSB +: AW], rom_q[ALB_ROM_E4_DST0_BASE_LSB +: AW]};
        end
        if ((state_q == S_SCAN || state_q == S_FETCH) && fc_q == 6) begin
            dbrd_q[15:8]         <= {rom_q[ALB_ROM_E5_DST3_BOARD_LSB +: BRD_W], rom_q[ALB_ROM_E5_DST2_BOARD_LSB +: BRD_W]};
            dbase_q[4*AW-1:2*AW] <= {rom_q[ALB_ROM_E5_DST3_BASE_LSB +: AW], rom_q[ALB_ROM_E5_DST2_BASE_LSB +: AW]};
        end
        // working state (held at zero in INIT, which writes it to every channel)
        if (init || rst_i || state_q == S_FETCH)                                     imp_open_q <= 1'b0;
        else if (state_q == S_SRL_ST && acc_ack)                                     imp_open_q <= 1'b1;
        else if (state_q == S_SA_LD && acc_ack && vidx(a_byte) && a_byte[1:0] == rl_q) imp_open_q <= 1'b0;
        if (init)                     rl_q <= 2'd0;
        else if (st_ld)               rl_q <= st_q[33:32];
        else if (rl_op == RL_APEND)   rl_q <= apend_q;
        else if (rl_op == RL_ZERO)    rl_q <= 2'd0;
        if (init)                     need_q <= 4'd0;
        else if (st_ld)               need_q <= st_q[37:34];
        else if (need_op == N_ALL)    need_q <= 4'hF;
        else if (need_op == N_CLR)    need_q <= need_q & ~dsel;
        if (init)                     act_q <= 8'd0;
        else if (st_ld)               act_q <= st_q[45:38];
        else if (act_op == A_BYTE)    act_q <= put2(act_q, di_q, a_byte[1:0]);
        else if (act_op == A_ZERO)    act_q <= put2(act_q, di_q, 2'd0);
        else if (act_op == A_WBUF)    act_q <= put2(act_q, di_q, sel2(wbuf_q, di_q));
        if (init)                     tried_q <= 8'd0;
        else if (st_ld)               tried_q <= st_q[53:46];
        else if (tried_op == TR_ALL0) tried_q <= 8'd0;
        else if (tried_op == TR_CLR)  tried_q <= put2(tried_q, di_q, 2'd0);
        else if (tried_op == TR_SET)  tried_q <= put2(tried_q, di_q, sel2(wbuf_q, di_q));
        if (init)                     taken_q <= 32'd0;
        else if (taken_time)          taken_q <= time_q;
        else if (st_ld && kind_q == K_COPY) taken_q <= st_q[31:0];
        wbuf_q <= wbuf_d;
        if (st_ld) begin
            fl1_q <= 4'd0;
            out_q <= 4'd0;
        end else if (dfail) begin
            fl1_q <= fl1_q | dsel;
            out_q <= out_q | (fl1_q & dsel);
        end
        if (newv_set)      newv_q <= 1'b1;
        else if (newv_clr) newv_q <= 1'b0;
        if (apend_ld)      apend_q <= a_byte[1:0];
        di_q <= di_d;
        wi_q <= wi_d;
        w1_q <= w_q[AW-1:0] + TAKEN_W;
        case (pc_op)
            P_ZERO:  pc_q <= {PC_BITS{1'b0}};
            P_LAST:  pc_q <= PC_LAST;
            P_SAT:   if (pc_q != PC_LAST) pc_q <= pc_q + {{(PC_BITS-1){1'b0}}, 1'b1};
            default: pc_q <= pc_q + {{(PC_BITS-1){1'b0}}, 1'b1};
        endcase
        // bus
        if (go_new) begin
            we_q  <= a_we;
            adr_q <= {a_brd, a_word};
            sel_q <= a_sel;
            if (dat_sel != DS_NONE) dat_q <= dat_n;
        end
        if (go_new || go_retry) tmo_q <= {TMO_BITS{1'b0}};
        else if (cyc_q)         tmo_q <= tmo_q + {{(TMO_BITS-1){1'b0}}, 1'b1};
    end

    assign m_cyc_o      = cyc_q;
    assign m_stb_o      = cyc_q;
    assign m_we_o       = we_q;
    assign m_adr_o      = adr_q;
    assign m_sel_o      = sel_q;
    assign m_dat_o      = dat_q;
    assign time_o       = time_q;
    assign error_o      = err_q;
    assign rom_errors_o = rerr_q;

endmodule

`default_nettype wire
