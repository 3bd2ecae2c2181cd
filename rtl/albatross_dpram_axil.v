// albatross_dpram_axil -- byte-arbitrated dual-ported RAM, AXI4-Lite slave on
// port A, Wishbone B4 classic slave on port B (ALBATROSS, the paper, section 3.1; docs/rtl.md
// "albatross_dpram_axil", "Vivado / AXI users").
//
// A thin wrapper, the PicoRV32 way: albatross_dpram_core (the RAM, its fixed
// time-division arbitration and byte atomicity) with the generic front-end
// albatross_axil2native on port A, the CPU's port, so a Zynq PS, MicroBlaze
// or any AXI RISC-V core attaches without glue.  Port B is the same Wishbone
// B4 classic slave as albatross_dpram's port B, clock for clock (req = cyc &
// stb): the side of the ALBATROSS controller (albatross_bus), of
// albatross_wb_cdc, or of a second CPU's Wishbone adapter.  Rules:
//   * Port B: ack 1 or 2 clocks after stb (the core's bound), one access every
//     2 clocks at most, whatever port A does.
//   * Port A (AXI4-Lite, byte addresses, 32-bit data): AW and W in any order or
//     together, WSTRB = byte enables, BRESP/RRESP always OKAY, one access in
//     flight; with the response channel free, BVALID rises 2 to 5 clocks
//     after the handshake that completed the write, RVALID 2 to 4 clocks after
//     the AR handshake (the adapter's 2 * 2 + 1 and 2 * 2 over the core's
//     bound 2); a stalled B or R delays only the next access of that kind.
//     The bounds hold whatever port B does.
//   * Byte atomicity as the core: every access of either port is one whole
//     access of the single-ported array, so a read sees each byte wholly old
//     or wholly new.
//   * One clock, one synchronous active-high reset (from an active-low
//     ARESETN: rst_i = ~aresetn, e.g. Vivado Processor System Reset's
//     peripheral_reset).  Reset never clears the array.
`default_nettype none

module albatross_dpram_axil #(
    parameter ADDR_WIDTH = 10, // word-address bits: 2**ADDR_WIDTH words of 32 bits (AXI: ADDR_WIDTH+2 byte-address bits)
    parameter INIT_FILE  = ""  // $readmemh image loaded at configuration ("": none)
) (
    (* X_INTERFACE_INFO = "xilinx.com:signal:clock:1.0 clk_i CLK" *)
    (* X_INTERFACE_PARAMETER = "ASSOCIATED_BUSIF S_AXI, ASSOCIATED_RESET rst_i" *)
    input  wire                  clk_i,
    (* X_INTERFACE_INFO = "xilinx.com:signal:reset:1.0 rst_i RST" *)
    (* X_INTERFACE_PARAMETER = "POLARITY ACTIVE_HIGH" *)
    input  wire                  rst_i,     // synchronous, active high
    // port A: AXI4-Lite slave
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI AWVALID" *)
    (* X_INTERFACE_PARAMETER = "PROTOCOL AXI4LITE, DATA_WIDTH 32" *)
    input  wire                  s_axi_awvalid_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI AWREADY" *)
    output wire                  s_axi_awready_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI AWADDR" *)
    input  wire [ADDR_WIDTH+1:0] s_axi_awaddr_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI AWPROT" *)
    input  wire [2:0]            s_axi_awprot_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI WVALID" *)
    input  wire                  s_axi_wvalid_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI WREADY" *)
    output wire                  s_axi_wready_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI WDATA" *)
    input  wire [31:0]           s_axi_wdata_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI WSTRB" *)
    input  wire [3:0]            s_axi_wstrb_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI BVALID" *)
    output wire                  s_axi_bvalid_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI BREADY" *)
    input  wire                  s_axi_bready_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI BRESP" *)
    output wire [1:0]            s_axi_bresp_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI ARVALID" *)
    input  wire                  s_axi_arvalid_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI ARREADY" *)
    output wire                  s_axi_arready_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI ARADDR" *)
    input  wire [ADDR_WIDTH+1:0] s_axi_araddr_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI ARPROT" *)
    input  wire [2:0]            s_axi_arprot_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI RVALID" *)
    output wire                  s_axi_rvalid_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI RREADY" *)
    input  wire                  s_axi_rready_i,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI RDATA" *)
    output wire [31:0]           s_axi_rdata_o,
    (* X_INTERFACE_INFO = "xilinx.com:interface:aximm:1.0 S_AXI RRESP" *)
    output wire [1:0]            s_axi_rresp_o,
    // port B: Wishbone B4 classic slave (as albatross_dpram's port B)
    input  wire                  b_cyc_i,
    input  wire                  b_stb_i,
    input  wire                  b_we_i,
    input  wire [ADDR_WIDTH-1:0] b_adr_i,
    input  wire [3:0]            b_sel_i,
    input  wire [31:0]           b_dat_i,
    output wire [31:0]           b_dat_o,
    output wire                  b_ack_o
);

    // port A's native request (adapter -> core)
    wire                  n_req, n_we, n_ack;
    wire [ADDR_WIDTH-1:0] n_adr;
    wire [3:0]            n_be;
    wire [31:0]           n_wdata, n_rdata;

    albatross_axil2native #(
        .ADDR_WIDTH(ADDR_WIDTH)
    ) u_axil (
        .clk_i(clk_i), .rst_i(rst_i),
        .s_axi_awvalid_i(s_axi_awvalid_i), .s_axi_awready_o(s_axi_awready_o),
        .s_axi_awaddr_i(s_axi_awaddr_i), .s_axi_awprot_i(s_axi_awprot_i),
        .s_axi_wvalid_i(s_axi_wvalid_i), .s_axi_wready_o(s_axi_wready_o),
        .s_axi_wdata_i(s_axi_wdata_i), .s_axi_wstrb_i(s_axi_wstrb_i),
        .s_axi_bvalid_o(s_axi_bvalid_o), .s_axi_bready_i(s_axi_bready_i), .s_axi_bresp_o(s_axi_bresp_o),
        .s_axi_arvalid_i(s_axi_arvalid_i), .s_axi_arready_o(s_axi_arready_o),
        .s_axi_araddr_i(s_axi_araddr_i), .s_axi_arprot_i(s_axi_arprot_i),
        .s_axi_rvalid_o(s_axi_rvalid_o), .s_axi_rready_i(s_axi_rready_i),
        .s_axi_rdata_o(s_axi_rdata_o), .s_axi_rresp_o(s_axi_rresp_o),
        .n_req_o(n_req), .n_we_o(n_we), .n_adr_o(n_adr), .n_be_o(n_be),
        .n_wdata_o(n_wdata), .n_rdata_i(n_rdata), .n_ack_i(n_ack)
    );

    albatross_dpram_core #(
        .ADDR_WIDTH(ADDR_WIDTH),
        .INIT_FILE (INIT_FILE)
    ) u_core (
        .clk_i(clk_i), .rst_i(rst_i),
        .a_req_i(n_req), .a_we_i(n_we), .a_adr_i(n_adr), .a_be_i(n_be),
        .a_wdata_i(n_wdata), .a_rdata_o(n_rdata), .a_ack_o(n_ack),
        .b_req_i(b_cyc_i & b_stb_i), .b_we_i(b_we_i), .b_adr_i(b_adr_i), .b_be_i(b_sel_i),
        .b_wdata_i(b_dat_i), .b_rdata_o(b_dat_o), .b_ack_o(b_ack_o)
    );

endmodule

`default_nettype wire
