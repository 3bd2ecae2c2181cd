#!/usr/bin/env bash
# fusesoc_user_core.sh [--negative] -- the user's core of docs/integration.md
# ("In your own core"), taken from the page as it stands: its first ```yaml
# block becomes build/fusesoc/user/lib/my_top.core, beside a my_top.v that
# wraps albatross_dpram, and tools/fusesoc_check.py checks that library with
# the checkout as a second one: the core loads, and its lint target passes
# (Verilator -Wall through FuseSoC) with the files it depends on.
# --negative: the same block without its targets: section must be rejected
# (no lint target in a core of Verilog sources).
# Needs build/FUSESOC_IGNORE (make fusesoc-ignore), so that FuseSoC does not
# read the copies of core files under build/ as part of the checkout.
set -u
neg=0; [ "${1:-}" = "--negative" ] && neg=1
d=build/fusesoc/user$([ $neg = 1 ] && echo -neg)
rm -rf "$d"; mkdir -p "$d/lib"
awk '/^```yaml$/ {on=1; next} on && /^```$/ {exit} on {print}' docs/integration.md > "$d/lib/my_top.core"
grep -q '^CAPI=2:' "$d/lib/my_top.core" || { echo "fusesoc-user-core: expected a core file (CAPI=2:) in the first yaml block of docs/integration.md, got: $(head -n 1 "$d/lib/my_top.core")"; exit 1; }
grep -q '^targets:' "$d/lib/my_top.core" || { echo "fusesoc-user-core: expected a targets: section in the snippet of docs/integration.md, got none"; exit 1; }
if [ $neg = 1 ]; then
    sed -i '/^targets:/,$d' "$d/lib/my_top.core"
fi
cat > "$d/lib/my_top.v" <<'V'
`default_nettype none
// my_top -- the user's top of docs/integration.md's core file: albatross_dpram
// with its ports passed through.
module my_top (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        a_cyc_i, a_stb_i, a_we_i,
    input  wire [9:0]  a_adr_i,
    input  wire [3:0]  a_sel_i,
    input  wire [31:0] a_dat_i,
    output wire [31:0] a_dat_o,
    output wire        a_ack_o,
    input  wire        b_cyc_i, b_stb_i, b_we_i,
    input  wire [9:0]  b_adr_i,
    input  wire [3:0]  b_sel_i,
    input  wire [31:0] b_dat_i,
    output wire [31:0] b_dat_o,
    output wire        b_ack_o
);
    albatross_dpram #(.ADDR_WIDTH(10)) u_ram (
        .clk_i(clk_i), .rst_i(rst_i),
        .a_cyc_i(a_cyc_i), .a_stb_i(a_stb_i), .a_we_i(a_we_i), .a_adr_i(a_adr_i),
        .a_sel_i(a_sel_i), .a_dat_i(a_dat_i), .a_dat_o(a_dat_o), .a_ack_o(a_ack_o),
        .b_cyc_i(b_cyc_i), .b_stb_i(b_stb_i), .b_we_i(b_we_i), .b_adr_i(b_adr_i),
        .b_sel_i(b_sel_i), .b_dat_i(b_dat_i), .b_dat_o(b_dat_o), .b_ack_o(b_ack_o));
endmodule
`default_nettype wire
V
python3 tools/fusesoc_check.py --root "$d/lib" --work "$d/work" --library . > "$d/check.log" 2>&1
rc=$?
cat "$d/check.log"
if [ $neg = 0 ]; then
    [ $rc = 0 ] && grep -q "1 lint targets" "$d/check.log" || { echo "fusesoc-user-core: expected the snippet's core to load and its lint target to pass, got exit $rc"; exit 1; }
    echo "fusesoc-user-core: the core file of docs/integration.md loads and lints with its dependencies"
else
    [ $rc != 0 ] && grep -q "expected a lint target" "$d/check.log" || { echo "fusesoc-user-core-negative: expected the core without targets: to be rejected for its missing lint target, got exit $rc"; exit 1; }
    echo "fusesoc-user-core-negative: the core without its targets: section is rejected"
fi
