# target: rtl/albatross_controller.v
# Controller mutant: the per-channel state is forgotten outside mode 0 (the
# ReadLocked copy reads as 0, unknown), so a channel of mode 1 takes its
# unchanged source value as New in every cycle and publishes it again.
# Scenario modes must fail: the value is New twice
# (test-controller-negative-forget_state).
s/    wire \[2:0\]  st_rl    = st_q\[34:32\];/    wire [2:0]  st_rl    = (mode != 4'd0) ? 3'd0 : st_q[34:32];/
