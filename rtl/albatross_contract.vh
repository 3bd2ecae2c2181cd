// Generated from rtl/albatross_contract.toml by make contract (compiler/albatross_schedule/contract_gen.py); do not edit.
// The ALBATROSS contract for albatross_controller (`include'd inside its module
// body): the schedule ROM's fields as <WORD>_<FIELD>_LSB / _W (bits [LSB+W-1:LSB]
// of the word), its constants, and the channel layout in bytes from the channel
// base.  See docs/contract.md.
/* verilator lint_off UNUSEDPARAM */
localparam ALB_ROM_HEADER_WORDS    = 4;
localparam ALB_ROM_ENTRY_WORDS     = 8;
localparam [15:0] ALB_ROM_MAGIC      = 16'hA1BA;
localparam [31:0] ALB_ROM_CRC_POLY = 32'h000000AF;  // P = x^32 + POLY; c = (c * x^32 + word) mod P
localparam [31:0] ALB_ROM_CRC_SEED = 32'hFFFFFFFF;
localparam ALB_ROM_CRC_WORD        = 3;  // the check word: a valid image's CRC is 0
localparam ALB_ROM_TIME_BITS       = 16;  // widest time within a cycle
localparam ALB_ROM_MAX_ENTRIES     = 255;
localparam ALB_ROM_MAX_DESTS       = 4;
// fields
localparam ALB_ROM_H0_MAGIC_LSB      = 16, ALB_ROM_H0_MAGIC_W      = 16;
localparam ALB_ROM_H0_NE_LSB         =  8, ALB_ROM_H0_NE_W         =  8;
localparam ALB_ROM_H0_FLAGS_LSB      =  0, ALB_ROM_H0_FLAGS_W      =  8;
localparam ALB_ROM_H1_CYCLE_LSB      =  0, ALB_ROM_H1_CYCLE_W      = 16;
localparam ALB_ROM_H1_NEXT_LSB       = 16, ALB_ROM_H1_NEXT_W       = 16;
localparam ALB_ROM_H2_DROP_RUN_LSB   =  0, ALB_ROM_H2_DROP_RUN_W   =  8;
localparam ALB_ROM_H2_TABLE_LSB      =  8, ALB_ROM_H2_TABLE_W      =  8;
localparam ALB_ROM_H2_MODES_LSB      = 16, ALB_ROM_H2_MODES_W      =  4;
localparam ALB_ROM_H2_CLUSTER_LSB    = 20, ALB_ROM_H2_CLUSTER_W    =  4;
localparam ALB_ROM_H2_START_END_LSB  = 24, ALB_ROM_H2_START_END_W  =  8;
localparam ALB_ROM_H3_CRC_LSB        =  0, ALB_ROM_H3_CRC_W        = 32;
localparam ALB_ROM_E0_KIND_LSB       = 28, ALB_ROM_E0_KIND_W       =  4;
localparam ALB_ROM_E0_FLAGS_LSB      = 24, ALB_ROM_E0_FLAGS_W      =  4;
localparam ALB_ROM_E0_ID_LSB         = 16, ALB_ROM_E0_ID_W         =  8;
localparam ALB_ROM_E0_ND_LSB         = 12, ALB_ROM_E0_ND_W         =  4;
localparam ALB_ROM_E0_W_LSB          =  0, ALB_ROM_E0_W_W          = 12;
localparam ALB_ROM_E1_START_LSB      =  0, ALB_ROM_E1_START_W      = 16;
localparam ALB_ROM_E2_LENGTH_LSB     =  0, ALB_ROM_E2_LENGTH_W     = 16;
localparam ALB_ROM_E3_SRC_LSB        =  0, ALB_ROM_E3_SRC_W        = 16;
localparam ALB_ROM_E3_SRC_BOARD_LSB  = 12, ALB_ROM_E3_SRC_BOARD_W  =  4;
localparam ALB_ROM_E3_SRC_BASE_LSB   =  0, ALB_ROM_E3_SRC_BASE_W   = 12;
localparam ALB_ROM_E4_DST0_LSB       =  0, ALB_ROM_E4_DST0_W       = 16;
localparam ALB_ROM_E4_DST0_BOARD_LSB = 12, ALB_ROM_E4_DST0_BOARD_W =  4;
localparam ALB_ROM_E4_DST0_BASE_LSB  =  0, ALB_ROM_E4_DST0_BASE_W  = 12;
localparam ALB_ROM_E4_DST1_LSB       = 16, ALB_ROM_E4_DST1_W       = 16;
localparam ALB_ROM_E4_DST1_BOARD_LSB = 28, ALB_ROM_E4_DST1_BOARD_W =  4;
localparam ALB_ROM_E4_DST1_BASE_LSB  = 16, ALB_ROM_E4_DST1_BASE_W  = 12;
localparam ALB_ROM_E5_DST2_LSB       =  0, ALB_ROM_E5_DST2_W       = 16;
localparam ALB_ROM_E5_DST2_BOARD_LSB = 12, ALB_ROM_E5_DST2_BOARD_W =  4;
localparam ALB_ROM_E5_DST2_BASE_LSB  =  0, ALB_ROM_E5_DST2_BASE_W  = 12;
localparam ALB_ROM_E5_DST3_LSB       = 16, ALB_ROM_E5_DST3_W       = 16;
localparam ALB_ROM_E5_DST3_BOARD_LSB = 28, ALB_ROM_E5_DST3_BOARD_W =  4;
localparam ALB_ROM_E5_DST3_BASE_LSB  = 16, ALB_ROM_E5_DST3_BASE_W  = 12;
localparam ALB_ROM_E6_BASE_LSB       =  0, ALB_ROM_E6_BASE_W       = 15;
localparam ALB_ROM_E6_REP_LSB        = 16, ALB_ROM_E6_REP_W        =  4;
localparam ALB_ROM_E7_FRAG_LSB       =  0, ALB_ROM_E7_FRAG_W       = 12;
localparam ALB_ROM_D0_CYCLE_LSB      =  0, ALB_ROM_D0_CYCLE_W      = 16;
localparam ALB_ROM_D0_FIRST_LSB      = 16, ALB_ROM_D0_FIRST_W      =  8;
localparam ALB_ROM_D0_END_LSB        = 24, ALB_ROM_D0_END_W        =  8;
localparam ALB_ROM_D1_DROP_RUN_LSB   =  0, ALB_ROM_D1_DROP_RUN_W   =  8;
localparam ALB_ROM_D1_NEXT_LSB       = 16, ALB_ROM_D1_NEXT_W       = 16;
localparam ALB_ROM_D2_CLUSTER_LSB    = 20, ALB_ROM_D2_CLUSTER_W    =  4;
localparam ALB_ROM_PLACE_BOARD_LSB = 12, ALB_ROM_PLACE_BOARD_W = 4;
localparam ALB_ROM_PLACE_BASE_LSB  = 0, ALB_ROM_PLACE_BASE_W  = 12;
// E0.kind codes; flag bits within H0.flags and E0.flags
localparam [3:0] ALB_KIND_IDLE   = 4'd0;
localparam [3:0] ALB_KIND_COPY   = 4'd1;
localparam [3:0] ALB_KIND_TIME   = 4'd2;
localparam [3:0] ALB_KIND_STATUS = 4'd3;
localparam ALB_ROM_HFLAG_SYNC_MODE = 0;
localparam ALB_ROM_EFLAG_SYNC = 0;
localparam ALB_ROM_EFLAG_FOUR_SLOT = 1;
localparam ALB_ROM_EFLAG_REQUEST = 2;
localparam ALB_ROM_EFLAG_MODE = 3;
// channel layout: byte offsets from the channel base; buffer index values
localparam ALB_CH_OFF_ACTUAL     = 0;
localparam ALB_CH_OFF_READLOCKED = 1;
localparam ALB_CH_OFF_BUFFERS    = 4;
localparam ALB_CH_WORD_BYTES     = 4;
localparam ALB_CH_BUFFERS        = 3;
localparam ALB_CH_BUFFER1        = 1;
localparam ALB_CH_BUFFER_LAST    = 3;
localparam ALB_CH_INITIAL_INDEX  = 1;
localparam ALB_CH_NOT_STARTED    = 0;  // a control byte its writer has not set yet
localparam ALB_CH_TAKEN_AT_WORDS = 1;  // destination stride: W + TAKEN_AT_WORDS
// four-slot kind (E0 flag FOUR_SLOT): slot bytes, buffers 1..FS_BUFFERS, buffer b is
// pair (b-1)>>1, slot (b-1)&1
localparam ALB_CH_OFF_SLOT0      = 2;
localparam ALB_CH_OFF_SLOT1      = 3;
localparam ALB_FS_BUFFERS        = 4;
localparam ALB_FS_BUFFER_LAST    = 4;
localparam ALB_FS_INITIAL_SLOT   = 0;
/* verilator lint_on UNUSEDPARAM */
