#!/usr/bin/env bash
# expect_fail.sh BINARY... -- the checker's own negative test.  Each BINARY is
# the unit tests (tb/unit/*.c, see DRV_UNIT_SRC in tools/mk/driver.mk) built
# against a deliberately broken port (see tb/unit/port/alb_port_impl.h,
# UNIT_BROKEN_PORT).  Each must end with exit
# status 1 and a last line "driver-unit: N checks, F failed" with F > 0
# (a crash or a clean pass both count as "not caught").  Exits non-zero
# unless every broken port was caught.
set -u
caught=0; total=0
for bin in "$@"; do
    total=$((total + 1))
    log=$bin.log
    "$bin" >"$log" 2>&1
    rc=$?
    last=$(tail -n 1 "$log")
    if [ "$rc" -eq 1 ] && [[ "$last" =~ ^driver-unit:\ [0-9]+\ checks,\ [1-9][0-9]*\ failed$ ]]; then
        caught=$((caught + 1))
        echo "caught     $(basename "$bin"): $last; first: $(head -n 1 "$log")"
    else
        echo "NOT CAUGHT $(basename "$bin"): exit $rc, last line: $last"
    fi
done
echo "driver-unit-negative: $caught of $total broken ports caught"
[ "$caught" -eq "$total" ] && [ "$total" -gt 0 ]
