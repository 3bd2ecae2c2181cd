// tb_dpram_async -- test top: albatross_dpram with two independent CPU clocks.
//
// One albatross_dpram on the RAM clock and one albatross_wb_cdc on each of its
// ports, so CPU A and CPU B each reach the RAM from their own clock.  All three
// clocks are inputs: the C++ harness (tb/cdc/test_cdc.cpp) generates them.
// The CPU-side Wishbone ports are exposed; the RAM-side bus of each bridge is
// exposed read-only (mon_*) so the harness can follow every RAM access.
`default_nettype none

module tb_dpram_async #(
    parameter ADDR_WIDTH  = 8,  // word-address bits of the RAM and both bridges
    parameter SYNC_STAGES = 2   // flops per toggle synchroniser in both bridges
) (
    input  wire                  ram_clk_i,
    input  wire                  ram_rst_i,
    input  wire                  a_clk_i,
    input  wire                  a_rst_i,
    input  wire                  b_clk_i,
    input  wire                  b_rst_i,
    // CPU A: Wishbone B4 classic, on a_clk_i
    input  wire                  a_cyc_i,
    input  wire                  a_stb_i,
    input  wire                  a_we_i,
    input  wire [ADDR_WIDTH-1:0] a_adr_i,
    input  wire [3:0]            a_sel_i,
    input  wire [31:0]           a_dat_i,
    output wire [31:0]           a_dat_o,
    output wire                  a_ack_o,
    // CPU B: Wishbone B4 classic, on b_clk_i
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i,
    output wire [31:0]           b_dat_o,
    output wire                  b_ack_o,
    // RAM-side bus of bridge A (RAM port A), for monitoring, on ram_clk_i
    output wire                  mon_a_cyc_o,
    output wire                  mon_a_stb_o,
    output wire                  mon_a_we_o,
    output wire [ADDR_WIDTH-1:0] mon_a_adr_o,
    output wire [3:0]            mon_a_sel_o,
    output wire [31:0]           mon_a_wdat_o,
    output wire [31:0]           mon_a_rdat_o,
    output wire                  mon_a_ack_o,
    // RAM-side bus of bridge B (RAM port B), for monitoring, on ram_clk_i
    output wire                  mon_b_cyc_o,
    output wire                  mon_b_stb_o,
    output wire                  mon_b_we_o,
    output wire [ADDR_WIDTH-1:0] mon_b_adr_o,
    output wire [3:0]            mon_b_sel_o,
    output wire [31:0]           mon_b_wdat_o,
    output wire [31:0]           mon_b_rdat_o,
    output wire                  mon_b_ack_o
);

    albatross_wb_cdc #(
        .ADDR_WIDTH  (ADDR_WIDTH),
        .SYNC_STAGES (SYNC_STAGES)
    ) u_cdc_a (
        .s_clk_i (a_clk_i),
        .s_rst_i (a_rst_i),
        .m_clk_i (ram_clk_i),
        .m_rst_i (ram_rst_i),
        .s_cyc_i (a_cyc_i),
        .s_stb_i (a_stb_i),
        .s_we_i  (a_we_i),
        .s_adr_i (a_adr_i),
        .s_sel_i (a_sel_i),
        .s_dat_i (a_dat_i),
        .s_dat_o (a_dat_o),
        .s_ack_o (a_ack_o),
        .m_cyc_o (mon_a_cyc_o),
        .m_stb_o (mon_a_stb_o),
        .m_we_o  (mon_a_we_o),
        .m_adr_o (mon_a_adr_o),
        .m_sel_o (mon_a_sel_o),
        .m_dat_o (mon_a_wdat_o),
        .m_dat_i (mon_a_rdat_o),
        .m_ack_i (mon_a_ack_o)
    );

    albatross_wb_cdc #(
        .ADDR_WIDTH  (ADDR_WIDTH),
        .SYNC_STAGES (SYNC_STAGES)
    ) u_cdc_b (
        .s_clk_i (b_clk_i),
        .s_rst_i (b_rst_i),
        .m_clk_i (ram_clk_i),
        .m_rst_i (ram_rst_i),
        .s_cyc_i (b_cyc_i),
        .s_stb_i (b_stb_i),
        .s_we_i  (b_we_i),
        .s_adr_i (b_adr_i),
        .s_sel_i (b_sel_i),
        .s_dat_i (b_dat_i),
        .s_dat_o (b_dat_o),
        .s_ack_o (b_ack_o),
        .m_cyc_o (mon_b_cyc_o),
        .m_stb_o (mon_b_stb_o),
        .m_we_o  (mon_b_we_o),
        .m_adr_o (mon_b_adr_o),
        .m_sel_o (mon_b_sel_o),
        .m_dat_o (mon_b_wdat_o),
        .m_dat_i (mon_b_rdat_o),
        .m_ack_i (mon_b_ack_o)
    );

    albatross_dpram #(
        .ADDR_WIDTH (ADDR_WIDTH)
    ) u_dpram (
        .clk_i   (ram_clk_i),
        .rst_i   (ram_rst_i),
        .a_cyc_i (mon_a_cyc_o),
        .a_stb_i (mon_a_stb_o),
        .a_we_i  (mon_a_we_o),
        .a_adr_i (mon_a_adr_o),
        .a_sel_i (mon_a_sel_o),
        .a_dat_i (mon_a_wdat_o),
        .a_dat_o (mon_a_rdat_o),
        .a_ack_o (mon_a_ack_o),
        .b_cyc_i (mon_b_cyc_o),
        .b_stb_i (mon_b_stb_o),
        .b_we_i  (mon_b_we_o),
        .b_adr_i (mon_b_adr_o),
        .b_sel_i (mon_b_sel_o),
        .b_dat_i (mon_b_wdat_o),
        .b_dat_o (mon_b_rdat_o),
        .b_ack_o (mon_b_ack_o)
    );

endmodule

`default_nettype wire
