# target: rtl/albatross_controller.v
# Controller mutant: every channel's state is forgotten in the first 100
# clocks of a mode (the ReadLocked copy reads as 0, unknown), so after a
# switch a channel whose value did not change is taken as New and published
# again.  Scenario modes must fail: channel 0's value, unchanged over the
# switches to mode 1 and back, comes New twice
# (test-controller-negative-forget_switch).
s/    wire \[2:0\]  st_rl    = st_q\[34:32\];/    wire [2:0]  st_rl    = (time_o - mode_since < 32'd100) ? 3'd0 : st_q[34:32];/
