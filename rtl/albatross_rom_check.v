// albatross_rom_check -- the schedule ROM's integrity check for
// albatross_sequencer: the start-up CRC pass and the background re-check,
// with the memory of prefix signatures (docs/controller.md "Execution").
// The sequencer owns the ROM and its one read port; this module says which
// word to read when the sequencer does not need the port, and checks the
// words so read.
// Rules:
//   * CRC (rtl/albatross_contract.toml): c = CRC_SEED; for each word w in
//     address order c = (c * x^32 + w) mod P, P = x^32 + CRC_POLY; over
//     words 0 .. 4+8*NE-1 (last_word_i), H3 included: H3 is the check word
//     that makes a valid image's CRC 0, so the check is a test for zero.
//   * The CRC takes CRC_BITS bits of a word in a clock, most significant
//     first: c = (c * x^N + chunk) mod P for the C = 32 / CRC_BITS chunks of
//     the word, which is the same CRC (a narrow step is smaller: with 4 bits
//     only the 11 low bits of c take an XOR).  The unit the check reads and
//     steps through is therefore a chunk {word, chunk index}: each chunk read
//     re-reads its word (the ROM holds no shift register), and a word takes
//     C clocks of the ROM port.
//   * Parts: part 0 is the header (words 0..3), part k+1 entry k (words
//     4+8k .. 11+8k).  A part ends with the last chunk of a word whose
//     address is 3 mod 8.
//   * A read is issued in each clock with bg_on_i high and main_rom_i low
//     (the sequencer's fetches come first); its data is checked in the next
//     clock.  The read index {word, chunk} then steps on, wrapping after
//     the last chunk of last_word_i (so it never exceeds last_word_i: it is
//     0 when the start-up pass begins, and the header fixes last_word_i
//     before).
//   * Start-up (learn_i): the CRC runs over the whole image, and its value
//     after each part is stored as that part's prefix signature (bad mark
//     clear), written in the clock after the part's last check from the CRC
//     register (which holds it then), at the part register the mismatch
//     marks are written at: the memory has one write address.  No read is
//     issued in the clock of the check of last_word_i's
//     last chunk; last_o is high in the clock after it, and crc_ok_o then
//     says whether the CRC (the register, through last_word_i) is 0: a test
//     of a register, not of the last step's result.  The pass takes
//     C * (4 + 8*NE) clocks.
//   * Background (learn_i low): the CRC is carried on from the stored
//     prefix of the previous part; at the end of each part it is compared
//     with that part's stored prefix.  A mismatch sets the part's bad mark
//     in the next clock (the compare ends at a register, not at the
//     signature RAM's write enable); mism_o is high in that clock for the
//     first mismatch of a part (counted once).  After last_word_i the CRC restarts from CRC_SEED (only with
//     the re-check: without it no word is checked after the start-up pass).
//   * One read port on the signatures: the background part, except in the
//     clock fetch_i (no background read is issued then), which reads part
//     fetch_part_i; bad_o is that part's bad mark in the next clock (as it
//     was before a write in the clock fetch_i).
//   * Reset (synchronous) clears the read address and the CRC; the
//     signature memory is never reset (the start-up pass writes it).
//   * HAS_ROM_RECHECK 0 (the sequencer then issues reads only in the
//     start-up pass): no background check, so no prefix is read back and no
//     bad mark is set: mism_o and bad_o are 0 (what the memory, written by
//     the start-up pass with clear marks, returned), and the signature
//     memory, its compare and the CRC reload are left out.
`default_nettype none

module albatross_rom_check #(
    parameter ROM_WORDS = 1024,  // schedule ROM depth in 32-bit words, >= 12
    parameter HAS_ROM_RECHECK = 1, // 1: the background re-check; 0: the start-up pass only
    parameter CRC_BITS = 4       // bits of a ROM word the CRC takes in a clock: 1, 2, 4, 8, 16 or 32
) (
    input  wire                     clk_i,
    input  wire                     rst_i,        // synchronous, active high
    input  wire                     learn_i,      // the start-up pass: store the prefixes
    input  wire                     bg_on_i,      // the check may read the ROM
    input  wire                     main_rom_i,   // the sequencer reads the ROM this clock
    input  wire [$clog2(ROM_WORDS)-1:0] last_word_i, // 4 + 8*NE - 1
    output wire [$clog2(ROM_WORDS)-1:0] adr_o,    // ROM word to read when main_rom_i is low
    input  wire [31:0]              rom_dat_i,    // the ROM word read in the previous clock
    input  wire                     fetch_i,      // clock S of a fetch: read fetch_part_i's mark
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [7:0]               fetch_part_i, // the part of the entry fetched: entry + 1
    /* verilator lint_on UNUSEDSIGNAL */
    output wire                     last_o,       // the clock after the check of last_word_i
    output wire                     crc_ok_o,     // the CRC register is 0
    output wire                     mism_o,       // a part's first background mismatch
    output wire                     bad_o         // the bad mark read for fetch_part_i
);

`include "albatross_contract.vh"

    localparam [31:0] CRC_POLY = ALB_ROM_CRC_POLY;  // P = x^32 + CRC_POLY
    localparam [31:0] CRC_SEED = ALB_ROM_CRC_SEED;  // c before the first word
    localparam NE_FIT  = (ROM_WORDS - 4) / 8;       // entries that fit
    localparam NE_MAX  = (NE_FIT > 255) ? 255 : NE_FIT; // entries the header may state
    localparam ROM_AW  = $clog2(ROM_WORDS);         // ROM word-address bits
    localparam RG_BITS = $clog2(NE_MAX + 1);        // parts: 0 header, k+1 entry k
    localparam CHUNKS  = 32 / CRC_BITS;             // C, clocks of the ROM port per word
    localparam CB      = (CHUNKS > 1) ? $clog2(CHUNKS) : 1;   // chunk-index bits
    localparam XW      = ROM_AW + CB;               // a read index {word, chunk}
    localparam integer  LAST_CHUNK_I = CHUNKS - 1;
    localparam [CB-1:0] LAST_CHUNK   = LAST_CHUNK_I[CB-1:0];
    // One word a clock (C = 1) keeps a constant 0 chunk bit: the index steps by 2.
    localparam [XW-1:0] STEP = (CHUNKS > 1) ? 1 : 2;

    generate
        if (CRC_BITS != 1 && CRC_BITS != 2 && CRC_BITS != 4 && CRC_BITS != 8 && CRC_BITS != 16 &&
            CRC_BITS != 32) begin : g_param_check
            albatross_rom_check_parameter_out_of_range u_error ();
        end
    endgenerate

    reg [XW-1:0]       bg_adr_q;      // next {word, chunk} to read
    reg [XW-1:0]       bg_dadr_q;     // {word, chunk} in rom_dat_i when bg_data_q
    reg                bg_data_q;
    reg                dat_last_q;    // bg_dadr_q is last_word_i's last chunk (last_word_i is fixed while checks run)
    reg [31:0]         crc_q;
    reg                last_q;        // the clock after the check of last_word_i

    // ------------------------------------------------------------ memory (never reset)
    // No collision logic on the RAM (no_rw_check: a read of the word written
    // in the same clock returns undefined data in hardware).  Only a fetch
    // read can meet a write (a background mismatch's mark of that part);
    // clash_q then gives the old mark, which the part's background read
    // left in sig_q[32] in the compare's clock, kept in mark_old_q (what a
    // read-first RAM would return).  (A start-up write can meet a background
    // read of its part, whose data the start-up pass does not use.)
    (* no_rw_check, ram_style = "block" *)
    reg [32:0]         sig [0:NE_MAX]; // {part r found bad, prefix CRC after part r}
    reg [32:0]         sig_q;
    reg                clash_q;       // the fetch read met a write of its part ...
    reg                clash_bad_q;   // ... whose old mark this is

    function [31:0] crc_step;            // (crc * x^N + chunk) mod P, N = CRC_BITS, one bit at a time
        input [31:0]         crc;
        input [CRC_BITS-1:0] chunk;
        integer i;
        reg [31:0] x;
        begin
            x = crc;
            for (i = CRC_BITS - 1; i >= 0; i = i - 1) x = {x[30:0], chunk[i]} ^ (x[31] ? CRC_POLY : 32'd0);
            crc_step = x;
        end
    endfunction

    wire [ROM_AW-1:0]   word     = bg_dadr_q[XW-1 -: ROM_AW];        // the word in rom_dat_i
    wire [CB-1:0]       chunk_ix = bg_dadr_q[CB-1:0];
    /* verilator lint_off UNUSEDSIGNAL */
    wire [CB+4:0]       amount   = {chunk_ix, 5'd0} >> CB;          // CRC_BITS * chunk_ix, no multiplier
    wire [31:0]         shifted  = rom_dat_i << amount;             // chunk 0: the top bits
    /* verilator lint_on UNUSEDSIGNAL */
    wire [CRC_BITS-1:0] chunk    = shifted[31 -: CRC_BITS];
    wire [ROM_AW-1:0]   adr_word = bg_adr_q[XW-1 -: ROM_AW];
    wire [RG_BITS-1:0] part     = word[RG_BITS+2:3];                 // 0 header, k+1 entry k
    wire               p_end    = bg_data_q && word[2:0] == 3'b011 && chunk_ix == LAST_CHUNK;
    wire               at_last  = bg_adr_q == {last_word_i, LAST_CHUNK};
    wire               p_last   = bg_data_q && dat_last_q;
    // (start-up: no read in the clock of the last check, so that the CRC
    // register holds the whole image's CRC in the next clock)
    wire               bg_issue = bg_on_i && !main_rom_i && !(p_last && learn_i);
    wire [31:0]        crc_n    = crc_step(crc_q, chunk);
    wire [RG_BITS-1:0] fetch_part = fetch_part_i[RG_BITS-1:0];
    wire [RG_BITS-1:0] rd_part  = fetch_i ? fetch_part : adr_word[RG_BITS+2:3];
    localparam         RECHECK  = HAS_ROM_RECHECK != 0;
    wire               mism     = RECHECK && p_end && !learn_i && crc_n != sig_q[31:0];

    // The mismatch is a register: the mark is written a clock after the
    // compare (its part and its old mark kept), so that no path runs from
    // the signature RAM's output through the compare into its write enable.
    reg                mism_q;        // part mism_part_q mismatched in the last clock ...
    reg [RG_BITS-1:0]  mism_part_q;
    reg                mark_old_q;    // ... its mark then (sig_q[32] of that clock)
    reg                learn_wr_q;    // part mism_part_q ended in the start-up pass in the last clock: crc_q is its prefix

    always @(posedge clk_i) begin
        // A mismatch writes the mark alone (bit write enables, no data multiplexer).
        if (learn_wr_q)           sig[mism_part_q][31:0] <= crc_q;
        if (learn_wr_q || mism_q) sig[mism_part_q][32]   <= mism_q;
        sig_q       <= sig[rd_part];
        mism_part_q <= part;
        mark_old_q  <= sig_q[32];
        clash_q     <= fetch_i && mism_q && fetch_part == mism_part_q;
        clash_bad_q <= mark_old_q;
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            bg_data_q <= 1'b0;
            bg_adr_q  <= {XW{1'b0}};
            crc_q     <= CRC_SEED;
            last_q    <= 1'b0;
            mism_q    <= 1'b0;
            learn_wr_q <= 1'b0;
        end else begin
            mism_q    <= mism;
            learn_wr_q <= p_end && learn_i;
            bg_data_q <= bg_issue;
            bg_dadr_q <= bg_adr_q;
            dat_last_q <= at_last;                  // one compare for the wrap and p_last
            if (bg_issue) bg_adr_q <= at_last ? {XW{1'b0}} : bg_adr_q + STEP;
            last_q    <= p_last;
            // After the last word the CRC restarts from CRC_SEED: at once in
            // the background, a clock later after the start-up pass (its CRC
            // is compared in that clock).
            if (bg_data_q) crc_q <= (RECHECK && p_last && !learn_i) ? CRC_SEED :
                                    (RECHECK && p_end && !learn_i) ? sig_q[31:0] : crc_n;
            else if (RECHECK && last_q) crc_q <= CRC_SEED;
        end
    end

    assign adr_o    = adr_word;
    assign last_o   = last_q;
    assign crc_ok_o = crc_q == 32'd0;
    assign mism_o   = mism_q && !mark_old_q;
    assign bad_o    = RECHECK && (clash_q ? clash_bad_q : sig_q[32]);

endmodule

`default_nettype wire
