// board_memmap -- board part: the memory map of one board (simulated or FPGA) behind
// a PicoRV32-style native memory port (valid/addr/wdata/wstrb in,
// ready/rdata out).  Shared by every core wrapper (pico_core, serv_core).
//
// Memory map (address bits 31:28 select the region; soc/firmware/board.h):
//   0x0xxx_xxxx  local RAM, RAM_WORDS words, performed at the edge after the
//                request (one-cycle access), loaded from FW_FILE (synthesis:
//                block-RAM contents); in simulation from +fw<CORE>=FILE when
//                that plusarg is given (it overrides FW_FILE)
//   0x1xxx_xxxx  DPRAM window: wb_* through a pico_wb_adapter
//   0x2xxx_xxxx  board registers, one-cycle access, reads give 0:
//                +0x00 TOHOST: a store sets done_o and code_o
//                +0x10..0x1c STAT 0..3 (stat_o)
//                +0x20 EVENT: a store pulses ev_valid_o for one clock with
//                      ev_data_o = the value, ev_arg_o = ARG
//                +0x24 ARG: the argument of the next EVENT
//                +0x40 TIMER (read-only): the board's local timer, a 32-bit
//                      count of ticks since reset, one per clock of clk_i;
//                      the value read is the count in the clock the access
//                      completes; reading it changes nothing, a store to it
//                      is ignored
//   other        bus_err_o is set (sticky); the access completes, reads 0
// stall_i holds the local-RAM access (instruction fetches included) while
// high: a harness varies the core's speed with it, as an interrupt or a slow
// memory would, or freezes the core for good (a crash).  DPRAM accesses are
// never held.  Reset (synchronous, active high) clears control state, never
// the RAM.
// Local timer: TIMER counts one tick per clock (timer_q, wrapping at 2^32);
// synthesis always counts every clock.  Simulation only: +drift<CORE>=PPM
// (a signed integer, |PPM| < 1000000) makes this board's clock run PPM parts
// per million fast (> 0) or slow (< 0) against the controller's: a
// fractional accumulator adds |PPM| each clock and, each time it passes
// 10^6, the timer counts 2 ticks in that clock (fast) or none (slow), so it
// runs at 1 + PPM/10^6 ticks per clock.  timer_read (a TIMER read completes
// in this clock) and timer_q are for a harness's hierarchical reference
// (sim/pico_boards.v).
`default_nettype none

module board_memmap #(
    parameter CORE       = 0,     // index: the firmware plusarg is +fw<CORE>=FILE (0..3)
    parameter ADDR_WIDTH = 10,    // word-address bits of the DPRAM port
    parameter RAM_WORDS  = 4096,  // words of the local RAM (16 KiB)
    parameter FW_FILE    = ""     // $readmemh program image at configuration (simulation: +fw<CORE>=FILE instead, when given)
) (
    input  wire                  clk_i,
    input  wire                  rst_i,     // synchronous, active high
    input  wire                  stall_i,   // hold the local-RAM access this cycle
    // native memory port (PicoRV32 mem_*)
    input  wire                  valid_i,
    input  wire [31:0]           addr_i,
    input  wire [31:0]           wdata_i,
    input  wire [3:0]            wstrb_i,   // 0: read
    output wire                  ready_o,
    output wire [31:0]           rdata_o,
    // Wishbone B4 classic master to a DPRAM port
    output wire                  wb_cyc_o,
    output wire                  wb_stb_o,
    output wire                  wb_we_o,
    output wire [ADDR_WIDTH-1:0] wb_adr_o,
    output wire [3:0]            wb_sel_o,
    output wire [31:0]           wb_dat_o,
    input  wire [31:0]           wb_dat_i,
    input  wire                  wb_ack_i,
    // board status
    output wire                  done_o,    // the core stored to TOHOST
    output wire [31:0]           code_o,    // the last value it stored (exit code)
    output wire [127:0]          stat_o,    // STAT k at [k*32 +: 32]
    output wire                  ev_valid_o,// a store to EVENT, this clock
    output wire [31:0]           ev_data_o, // its value
    output wire [31:0]           ev_arg_o,  // ARG at that time
    output wire                  bus_err_o  // an access to an unmapped address
);

    localparam RAM_BITS = $clog2(RAM_WORDS);  // word-address bits, local RAM

    // Address decode: bits 31:28 pick the region.
    wire sel_ram  = valid_i && addr_i[31:28] == 4'h0;
    wire sel_dp   = valid_i && addr_i[31:28] == 4'h1;
    wire sel_regs = valid_i && addr_i[31:28] == 4'h2;
    wire sel_none = valid_i && addr_i[31:28] >  4'h2;

    // Local RAM: performed at the edge after the request, ready then.
    reg [31:0] ram [0:RAM_WORDS-1];
    reg [31:0] ram_rdata_q;
    reg        ram_ready_q;
    wire [RAM_BITS-1:0] ram_idx = addr_i[RAM_BITS+1:2];
    // The program: FW_FILE; in simulation +fw<CORE>=FILE, when given, instead
    // (so one simulation model runs other programs).
`ifdef SYNTHESIS
    generate
        if (FW_FILE != "") begin : g_fw
            initial $readmemh(FW_FILE, ram);
        end
    endgenerate
