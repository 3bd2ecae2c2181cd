// albatross_entry_fields -- the fields of the entry albatross_sequencer
// fetches, taken from the ROM word of each fetch clock (docs/controller.md
// "Schedule ROM"): registers the transfer datapath reads through the slot.
// Rules:
//   * fetch_i with step_i = 1 (E0): kind, the flags SYNC, FOUR_SLOT, REQUEST
//     and MODE (the last two only with HAS_MODES), channel id, ND, W and
//     3 * W (FOUR_SLOT: 4 * W, the span the entry check needs); step 3 (E3):
//     the source place; step 4 (E4): destinations 0 and 1; step 5 (E5):
//     destinations 2 and 3.  Each field holds until its word's next fetch.
//   * E7 (HAS_FRAGMENTS): the fetch clocks are all taken, so E7 of the
//     entry that runs is read in the first clock of its transfer (e7_rd_o,
//     the clock after go_i, at {e7_ent_o, 011}: e7_ent_o is the entry + 1,
//     taken in FETCH clock 5); frag_on_o, its frag field is not 0, from the
//     clock after that read (of the ROM word itself, then a register), held
//     until the next transfer's.  HAS_FRAGMENTS 0: no read, frag_on_o 0.
//   * Data registers: never reset (the sequencer starts no slot before a
//     fetch has written them); reset clears the E7 read strobes.
`default_nettype none

module albatross_entry_fields #(
    parameter ADDR_WIDTH = 10, // word-address bits of a board RAM
    parameter HAS_MODES  = 1,  // 1: the REQUEST and MODE flags; 0: read as 0
    parameter HAS_FRAGMENTS = 1 // 1: E7.frag != 0 of the entry that runs; 0: frag_on_o is 0
) (
    input  wire                    clk_i,
    input  wire                    rst_i,          // synchronous, active high (the E7 strobes)
    input  wire                    fetch_i,        // the sequencer fetches an entry (step_i: its clock)
    input  wire [2:0]              step_i,
    input  wire [31:0]             rom_i,          // the ROM word read in the previous clock
    input  wire [7:0]              ent_inc_i,      // the entry fetched + 1
    input  wire                    go_i,           // one clock: the entry's transfer starts
    output wire                    e7_rd_o,        // read E7 of the entry that runs now (at {e7_ent_o, 011})
    output reg  [7:0]              e7_ent_o,       // the entry that runs + 1
    output wire                    frag_on_o,      // E7.frag != 0 for the entry that runs (2 clocks after go_i on)
    output reg  [1:0]              kind_o,
    output reg                     sync_o,         // E0 flag SYNC
    output reg                     four_o,         // E0 flag FOUR_SLOT
    output reg                     request_o,      // E0 flag REQUEST
    output reg                     mode_info_o,    // E0 flag MODE
    output reg  [6:0]              chan_o,
    output reg  [2:0]              nd_o,
    output reg  [11:0]             words_o,        // W
    output reg  [13:0]             span_o,         // 3 * W (FOUR_SLOT: 4 * W)
    output reg  [3:0]              src_board_o,
    output reg  [ADDR_WIDTH-1:0]   src_base_o,
    output reg  [15:0]             dst_board_o,    // destination d at [4d +: 4]
    output reg  [4*ADDR_WIDTH-1:0] dst_base_o      // destination d at [d*ADDR_WIDTH +: ADDR_WIDTH]
);

`include "albatross_contract.vh"

    localparam AW        = ADDR_WIDTH;
    localparam FLAG_SYNC = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_SYNC;
    localparam FLAG_FOUR = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_FOUR_SLOT;
    localparam FLAG_REQ  = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_REQUEST;
    localparam FLAG_MODE = ALB_ROM_E0_FLAGS_LSB + ALB_ROM_EFLAG_MODE;

    wire [11:0] w = rom_i[ALB_ROM_E0_W_LSB +: 12];

    always @(posedge clk_i) if (fetch_i) begin
        case (step_i)
            3'd1: begin                                                         // E0
                kind_o      <= rom_i[ALB_ROM_E0_KIND_LSB +: 2];
                sync_o      <= rom_i[FLAG_SYNC];
                four_o      <= rom_i[FLAG_FOUR];
                request_o   <= HAS_MODES != 0 && rom_i[FLAG_REQ];
                mode_info_o <= HAS_MODES != 0 && rom_i[FLAG_MODE];
                chan_o      <= rom_i[ALB_ROM_E0_ID_LSB +: 7];
                nd_o        <= rom_i[ALB_ROM_E0_ND_LSB +: 3];
                words_o     <= w;
                span_o      <= rom_i[FLAG_FOUR] ? {w, 2'b00} : {2'b00, w} + {1'b0, w, 1'b0};
            end
            3'd3: begin                                                         // E3
                src_board_o <= rom_i[ALB_ROM_E3_SRC_BOARD_LSB +: 4];
                src_base_o  <= rom_i[ALB_ROM_E3_SRC_BASE_LSB +: AW];
            end
            3'd4: begin                                                         // E4
                dst_board_o[7:0]    <= {rom_i[ALB_ROM_E4_DST1_BOARD_LSB +: 4], rom_i[ALB_ROM_E4_DST0_BOARD_LSB +: 4]};
                dst_base_o[2*AW-1:0] <= {rom_i[ALB_ROM_E4_DST1_BASE_LSB +: AW], rom_i[ALB_ROM_E4_DST0_BASE_LSB +: AW]};
            end
            3'd5: begin                                                         // E5
                dst_board_o[15:8]       <= {rom_i[ALB_ROM_E5_DST3_BOARD_LSB +: 4], rom_i[ALB_ROM_E5_DST2_BOARD_LSB +: 4]};
                dst_base_o[4*AW-1:2*AW] <= {rom_i[ALB_ROM_E5_DST3_BASE_LSB +: AW], rom_i[ALB_ROM_E5_DST2_BASE_LSB +: AW]};
                e7_ent_o                <= ent_inc_i;
            end
            default: ;
        endcase
    end

    // E7 of the entry that runs: read now / in rom_i now; its frag is not 0
    wire        e7_on = rom_i[ALB_ROM_E7_FRAG_LSB +: 12] != 12'd0;
    reg         e7_rd_q, e7_q;
    reg         frag_q;
    always @(posedge clk_i) begin
        e7_rd_q <= !rst_i && HAS_FRAGMENTS != 0 && go_i;
        e7_q    <= !rst_i && e7_rd_q;
        if (e7_q) frag_q <= e7_on;
    end
    assign e7_rd_o = e7_rd_q;
    assign frag_on_o = HAS_FRAGMENTS != 0 && (e7_q ? e7_on : frag_q);

endmodule

`default_nettype wire
