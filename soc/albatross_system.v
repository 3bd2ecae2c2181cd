// albatross_system -- the one ALBATROSS multi-board system: NB boards, each an
// albatross_dpram whose port A is used by the board's processor and whose
// port B hangs on albatross_bus, the bus mastered by albatross_controller
// running the schedule ROM.  The FPGA demonstration (fpga/duo_system.v), the
// robot simulation (sim/pico_boards.v) and the system test
// (tb/system/tb_system.v) all instantiate this module; none wires the system
// by hand.
//
// Boards.  Board c's processor is chosen by two masks:
//   * EXT_MASK bit c set: no processor here.  Port A of board c's DPRAM is
//     the Wishbone port ext_*[c], for a master outside the module (the
//     simulated CPUs of tb/system, driven from C++).  It runs on clk_i with
//     no bridge: albatross_dpram's timing (an ack 1 or 2 clocks after the
//     request; port A served in every other clock).
//   * otherwise a soft core, board_core: VexRiscv where VEX_MASK bit c is
//     set (soc/vexriscv_core.v, instruction and data caches; it sees the
//     DPRAM window and the registers uncached at 0x9000_0000 / 0xA000_0000),
//     SERV where SERV_MASK bit c is set
//     (soc/serv_core.v), else PicoRV32 (soc/pico_core.v; SMALL 1 drops its
//     counters and traps).  Its memory map is soc/board_memmap.v and
//     soc/firmware/board.h: local RAM of RAM_WORDS words at 0, DPRAM window
//     at 0x1000_0000, board registers (TOHOST, STAT 0..3, EVENT, ARG) at
//     0x2000_0000.  stall_i[c] holds its local-RAM accesses (instruction
//     fetches included) for a clock; its DPRAM accesses are never held.
// A board's status outputs (done_o .. map_err_o) are 0 for an external board.
//
// Clocks.  With CPU_CDC 0 everything runs on clk_i, reset by rst_i
// (synchronous, active high); cpu_clk_i and cpu_rst_i are unused.  With
// CPU_CDC 1 the cores run on cpu_clk_i (reset cpu_rst_i) and each reaches its
// DPRAM's port A through albatross_wb_cdc, while the DPRAMs, the bus, the
// controller and the external ports stay on clk_i.  The two clocks may be
// unrelated; rst_i and cpu_rst_i must follow albatross_wb_cdc's reset rule
// (fpga/duo_system.v shows one way).  A core's DPRAM access then takes up to
// 6 CPU + 7 RAM clocks instead of 1 or 2 clocks (SYNC_STAGES 2).  The board
// status outputs are synchronous to the cores' clock, everything else to
// clk_i.
//
// The controller's bus (the fault-injection hook).  BUS_HOOK 0: the
// controller's master port drives the bus inside the module; the ctl_*_i and
// bus_*_i inputs are ignored (tie them to 0).  BUS_HOOK 1: the module does not
// close that loop: the controller's master port is ctl_* and the bus's master
// side is bus_*, and the parent connects the two, directly or through a test
// fixture such as tb/common/bus_fault_injector.v.  Either way ctl_*_o show the
// controller's requests; with BUS_HOOK 1 ctl_*_i are the answers it sees.
// Bus address: {board[3:0], word}.  The bus's slave err inputs are tied low
// (albatross_dpram never answers err).
//
// Observation (for harnesses; unused outputs cost no logic after synthesis):
//   * mon_a_*[c]: board c's port A as its DPRAM performs it: mon_a_ack_o is
//     high in the clock of an acked access (cyc & stb & ack), and
//     mon_a_we/adr/sel_o then describe it.
//   * mon_b_*[c]: board c's port B, wired straight through: mon_b_ack_o is
//     high in the clock after the RAM performed a port-B access; in that
//     clock mon_b_we/adr/sel/wdat_o still carry the request and mon_b_rdat_o
//     the read data.
//   * ctl_time_o, ctl_error_o, ctl_rom_errors_o: the controller's status.
//
// Images.  <RAM_PREFIX><c>.hex is board c's DPRAM image (the compiler's
// <board>_ram.hex), <FW_PREFIX><c>.hex core c's program, ROM_FILE the
// schedule ROM (the compiler's rom.hex); all become block-RAM contents ("":
// none; in simulation +fw<c>=FILE and +rom=FILE are read by board_memmap and
// the controller instead).  NB is at most 10 with image prefixes (one digit).
//
// Vectors: board c uses bits [c*w +: w] of every flattened w-bit field.
`default_nettype none

module albatross_system #(
    parameter NB         = 2,     // boards, 1..16 (at most 4 cores: +fw0..3 plusargs)
    parameter ADDR_WIDTH = 8,     // word-address bits of each DPRAM (8: 1 KiB)
    parameter RAM_WORDS  = 512,   // words of each core's local program RAM
    parameter N_CHAN     = 4,     // controller channel ids (the description's n_chan)
    parameter ROM_WORDS  = 256,   // schedule ROM depth in words
    parameter ROM_FILE   = "",    // schedule ROM image ("": +rom=FILE in simulation)
    parameter FW_PREFIX  = "",    // core c's program: <FW_PREFIX><c>.hex ("": +fw<c>=FILE in simulation)
    parameter RAM_PREFIX = "",    // board c's DPRAM image: <RAM_PREFIX><c>.hex ("": none)
    parameter TIMEOUT    = 8,     // controller access timeout, clocks
    parameter POLL       = 16,    // controller poll interval in sync mode, clocks
    parameter CTRL_HAS_STATUS = 1, // controller HAS_STATUS: 0 for a schedule with no STATUS entry (STATUS sends zeros)
    parameter CTRL_HAS_SYNC   = 1, // controller HAS_SYNC: 0 for a time-rigid schedule (no poll requester)
    parameter CTRL_HAS_MODES  = 1, // controller HAS_MODES: 0 for a schedule without modes (no mode switch)
    parameter CTRL_HAS_FRAGMENTS = 1, // controller HAS_FRAGMENTS: 0 for a schedule whose values go whole (no progress RAM)
    parameter CTRL_HAS_MULTIRATE = 1, // controller HAS_MULTIRATE: 0 for a single-rate schedule (no minor-cycle count)
    parameter EXT_MASK   = 0,     // NB bits: board c's port A is ext_*[c] when bit c is set, else a core
    parameter SERV_MASK  = 0,     // NB bits: core c is SERV when bit c is set, else PicoRV32
    parameter VEX_MASK   = 0,     // NB bits: core c is VexRiscv (caches; soc/vexriscv_core.v) when bit c is set
    parameter SMALL      = 0,     // PicoRV32 cores: 1 drops the counters and the misalign/illegal traps
    parameter CPU_CDC    = 0,     // 1: the cores on cpu_clk_i, through albatross_wb_cdc; 0: all on clk_i
    parameter BUS_HOOK   = 0      // 1: the parent connects ctl_* to bus_*; 0: connected inside
) (
    input  wire                     clk_i,        // DPRAMs, bus, controller, ext ports (CPU_CDC 0: all)
    input  wire                     rst_i,        // synchronous to clk_i, active high
    input  wire                     cpu_clk_i,    // the cores' clock (CPU_CDC 1 only)
    input  wire                     cpu_rst_i,    // synchronous to cpu_clk_i, active high (CPU_CDC 1 only)
    input  wire [NB-1:0]            stall_i,      // core c: hold its local-RAM access this clock
    // external masters: port A of each board in EXT_MASK (Wishbone B4 classic slave, clk_i)
    input  wire [NB-1:0]            ext_cyc_i,    // cycle
    input  wire [NB-1:0]            ext_stb_i,    // strobe
    input  wire [NB-1:0]            ext_we_i,     // write enable
    input  wire [NB*ADDR_WIDTH-1:0] ext_adr_i,    // word address
    input  wire [NB*4-1:0]          ext_sel_i,    // byte lanes
    input  wire [NB*32-1:0]         ext_dat_i,    // write data
    output wire [NB*32-1:0]         ext_dat_o,    // read data (0 for a core's board)
    output wire [NB-1:0]            ext_ack_o,    // acknowledge (0 for a core's board)
    // the controller's master port (Wishbone B4 classic master)
    output wire                     ctl_cyc_o,    // cycle
    output wire                     ctl_stb_o,    // strobe
    output wire                     ctl_we_o,     // write enable
    output wire [ADDR_WIDTH+3:0]    ctl_adr_o,    // {board[3:0], word}
    output wire [3:0]               ctl_sel_o,    // byte lanes
    output wire [31:0]              ctl_dat_o,    // write data
    input  wire [31:0]              ctl_dat_i,    // read data (BUS_HOOK 1 only)
    input  wire                     ctl_ack_i,    // acknowledge (BUS_HOOK 1 only)
    input  wire                     ctl_err_i,    // error (BUS_HOOK 1 only)
    // the bus's master side (Wishbone B4 classic slave; inputs BUS_HOOK 1 only)
    input  wire                     bus_cyc_i,    // cycle
    input  wire                     bus_stb_i,    // strobe
    input  wire                     bus_we_i,     // write enable
    input  wire [ADDR_WIDTH+3:0]    bus_adr_i,    // {board[3:0], word}
    input  wire [3:0]               bus_sel_i,    // byte lanes
    input  wire [31:0]              bus_dat_i,    // write data
    output wire [31:0]              bus_dat_o,    // read data
    output wire                     bus_ack_o,    // acknowledge
    output wire                     bus_err_o,    // error (an address beyond NB boards)
    // board status (cores' clock; 0 for an external board)
    output wire [NB-1:0]            done_o,       // core c stored to TOHOST (its program ended)
    output wire [NB*32-1:0]         code_o,       // the last value it stored there (exit code)
    output wire [NB*128-1:0]        stat_o,       // core c's STAT k at [c*128 + k*32 +: 32]
    output wire [NB-1:0]            ev_valid_o,   // core c stored to EVENT (one clock)
    output wire [NB*32-1:0]         ev_data_o,    // that value
    output wire [NB*32-1:0]         ev_arg_o,     // ARG at that time
    output wire [NB-1:0]            trap_o,       // core c trapped (PicoRV32; SERV, VexRiscv: 0)
    output wire [NB-1:0]            map_err_o,    // core c accessed an unmapped address
    // port A of each DPRAM as performed (clk_i)
    output wire [NB-1:0]            mon_a_ack_o,  // an access acked this clock
    output wire [NB-1:0]            mon_a_we_o,   // ... a write
    output wire [NB*ADDR_WIDTH-1:0] mon_a_adr_o,  // its word address
    output wire [NB*4-1:0]          mon_a_sel_o,  // its byte lanes
    // port B of each DPRAM, straight through (clk_i)
    output wire [NB-1:0]            mon_b_ack_o,  // the RAM performed an access (previous clock)
    output wire [NB-1:0]            mon_b_we_o,   // ... a write
    output wire [NB*ADDR_WIDTH-1:0] mon_b_adr_o,  // its word address
    output wire [NB*4-1:0]          mon_b_sel_o,  // its byte lanes
    output wire [NB*32-1:0]         mon_b_wdat_o, // its write data
    output wire [NB*32-1:0]         mon_b_rdat_o, // the read data
    // controller status (clk_i)
    output wire [31:0]              ctl_time_o,       // global time
    output wire                     ctl_error_o,      // invalid ROM header: the bus is never used
    output wire [15:0]              ctl_rom_errors_o  // invalid entries skipped (counter)
);

    localparam BA = 4 + ADDR_WIDTH;  // bus address {board[3:0], word}

    // The cores' clock and reset (a constant choice, no clock multiplexer).
    wire core_clk = (CPU_CDC != 0) ? cpu_clk_i : clk_i;
    wire core_rst = (CPU_CDC != 0) ? cpu_rst_i : rst_i;
    wire unused_core_clk = &{1'b0, core_clk, core_rst};  // unused when every board is external

    // ---- controller, bus, and the loop between them -----------------------
    wire          m_ack, m_err;          // the controller's answer
    wire [31:0]   m_rdat;
    wire          b_cyc, b_stb, b_we;    // the bus's request
    wire [BA-1:0] b_adr;
    wire [3:0]    b_sel;
    wire [31:0]   b_wdat;
    wire [NB-1:0]            s_cyc, s_stb, s_we, s_ack;  // bus <-> port B of each RAM
    wire [NB*ADDR_WIDTH-1:0] s_adr;
    wire [NB*4-1:0]          s_sel;
    wire [NB*32-1:0]         s_wdat, s_rdat;

    albatross_controller #(
        .NB(NB), .ADDR_WIDTH(ADDR_WIDTH), .N_CHAN(N_CHAN), .ROM_WORDS(ROM_WORDS),
        .ROM_FILE(ROM_FILE), .TIMEOUT(TIMEOUT), .POLL(POLL),
        .HAS_STATUS(CTRL_HAS_STATUS), .HAS_SYNC(CTRL_HAS_SYNC), .HAS_MODES(CTRL_HAS_MODES),
        .HAS_FRAGMENTS(CTRL_HAS_FRAGMENTS), .HAS_MULTIRATE(CTRL_HAS_MULTIRATE)
    ) u_ctrl (
        .clk_i(clk_i), .rst_i(rst_i),
        .m_cyc_o(ctl_cyc_o), .m_stb_o(ctl_stb_o), .m_we_o(ctl_we_o), .m_adr_o(ctl_adr_o),
        .m_sel_o(ctl_sel_o), .m_dat_o(ctl_dat_o), .m_dat_i(m_rdat), .m_ack_i(m_ack), .m_err_i(m_err),
        .time_o(ctl_time_o), .error_o(ctl_error_o), .rom_errors_o(ctl_rom_errors_o)
    );

    generate
        if (BUS_HOOK != 0) begin : g_hook
            assign {b_cyc, b_stb, b_we, b_adr, b_sel, b_wdat} =
                   {bus_cyc_i, bus_stb_i, bus_we_i, bus_adr_i, bus_sel_i, bus_dat_i};
            assign {m_rdat, m_ack, m_err} = {ctl_dat_i, ctl_ack_i, ctl_err_i};
        end else begin : g_loop
            assign {b_cyc, b_stb, b_we, b_adr, b_sel, b_wdat} =
                   {ctl_cyc_o, ctl_stb_o, ctl_we_o, ctl_adr_o, ctl_sel_o, ctl_dat_o};
            assign {m_rdat, m_ack, m_err} = {bus_dat_o, bus_ack_o, bus_err_o};
            wire unused_hook = &{1'b0, ctl_dat_i, ctl_ack_i, ctl_err_i, bus_cyc_i, bus_stb_i,
                                 bus_we_i, bus_adr_i, bus_sel_i, bus_dat_i};
        end
    endgenerate

    albatross_bus #(.NB(NB), .ADDR_WIDTH(ADDR_WIDTH)) u_bus (
        .clk_i(clk_i), .m_cyc_i(b_cyc), .m_stb_i(b_stb), .m_we_i(b_we), .m_adr_i(b_adr), .m_sel_i(b_sel),
        .m_dat_i(b_wdat), .m_dat_o(bus_dat_o), .m_ack_o(bus_ack_o), .m_err_o(bus_err_o),
        .s_cyc_o(s_cyc), .s_stb_o(s_stb), .s_we_o(s_we), .s_adr_o(s_adr), .s_sel_o(s_sel),
        .s_dat_o(s_wdat), .s_dat_i(s_rdat), .s_ack_i(s_ack), .s_err_i({NB{1'b0}})
    );

    assign mon_b_ack_o  = s_ack;
    assign mon_b_we_o   = s_we;
    assign mon_b_adr_o  = s_adr;
    assign mon_b_sel_o  = s_sel;
    assign mon_b_wdat_o = s_wdat;
    assign mon_b_rdat_o = s_rdat;

    // ---- the boards --------------------------------------------------------
    genvar c;
    generate
        for (c = 0; c < NB; c = c + 1) begin : g_board
            // "" (a zero) stays a zero at any width: no image.
            localparam FW_FILE  = (FW_PREFIX == "") ? "" : {FW_PREFIX, 8'd48 + c[7:0], ".hex"};
            localparam RAM_FILE = (RAM_PREFIX == "") ? "" : {RAM_PREFIX, 8'd48 + c[7:0], ".hex"};
            // Port A of the RAM.
            wire                  a_cyc, a_stb, a_we, a_ack;
            wire [ADDR_WIDTH-1:0] a_adr;
            wire [3:0]            a_sel;
            wire [31:0]           a_wdat, a_rdat;

            albatross_dpram #(.ADDR_WIDTH(ADDR_WIDTH), .INIT_FILE(RAM_FILE)) u_ram (
                .clk_i(clk_i), .rst_i(rst_i),
                .a_cyc_i(a_cyc), .a_stb_i(a_stb), .a_we_i(a_we), .a_adr_i(a_adr),
                .a_sel_i(a_sel), .a_dat_i(a_wdat), .a_dat_o(a_rdat), .a_ack_o(a_ack),
                .b_cyc_i(s_cyc[c]), .b_stb_i(s_stb[c]), .b_we_i(s_we[c]),
                .b_adr_i(s_adr[c*ADDR_WIDTH +: ADDR_WIDTH]), .b_sel_i(s_sel[c*4 +: 4]),
                .b_dat_i(s_wdat[c*32 +: 32]), .b_dat_o(s_rdat[c*32 +: 32]), .b_ack_o(s_ack[c])
            );
            assign mon_a_ack_o[c]                          = a_cyc & a_stb & a_ack;
            assign mon_a_we_o[c]                           = a_we;
            assign mon_a_adr_o[c*ADDR_WIDTH +: ADDR_WIDTH] = a_adr;
            assign mon_a_sel_o[c*4 +: 4]                   = a_sel;

            if (((EXT_MASK >> c) & 1) != 0) begin : g_ext
                // An external master on port A, on clk_i.
                assign a_cyc  = ext_cyc_i[c];
                assign a_stb  = ext_stb_i[c];
                assign a_we   = ext_we_i[c];
                assign a_adr  = ext_adr_i[c*ADDR_WIDTH +: ADDR_WIDTH];
                assign a_sel  = ext_sel_i[c*4 +: 4];
                assign a_wdat = ext_dat_i[c*32 +: 32];
                assign ext_dat_o[c*32 +: 32] = a_rdat;
                assign ext_ack_o[c]          = a_ack;
                assign {done_o[c], trap_o[c], map_err_o[c], ev_valid_o[c]} = 4'd0;
                assign code_o[c*32 +: 32]    = 32'd0;
                assign stat_o[c*128 +: 128]  = 128'd0;
                assign ev_data_o[c*32 +: 32] = 32'd0;
                assign ev_arg_o[c*32 +: 32]  = 32'd0;
                wire unused_core = &{1'b0, stall_i[c]};
            end else begin : g_core
                // The core's bus (c_*): port A itself with CPU_CDC 0, the
                // other side of a bridge with CPU_CDC 1.
                wire                  c_cyc, c_stb, c_we, c_ack;
                wire [ADDR_WIDTH-1:0] c_adr;
                wire [3:0]            c_sel;
                wire [31:0]           c_wdat, c_rdat;
                wire unused_ext = &{1'b0, ext_cyc_i[c], ext_stb_i[c], ext_we_i[c],
                                    ext_adr_i[c*ADDR_WIDTH +: ADDR_WIDTH], ext_sel_i[c*4 +: 4],
                                    ext_dat_i[c*32 +: 32]};
                assign ext_dat_o[c*32 +: 32] = 32'd0;
                assign ext_ack_o[c]          = 1'b0;

                if (CPU_CDC != 0) begin : g_cdc
                    albatross_wb_cdc #(.ADDR_WIDTH(ADDR_WIDTH)) u_cdc (
                        .s_clk_i(cpu_clk_i), .s_rst_i(cpu_rst_i), .m_clk_i(clk_i), .m_rst_i(rst_i),
                        .s_cyc_i(c_cyc), .s_stb_i(c_stb), .s_we_i(c_we), .s_adr_i(c_adr), .s_sel_i(c_sel),
                        .s_dat_i(c_wdat), .s_dat_o(c_rdat), .s_ack_o(c_ack),
                        .m_cyc_o(a_cyc), .m_stb_o(a_stb), .m_we_o(a_we), .m_adr_o(a_adr), .m_sel_o(a_sel),
                        .m_dat_o(a_wdat), .m_dat_i(a_rdat), .m_ack_i(a_ack)
                    );
                end else begin : g_direct
                    assign {a_cyc, a_stb, a_we, a_adr, a_sel, a_wdat} = {c_cyc, c_stb, c_we, c_adr, c_sel, c_wdat};
                    assign {c_rdat, c_ack} = {a_rdat, a_ack};
                end

                board_core #(.SERV((SERV_MASK >> c) & 1), .VEX((VEX_MASK >> c) & 1), .CORE(c), .ADDR_WIDTH(ADDR_WIDTH),
                             .RAM_WORDS(RAM_WORDS), .FW_FILE(FW_FILE), .SMALL(SMALL)) u_core (
                    .clk_i     (core_clk),
                    .rst_i     (core_rst),
                    .stall_i   (stall_i[c]),
                    .wb_cyc_o  (c_cyc),
                    .wb_stb_o  (c_stb),
                    .wb_we_o   (c_we),
                    .wb_adr_o  (c_adr),
                    .wb_sel_o  (c_sel),
                    .wb_dat_o  (c_wdat),
                    .wb_dat_i  (c_rdat),
                    .wb_ack_i  (c_ack),
                    .done_o    (done_o[c]),
                    .code_o    (code_o[c*32 +: 32]),
                    .stat_o    (stat_o[c*128 +: 128]),
                    .ev_valid_o(ev_valid_o[c]),
                    .ev_data_o (ev_data_o[c*32 +: 32]),
                    .ev_arg_o  (ev_arg_o[c*32 +: 32]),
                    .trap_o    (trap_o[c]),
                    .bus_err_o (map_err_o[c])
                );
            end
        end
    endgenerate

endmodule

`default_nettype wire