`else  // simulation: Yosys has no $value$plusargs
    reg [8*256-1:0] fw_file;
    integer         have_fw;
    initial begin
        case (CORE)
            0:       have_fw = $value$plusargs("fw0=%s", fw_file);
            1:       have_fw = $value$plusargs("fw1=%s", fw_file);
            2:       have_fw = $value$plusargs("fw2=%s", fw_file);
            default: have_fw = $value$plusargs("fw3=%s", fw_file);
        endcase
        if (have_fw != 0) $readmemh(fw_file, ram);
        else if (FW_FILE != "") $readmemh(FW_FILE, ram);
        else $display("board_memmap: no +fw%0d=FILE given, core %0d has an empty RAM", CORE, CORE);
    end
`endif
    always @(posedge clk_i) begin
        ram_ready_q <= sel_ram & ~ram_ready_q & ~stall_i & ~rst_i;
        if (sel_ram & ~ram_ready_q & ~stall_i) begin
            ram_rdata_q <= ram[ram_idx];
            if (wstrb_i[0]) ram[ram_idx][7:0]   <= wdata_i[7:0];
            if (wstrb_i[1]) ram[ram_idx][15:8]  <= wdata_i[15:8];
            if (wstrb_i[2]) ram[ram_idx][23:16] <= wdata_i[23:16];
            if (wstrb_i[3]) ram[ram_idx][31:24] <= wdata_i[31:24];
        end
    end
    wire unused_addr = &{1'b0, addr_i[27:RAM_BITS+2]};

    // Board registers and unmapped addresses: one-cycle access.
    reg        regs_ready_q, done_q, err_q, ev_valid_q;
    reg [31:0] code_q, ev_data_q, ev_arg_q;
    reg [31:0] stat_q [0:3];
    wire       reg_wr = sel_regs & ~regs_ready_q & (|wstrb_i);
    always @(posedge clk_i) begin
        if (rst_i) begin
            regs_ready_q <= 1'b0;
            done_q       <= 1'b0;
            err_q        <= 1'b0;
            code_q       <= 32'd0;
            ev_valid_q   <= 1'b0;
            ev_data_q    <= 32'd0;
            ev_arg_q     <= 32'd0;
        end else begin
            regs_ready_q <= (sel_regs | sel_none) & ~regs_ready_q;
            ev_valid_q   <= reg_wr && addr_i[7:0] == 8'h20;
            if (sel_none) err_q <= 1'b1;
            if (reg_wr && addr_i[7:0] == 8'h00) begin
                done_q <= 1'b1;
                code_q <= wdata_i;
            end
            if (reg_wr && addr_i[7:0] == 8'h20) ev_data_q <= wdata_i;
            if (reg_wr && addr_i[7:0] == 8'h24) ev_arg_q  <= wdata_i;
        end
    end
    // STAT is data, not control: never reset.
    always @(posedge clk_i)
        if (reg_wr && addr_i[7:4] == 4'h1) stat_q[addr_i[3:2]] <= wdata_i;

    // Local timer (TIMER, +0x40): one-cycle read like the other registers.
    reg  [31:0] timer_q;
    reg         timer_rd_q;  // the register access being answered reads TIMER
    wire [1:0]  timer_inc;   // ticks this clock: 1 (0 or 2 under simulated drift)
    always @(posedge clk_i) begin
        if (rst_i) begin
            timer_q    <= 32'd0;
            timer_rd_q <= 1'b0;
        end else begin
            timer_q    <= timer_q + {30'd0, timer_inc};
            timer_rd_q <= sel_regs & ~regs_ready_q & ~(|wstrb_i) && addr_i[7:0] == 8'h40;
        end
    end
    wire timer_read = regs_ready_q & timer_rd_q;  // harness probe: a TIMER read completes
`ifndef SYNTHESIS  // simulation only: the board clock's drift, +drift<CORE>=PPM
    integer drift_ppm, drift_acc, have_drift;
    reg     drift_step_q;  // this clock counts 2 ticks (PPM > 0) or none (PPM < 0)
    initial begin
        drift_ppm = 0;
        drift_acc = 0;
        drift_step_q = 1'b0;
        case (CORE)
            0:       have_drift = $value$plusargs("drift0=%d", drift_ppm);
            1:       have_drift = $value$plusargs("drift1=%d", drift_ppm);
            2:       have_drift = $value$plusargs("drift2=%d", drift_ppm);
            default: have_drift = $value$plusargs("drift3=%d", drift_ppm);
        endcase
        if (have_drift != 0 && (drift_ppm <= -1000000 || drift_ppm >= 1000000)) begin
            $display("board_memmap: +drift%0d=%0d out of range (|PPM| < 1000000): no drift", CORE, drift_ppm);
            drift_ppm = 0;
        end
    end
    always @(posedge clk_i) begin
        drift_step_q <= 1'b0;
        if (drift_acc + (drift_ppm < 0 ? -drift_ppm : drift_ppm) >= 1000000) begin
            drift_acc    <= drift_acc + (drift_ppm < 0 ? -drift_ppm : drift_ppm) - 1000000;
            drift_step_q <= 1'b1;
        end else begin
            drift_acc    <= drift_acc + (drift_ppm < 0 ? -drift_ppm : drift_ppm);
        end
    end
    assign timer_inc = drift_step_q ? (drift_ppm > 0 ? 2'd2 : 2'd0) : 2'd1;
`else
    assign timer_inc = 2'd1;
`endif

    // DPRAM window through the adapter.
    wire        dp_ready;
    wire [31:0] dp_rdata;
    pico_wb_adapter #(.ADDR_WIDTH(ADDR_WIDTH)) u_adapter (
        .valid_i (sel_dp),
        .addr_i  (addr_i[ADDR_WIDTH+1:0]),
        .wdata_i (wdata_i),
        .wstrb_i (wstrb_i),
        .ready_o (dp_ready),
        .rdata_o (dp_rdata),
        .wb_cyc_o(wb_cyc_o),
        .wb_stb_o(wb_stb_o),
        .wb_we_o (wb_we_o),
        .wb_adr_o(wb_adr_o),
        .wb_sel_o(wb_sel_o),
        .wb_dat_o(wb_dat_o),
        .wb_dat_i(wb_dat_i),
        .wb_ack_i(wb_ack_i)
    );

    assign ready_o    = ram_ready_q | regs_ready_q | dp_ready;
    assign rdata_o    = ram_ready_q ? ram_rdata_q : dp_ready ? dp_rdata : timer_read ? timer_q : 32'd0;

    assign done_o     = done_q;
    assign code_o     = code_q;
    assign stat_o     = {stat_q[3], stat_q[2], stat_q[1], stat_q[0]};
    assign ev_valid_o = ev_valid_q;
    assign ev_data_o  = ev_data_q;
    assign ev_arg_o   = ev_arg_q;
    assign bus_err_o  = err_q;

endmodule

`default_nettype wire
