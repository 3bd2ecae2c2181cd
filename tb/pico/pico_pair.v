// pico_pair -- test top: two soft cores share one albatross_dpram.  Each is
// a PicoRV32 (pico_core) or, where SERV_MASK selects it, a SERV (serv_core,
// the same ports), or, where VEX_MASK selects it, a VexRiscv with caches
// (vexriscv_core: its window is at 0x9000_0000, its registers at
// 0xA000_0000, both uncached; CACHED_ALIAS = 1 also maps them cached at 0x1
// and 0x2, for the negative test); SERV_MASK = VEX_MASK = 0 is the PicoRV32
// pair.  Both RAM ports (mon_*: an access completes in a clock where its
// ack is high) and the board events (ev_*) are brought out for a harness's
// protocol checker (tools/mk/vexriscv.mk).
//
// Core 0 (the producer) reaches the RAM through port A, core 1 (the consumer)
// through port B, each through a pico_wb_adapter.  Every core has its own
// program RAM, loaded with $readmemh from the plusargs +fw0=FILE and
// +fw1=FILE, and its own board registers.  Memory map of each core (the
// address bits 31:28 select the region; soc/firmware/board.h):
//   0x0xxx_xxxx  local RAM, RAM_WORDS words, one-cycle access
//   0x1xxx_xxxx  DPRAM window: the core's port of the shared RAM
//   0x2xxx_xxxx  board registers: +0 TOHOST (a store sets done_o[c] and
//                code_o[c]), +0x10..0x1c STAT 0..3 (stat_o), +0x20 EVENT and
//                +0x24 ARG (unused here); reads give 0 (soc/board_memmap.v)
//   other        bus_err_o[c] is set (sticky); the access completes, reads 0
// Core c uses the flattened outputs' bits [c*w +: w].  The cores run on clk_i
// with the RAM and share rst_i (synchronous, active high).  stall_i[c] holds
// core c's local-RAM accesses (instruction fetches included) while high: the
// harness uses it to vary the two cores' relative speed and phase, as an
// interrupt or a slow memory would; DPRAM accesses are never held.
`default_nettype none

module pico_pair #(
    parameter ADDR_WIDTH = 10,   // word-address bits of the shared DPRAM
    parameter RAM_WORDS  = 4096, // words of each core's local RAM (16 KiB)
    parameter SERV_MASK  = 0,    // 2 bits: core c is SERV when bit c is set, else PicoRV32
    parameter VEX_MASK   = 0,    // 2 bits: core c is VexRiscv when bit c is set (before SERV_MASK)
    parameter CACHED_ALIAS = 0   // VexRiscv cores: 1 also maps the DPRAM window and registers cached
) (
    input  wire         clk_i,
    input  wire         rst_i,      // synchronous, active high
    input  wire [1:0]   stall_i,    // core c: hold its local-RAM access this cycle
    output wire [1:0]   done_o,     // core c stored to TOHOST
    output wire [63:0]  code_o,     // the value it stored (exit code)
    output wire [255:0] stat_o,     // core c: STAT k at [c*128 + k*32 +: 32]
    output wire [1:0]   trap_o,     // core c trapped (PicoRV32 trap; 0 on SERV)
    output wire [1:0]   bus_err_o,  // core c accessed an unmapped address
    // monitors: port A (core 0) and port B (core 1) of the DPRAM
    output wire [1:0]   mon_we_o,
    output wire [2*ADDR_WIDTH-1:0] mon_adr_o,
    output wire [7:0]   mon_sel_o,
    output wire [63:0]  mon_wdat_o,
    output wire [63:0]  mon_rdat_o,
    output wire [1:0]   mon_ack_o,
    // board events: core c stored to EVENT this clock (ev_data_o, ev_arg_o)
    output wire [1:0]   ev_valid_o,
    output wire [63:0]  ev_data_o,
    output wire [63:0]  ev_arg_o
);

    // Each core's port of the shared RAM.
    wire [1:0]            wb_cyc, wb_stb, wb_we, wb_ack;
    wire [2*ADDR_WIDTH-1:0] wb_adr;
    wire [7:0]            wb_sel;
    wire [63:0]           wb_wdat, wb_rdat;

    albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH)) u_dpram (
        .clk_i  (clk_i),
        .rst_i  (rst_i),
        .a_cyc_i(wb_cyc[0]), .a_stb_i(wb_stb[0]), .a_we_i(wb_we[0]),
        .a_adr_i(wb_adr[0 +: ADDR_WIDTH]), .a_sel_i(wb_sel[0 +: 4]),
        .a_dat_i(wb_wdat[0 +: 32]), .a_dat_o(wb_rdat[0 +: 32]), .a_ack_o(wb_ack[0]),
        .b_cyc_i(wb_cyc[1]), .b_stb_i(wb_stb[1]), .b_we_i(wb_we[1]),
        .b_adr_i(wb_adr[ADDR_WIDTH +: ADDR_WIDTH]), .b_sel_i(wb_sel[4 +: 4]),
        .b_dat_i(wb_wdat[32 +: 32]), .b_dat_o(wb_rdat[32 +: 32]), .b_ack_o(wb_ack[1])
    );

    assign mon_we_o   = wb_we;
    assign mon_adr_o  = wb_adr;
    assign mon_sel_o  = wb_sel;
    assign mon_wdat_o = wb_wdat;
    assign mon_rdat_o = wb_rdat;
    assign mon_ack_o  = wb_ack;

    genvar c;
    generate
        for (c = 0; c < 2; c = c + 1) begin : g_core
            board_core #(.SERV((SERV_MASK >> c) & 1), .VEX((VEX_MASK >> c) & 1), .CACHED_ALIAS(CACHED_ALIAS),
                         .CORE(c), .ADDR_WIDTH(ADDR_WIDTH), .RAM_WORDS(RAM_WORDS)) u_core (
                .clk_i    (clk_i),
                .rst_i    (rst_i),
                .stall_i  (stall_i[c]),
                .wb_cyc_o (wb_cyc[c]),
                .wb_stb_o (wb_stb[c]),
                .wb_we_o  (wb_we[c]),
                .wb_adr_o (wb_adr[c*ADDR_WIDTH +: ADDR_WIDTH]),
                .wb_sel_o (wb_sel[c*4 +: 4]),
                .wb_dat_o (wb_wdat[c*32 +: 32]),
                .wb_dat_i (wb_rdat[c*32 +: 32]),
                .wb_ack_i (wb_ack[c]),
                .done_o   (done_o[c]),
                .code_o   (code_o[c*32 +: 32]),
                .stat_o   (stat_o[c*128 +: 128]),
                .ev_valid_o(ev_valid_o[c]),
                .ev_data_o(ev_data_o[c*32 +: 32]),
                .ev_arg_o (ev_arg_o[c*32 +: 32]),
                .trap_o   (trap_o[c]),
                .bus_err_o(bus_err_o[c])
            );
        end
    endgenerate

endmodule

`default_nettype wire
