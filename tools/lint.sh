#!/usr/bin/env bash
# lint.sh FILE... -- every Verilog file is its own top (module named as the
# file); the modules it instantiates come from the library folders rtl/
# (the IP), soc/ (soft-core board parts) and tb/common/ (shared test-only
# modules).  Each must pass Verilator's -Wall lint with no warning, compile
# with Icarus (-g2005) and elaborate in Yosys (which reads the files given
# and, from the library folders, only the file of a module still missing,
# e.g. soc/albatross_system.v under tb/system/tb_system.v: not whole folders,
# as test benches there may hold constructs Yosys does not parse, and are
# linted by their own targets).  Stops at the first failure.
set -eu
lib="-Irtl -y rtl -y soc -y tb/common"   # -Irtl: rtl/albatross_contract.vh
for f in "$@"; do
    top=$(basename "$f" .v)
    verilator --lint-only -Wall $lib --top-module "$top" "$f"
    iverilog -g2005 $lib -s "$top" -o /dev/null "$f"
    others=""
    for r in "$@"; do [ "$r" -ef "$f" ] || others="$others $r"; done
    yosys -q -p "verilog_defaults -add -Irtl; read_verilog$others $f; hierarchy -check -libdir rtl -libdir soc -libdir tb/common -top $top; proc"
    echo "lint ok  $f"
done
