// tb_equiv -- two albatross_controller models side by side on the same inputs,
// for tools/ctrl_equiv.sh: this tree's (albatross_controller) and a reference
// revision's (every controller module renamed ref_albatross_*).
// Rules:
//   * Both get the same clock, reset, read data, ack and err; equiv_main.cpp
//     drives them and compares every output in every clock (a difference in
//     any clock is a failure: the two must be cycle-equivalent).
//   * The configuration is the robot's (soc/albatross_system.v as the system
//     tests build it): NB 4, ADDR_WIDTH 10, N_CHAN 16, ROM_WORDS 1024,
//     TIMEOUT 8, POLL 16; the ROM comes from +rom=FILE (both read it).
//   * HAS (a parameter, default 1) sets the four HAS_* parameters of both:
//     1 the full configuration, 0 the core one.
`default_nettype none

module tb_equiv #(
    parameter HAS = 1  // HAS_STATUS, HAS_SYNC, HAS_ROM_RECHECK and HAS_ENTRY_CHECK of both controllers
) (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire [31:0] m_dat_i,
    input  wire        m_ack_i,
    input  wire        m_err_i,
    // this tree's controller
    output wire        n_cyc_o,
    output wire        n_stb_o,
    output wire        n_we_o,
    output wire [13:0] n_adr_o,
    output wire [3:0]  n_sel_o,
    output wire [31:0] n_dat_o,
    output wire [31:0] n_time_o,
    output wire        n_error_o,
    output wire [15:0] n_rerr_o,
    // the reference's
    output wire        r_cyc_o,
    output wire        r_stb_o,
    output wire        r_we_o,
    output wire [13:0] r_adr_o,
    output wire [3:0]  r_sel_o,
    output wire [31:0] r_dat_o,
    output wire [31:0] r_time_o,
    output wire        r_error_o,
    output wire [15:0] r_rerr_o
);
    albatross_controller #(.NB(4), .ADDR_WIDTH(10), .N_CHAN(16), .ROM_WORDS(1024), .ROM_FILE(""),
                           .TIMEOUT(8), .POLL(16), .HAS_STATUS(HAS), .HAS_SYNC(HAS), .HAS_ROM_RECHECK(HAS),
                           .HAS_ENTRY_CHECK(HAS)) u_new (
        .clk_i(clk_i), .rst_i(rst_i), .m_cyc_o(n_cyc_o), .m_stb_o(n_stb_o), .m_we_o(n_we_o), .m_adr_o(n_adr_o),
        .m_sel_o(n_sel_o), .m_dat_o(n_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i), .m_err_i(m_err_i),
        .time_o(n_time_o), .error_o(n_error_o), .rom_errors_o(n_rerr_o));
    ref_albatross_controller #(.NB(4), .ADDR_WIDTH(10), .N_CHAN(16), .ROM_WORDS(1024), .ROM_FILE(""),
                               .TIMEOUT(8), .POLL(16), .HAS_STATUS(HAS), .HAS_SYNC(HAS), .HAS_ROM_RECHECK(HAS),
                               .HAS_ENTRY_CHECK(HAS)) u_ref (
        .clk_i(clk_i), .rst_i(rst_i), .m_cyc_o(r_cyc_o), .m_stb_o(r_stb_o), .m_we_o(r_we_o), .m_adr_o(r_adr_o),
        .m_sel_o(r_sel_o), .m_dat_o(r_dat_o), .m_dat_i(m_dat_i), .m_ack_i(m_ack_i), .m_err_i(m_err_i),
        .time_o(r_time_o), .error_o(r_error_o), .rom_errors_o(r_rerr_o));
endmodule

`default_nettype wire
