// albatross_schedule_rom -- the schedule ROM of albatross_sequencer and its
// one read port: which word is read in each clock.
// Rules:
//   * The ROM (ROM_WORDS 32-bit words) is loaded from ROM_FILE ($readmemh; in
//     simulation +rom=FILE overrides it), zero elsewhere; never reset.
//   * One read a clock, registered: dat_o holds, from the next clock on, the
//     word addressed in this one.  A main read (main_o) has priority: the
//     header (header_i: step_i 0..3 read H0, H1, H2 and entry 0's E1),
//     the clock S of a fetch (start_i: E0 of entry ent_i) and the fetch
//     (fetch_i, step_i 1..6: E2, E3, E4, E5, then E1 of the next entry, of
//     entry first_i, the mode's first, after the last, last_i; in clock 6
//     E6 of entry ent_i, which the sequencer has moved on to that next
//     entry), the mode table's reads (mode_rd_i at mode_adr_i), E1 of entry
//     ent_i for the mode load (e1_i: the sequencer's entry register holds
//     the new mode's first entry then, so the mode table's reads carry no
//     entry address) and E6 of entry ent_i for the mode load and for the
//     header (e6_i; ent_i is 0 in the header), the last three only while no
//     other main read runs (HAS_E6 0: no E6 read), and
//     E7 of the entry whose transfer runs (e7_i, in its transfer's first
//     clock: {e7_ent_i, 011}, e7_ent_i that entry + 1).  In every other clock the word is the background
//     check's (bg_adr_i, rtl/albatross_rom_check.v).
//   * Addresses: entry k's word j is 4 + 8k + j = {k, 3'b100} + j (mod
//     2^ROM_AW): E0..E3 are {k, 1jj}; E4..E7 are {k + 1, 0jj}, k + 1 from
//     the sequencer (ent_inc_i): no adder.
//   * Simulation only: +rom_upset_word=N +rom_upset_at=T flips bit 16 of
//     word N when time_i = T (a run-time upset for the background check).
`default_nettype none

module albatross_schedule_rom #(
    parameter ROM_WORDS = 1024, // ROM depth in 32-bit words, >= 12
    parameter ROM_FILE  = "",   // $readmemh image; simulation: +rom=FILE overrides
    parameter HAS_E6    = 1     // 1: the E6 reads (FETCH clock 6, e6_i); 0: none (no minor cycles, no entry check)
) (
    input  wire              clk_i,
    input  wire [31:0]       time_i,      // global time (simulation upsets only)
    input  wire              header_i,    // the header is read (step_i 0..3)
    input  wire              start_i,     // clock S of a fetch: read E0
    input  wire              fetch_i,     // the entry is fetched (step_i 1..5: a read; 6: none)
    input  wire [2:0]        step_i,      // clock within the header or the fetch
    input  wire [7:0]        ent_i,       // the entry fetched
    input  wire [7:0]        ent_inc_i,   // ent_i + 1
    input  wire              last_i,      // ent_i is the last entry
    input  wire [7:0]        first_i,     // the mode's first entry (after the last)
    input  wire              mode_rd_i,   // a read of the mode table (rtl/albatross_mode_switch.v)
    input  wire [$clog2(ROM_WORDS)-1:0] mode_adr_i,
    input  wire              e1_i,        // a read of E1 of entry ent_i (the mode load's)
    input  wire              e6_i,        // a read of E6 of entry ent_i (the mode load's, the header's)
    input  wire              e7_i,        // a read of E7 of the running entry (its transfer's first clock)
    input  wire [7:0]        e7_ent_i,    // that entry + 1
    input  wire [$clog2(ROM_WORDS)-1:0] bg_adr_i,    // the background check's word
    output wire              main_o,      // a main read in this clock (the check's word waits)
    output wire [31:0]       dat_o
);

    localparam              ROM_AW = $clog2(ROM_WORDS);
    localparam [ROM_AW-1:0] A1 = 1, A2 = 2, A5 = 5;

    // ------------------------------------------------------------ memory (never reset)
    reg [31:0] rom [0:ROM_WORDS-1];
    reg [31:0] dat_q;

    integer ri;
`ifndef SYNTHESIS
    reg [8*1024-1:0] rom_arg;
    integer upset_word, upset_at;
`endif
    initial begin
        for (ri = 0; ri < ROM_WORDS; ri = ri + 1) rom[ri] = 32'd0;
        if (ROM_FILE != "") $readmemh(ROM_FILE, rom);
`ifndef SYNTHESIS
        if ($value$plusargs("rom=%s", rom_arg)) $readmemh(rom_arg, rom);
        if (!$value$plusargs("rom_upset_word=%d", upset_word)) upset_word = -1;
        if (!$value$plusargs("rom_upset_at=%d", upset_at)) upset_at = 0;
`endif
    end

    // ------------------------------------------------------------ address
    localparam        E6        = HAS_E6 != 0;
    wire              e6_rd     = E6 && ((fetch_i && step_i == 3'd6) || e6_i);   // E6 of entry ent_i
    wire              fetch_rom = fetch_i && step_i <= 3'd5;
    wire              main_rom  = header_i || start_i || fetch_rom || mode_rd_i || e1_i || e6_rd || e7_i;
    wire              adr_inc   = (fetch_i && step_i >= 3'd3) || (E6 && e6_i);  // E4, E5, next E1, E6
    /* verilator lint_off UNUSEDSIGNAL */
    wire [7:0]        ent_sel   = adr_inc ? ent_inc_i : ent_i;
    wire [7:0]        ent_wrap  = first_i;
    wire [7:0]        ent_e7    = e7_ent_i;
    wire              adr_wrap  = fetch_i && step_i == 3'd5 && last_i;  // last entry: word 5
    /* verilator lint_on UNUSEDSIGNAL */
    reg  [2:0]        adr_lo;
    always @* begin
        adr_lo = 3'b100;                                             // E0 (start_i)
        if (e6_rd) adr_lo = 3'b010;                                  // E6 of ent_i: {ent_i + 1, 010}
        else if (e1_i) adr_lo = 3'b101;                              // E1 of ent_i
        else if (fetch_i)
            case (step_i)
                3'd1:    adr_lo = 3'b110;                            // E2
                3'd2:    adr_lo = 3'b111;                            // E3
                3'd3:    adr_lo = 3'b000;                            // E4
                3'd4:    adr_lo = 3'b001;                            // E5
                default: adr_lo = 3'b101;                            // E1 of the next entry
            endcase
    end
    reg [ROM_AW-1:0] main_adr;
    always @* begin
        main_adr = {adr_wrap ? ent_wrap[ROM_AW-4:0] : ent_sel[ROM_AW-4:0], adr_lo};
        if (e7_i) main_adr = {ent_e7[ROM_AW-4:0], 3'b011};        // E7: {k + 1, 011}
        if (mode_rd_i) main_adr = mode_adr_i;
        if (header_i)
            case (step_i)
                3'd0:    main_adr = {ROM_AW{1'b0}};
                3'd1:    main_adr = A1;
                3'd2:    main_adr = A2;
                default: main_adr = A5;                              // E1 of entry 0
            endcase
    end
    always @(posedge clk_i) begin
        dat_q <= rom[main_rom ? main_adr : bg_adr_i];
`ifndef SYNTHESIS
        if (upset_word >= 0 && upset_word < ROM_WORDS && time_i == upset_at[31:0])
            rom[upset_word] <= rom[upset_word] ^ 32'h00010000;
`endif
    end

    assign main_o = main_rom;
    assign dat_o  = dat_q;

endmodule

`default_nettype wire
