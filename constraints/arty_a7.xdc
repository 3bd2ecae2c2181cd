## Digilent Arty A7-35T / A7-100T (CSG324): pins and clock of fpga/arty_top.v.
## Yosys synth_xilinx -family xc7 (make synth); Debian 12 has no open place
## and route for 7-series, so timing against this constraint is checked
## with Vivado (read_xdc constraints/arty_a7.xdc) or nextpnr-xilinx.

## 100 MHz oscillator
set_property -dict { PACKAGE_PIN E3  IOSTANDARD LVCMOS33 } [get_ports { clk_i }]
create_clock -name sys_clk -period 10.000 -waveform {0 5} [get_ports { clk_i }]

## RESET button (ck_rst), active low
set_property -dict { PACKAGE_PIN C2  IOSTANDARD LVCMOS33 } [get_ports { btn_n_i }]
set_false_path -from [get_ports { btn_n_i }]

## LEDs LD4..LD7
set_property -dict { PACKAGE_PIN H5  IOSTANDARD LVCMOS33 } [get_ports { led_o[0] }]
set_property -dict { PACKAGE_PIN J5  IOSTANDARD LVCMOS33 } [get_ports { led_o[1] }]
set_property -dict { PACKAGE_PIN T9  IOSTANDARD LVCMOS33 } [get_ports { led_o[2] }]
set_property -dict { PACKAGE_PIN T10 IOSTANDARD LVCMOS33 } [get_ports { led_o[3] }]

## RGB LED LD0
set_property -dict { PACKAGE_PIN G6  IOSTANDARD LVCMOS33 } [get_ports { led0_r_o }]
set_property -dict { PACKAGE_PIN F6  IOSTANDARD LVCMOS33 } [get_ports { led0_g_o }]
set_false_path -to [get_ports { led_o[*] led0_r_o led0_g_o }]
