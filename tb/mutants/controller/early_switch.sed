# target: rtl/albatross_mode_switch.v
# Controller mutant: the running mode changes as soon as the new mode's
# values are loaded (a few clocks before the cycle's end), not at the cycle
# boundary; the new mode's entries still start at the boundary.  The system
# test must catch it: a switch that is not on a cycle boundary
# (test-system-negative-modes-early).
s/^                    e6_q   <= 1'b1;/                    e6_q   <= 1'b1; mode_q <= idx_q;/
