#!/usr/bin/env bash
# lint.sh FILE... -- every Verilog file is its own top (module named as the
# file); the modules it instantiates come from the library folders rtl/
# (the IP), soc/ (soft-core board parts) and tb/common/ (shared test-only
# modules).  Each must pass Verilator's -Wall lint with no warning, compile
# with Icarus (-g2005) and elaborate in Yosys (which reads the files given
# and, from the library folders, only the file of a module still missing,
# e.g. soc/albatross_system.v under tb/system/tb_system.v: not whole folders,
# as test benches there may hold constructs Yosys does not parse, and are
# linted by their own targets).
# Verilator and Icarus run per file, LINT_JOBS at a time (default: the
# cores); Yosys reads every file once and elaborates each top from a saved
# copy of that design.  Exit status 0 when every file passes; otherwise the
# failures are printed, one "lint FAILED <file>: <tool>" line each.
set -u
lib="-Irtl -y rtl -y soc -y tb/common"   # -Irtl: rtl/albatross_contract.vh
jobs=${LINT_JOBS:-$(nproc)}
[ $# -gt 0 ] || { echo "usage: lint.sh FILE.v..." >&2; exit 2; }

one() {   # FILE: Verilator and Icarus on one file as its own top
    local f=$1 top
    top=$(basename "$f" .v)
    verilator --lint-only -Wall $lib --top-module "$top" "$f" || { echo "lint FAILED $f: verilator"; return 1; }
    iverilog -g2005 $lib -s "$top" -o /dev/null "$f" || { echo "lint FAILED $f: iverilog"; return 1; }
    echo "lint ok  $f (verilator, iverilog)"
}
export -f one; export lib
printf '%s\n' "$@" | xargs -P "$jobs" -I{} bash -c 'one "$1"' _ {}
rc_tools=$?

# Yosys: one read of every file, then per top: the saved design, hierarchy, proc.
script="verilog_defaults -add -Irtl; read_verilog $*; design -save all"
for f in "$@"; do
    top=$(basename "$f" .v)
    script="$script; design -load all; hierarchy -check -libdir rtl -libdir soc -libdir tb/common -top $top; proc"
done
if yosys -q -p "$script"; then
    echo "lint ok  all $# files (yosys)"; rc_yosys=0
else
    echo "lint FAILED: yosys (its error above names the module)"; rc_yosys=1
fi
[ "$rc_tools" -eq 0 ] && [ "$rc_yosys" -eq 0 ]
