// albatross_header_check -- the header words of albatross_sequencer's start-up
// (docs/controller.md "Validation"): what the sequencer keeps of them and
// whether they are valid.
// Rules:
//   * The sequencer reads H0, H1, H2 in its header steps; step_i (with hdr_i)
//     says which word rom_i holds: 1 H0, 2 H1, 3 H2.
//   * H0: the entry count NE (ne_o) and the sync-mode flag (smode_o) are
//     kept until the next start-up; the header is invalid when the magic is
//     not ALB_MAGIC or NE is outside 1..NE_MAX (NE_MAX the entries that fit
//     in ROM_WORDS, at most 255).
//   * H1: invalid when the cycle length does not fit in TIME_BITS or is 0
//     (H1's upper half is the start-up mode's next mask: albatross_mode_switch).
//   * H2: with modes (H2.modes > 0), invalid when start_end is 0 or above NE.
//   * bad_o rises in the clock after the word's check and stays high until
//     reset: the sequencer raises error_o with it and never leaves the
//     start-up.
//   * Reset (synchronous) clears bad_o; NE and the flag are written by H0.
`default_nettype none

module albatross_header_check #(
    parameter ROM_WORDS = 1024, // schedule ROM depth in 32-bit words, >= 12
    parameter TIME_BITS = 16    // bits of time within a cycle, 4..31
) (
    input  wire        clk_i,
    input  wire        rst_i,         // synchronous, active high
    input  wire        hdr_i,         // a header step runs this clock
    input  wire [2:0]  step_i,        // which: rom_i holds H0 (1), H1 (2), H2 (3)
    input  wire [31:0] rom_i,         // the ROM word read in the previous clock
    output wire [7:0]  ne_o,          // H0's NE
    output wire        smode_o,       // H0's SYNC_MODE flag: the ROM is position-synchronised
    output wire        bad_o          // a header word was invalid
);

`include "albatross_contract.vh"

    localparam NE_FIT  = (ROM_WORDS - 4) / 8;
    localparam NE_MAX  = (NE_FIT > 255) ? 255 : NE_FIT;
    localparam TB      = TIME_BITS;
    localparam [7:0] NE_MAX8    = NE_MAX[7:0];
    localparam       HFLAG_SYNC = ALB_ROM_H0_FLAGS_LSB + ALB_ROM_HFLAG_SYNC_MODE;

    reg  [7:0] ne_q;
    reg        smode_q;
    reg        bad_q;
    wire       h2_modes = rom_i[ALB_ROM_H2_MODES_LSB +: ALB_ROM_H2_MODES_W] != 0;
    // start_end > NE as the borrow of NE - start_end: a carry chain alone (Yosys
    // maps an equal-width relational operator to a carry chain and an equality tree)
    /* verilator lint_off UNUSEDSIGNAL */  // (only the borrow is read)
    wire [8:0] se_df    = {1'b0, ne_q} - {1'b0, rom_i[ALB_ROM_H2_START_END_LSB +: 8]};
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk_i) begin
        if (rst_i) bad_q <= 1'b0;
        else if (hdr_i)
            case (step_i)
                3'd1: begin                                             // H0
                    ne_q    <= rom_i[ALB_ROM_H0_NE_LSB +: 8];
                    smode_q <= rom_i[HFLAG_SYNC];
                    if (rom_i[ALB_ROM_H0_MAGIC_LSB +: 16] != ALB_ROM_MAGIC ||
                        rom_i[ALB_ROM_H0_NE_LSB +: 8] == 8'd0 || rom_i[ALB_ROM_H0_NE_LSB +: 8] > NE_MAX8)
                        bad_q <= 1'b1;
                end
                3'd2: begin                                             // H1
                    if ((rom_i[ALB_ROM_H1_CYCLE_LSB +: 16] >> TB) != 16'd0 || rom_i[TB-1:0] == {TB{1'b0}})
                        bad_q <= 1'b1;
                end
                3'd3: begin                                             // H2
                    if (h2_modes && (rom_i[ALB_ROM_H2_START_END_LSB +: 8] == 8'd0 ||
                                     se_df[8]))
                        bad_q <= 1'b1;
                end
                default: ;
            endcase
    end

    assign ne_o    = ne_q;
    assign smode_o = smode_q;
    assign bad_o   = bad_q;

endmodule

`default_nettype wire
