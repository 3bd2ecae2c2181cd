// tb_axil -- cocotb top of albatross_dpram_axil (tb/axil/test_axil.py,
// tools/mk/axil.mk): the wrapper with its AXI4-Lite port under the plain
// s_axi_* names cocotbext-axi looks for, and port B's Wishbone signals.  No
// logic of its own; the clock and every stimulus come from Python.
`default_nettype none

module tb_axil #(
    parameter ADDR_WIDTH = 4   // word-address bits of the RAM under test (16 words)
) (
    input  wire                  clk,
    input  wire                  rst,
    input  wire                  s_axi_awvalid,
    output wire                  s_axi_awready,
    input  wire [ADDR_WIDTH+1:0] s_axi_awaddr,
    input  wire [2:0]            s_axi_awprot,
    input  wire                  s_axi_wvalid,
    output wire                  s_axi_wready,
    input  wire [31:0]           s_axi_wdata,
    input  wire [3:0]            s_axi_wstrb,
    output wire                  s_axi_bvalid,
    input  wire                  s_axi_bready,
    output wire [1:0]            s_axi_bresp,
    input  wire                  s_axi_arvalid,
    output wire                  s_axi_arready,
    input  wire [ADDR_WIDTH+1:0] s_axi_araddr,
    input  wire [2:0]            s_axi_arprot,
    output wire                  s_axi_rvalid,
    input  wire                  s_axi_rready,
    output wire [31:0]           s_axi_rdata,
    output wire [1:0]            s_axi_rresp,
    input  wire                  b_cyc,
    input  wire                  b_stb,
    input  wire                  b_we,
    input  wire [ADDR_WIDTH-1:0] b_adr,
    input  wire [3:0]            b_sel,
    input  wire [31:0]           b_dat_w,
    output wire [31:0]           b_dat_r,
    output wire                  b_ack
);

    albatross_dpram_axil #(.ADDR_WIDTH(ADDR_WIDTH)) dut (
        .clk_i(clk), .rst_i(rst),
        .s_axi_awvalid_i(s_axi_awvalid), .s_axi_awready_o(s_axi_awready), .s_axi_awaddr_i(s_axi_awaddr),
        .s_axi_awprot_i(s_axi_awprot), .s_axi_wvalid_i(s_axi_wvalid), .s_axi_wready_o(s_axi_wready),
        .s_axi_wdata_i(s_axi_wdata), .s_axi_wstrb_i(s_axi_wstrb), .s_axi_bvalid_o(s_axi_bvalid),
        .s_axi_bready_i(s_axi_bready), .s_axi_bresp_o(s_axi_bresp), .s_axi_arvalid_i(s_axi_arvalid),
        .s_axi_arready_o(s_axi_arready), .s_axi_araddr_i(s_axi_araddr), .s_axi_arprot_i(s_axi_arprot),
        .s_axi_rvalid_o(s_axi_rvalid), .s_axi_rready_i(s_axi_rready), .s_axi_rdata_o(s_axi_rdata),
        .s_axi_rresp_o(s_axi_rresp),
        .b_cyc_i(b_cyc), .b_stb_i(b_stb), .b_we_i(b_we), .b_adr_i(b_adr), .b_sel_i(b_sel),
        .b_dat_i(b_dat_w), .b_dat_o(b_dat_r), .b_ack_o(b_ack)
    );

endmodule

`default_nettype wire
