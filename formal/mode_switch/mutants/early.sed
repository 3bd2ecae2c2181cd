# early: the mode switch takes effect as soon as the mode is loaded, in the
# clock after its E1 read, without waiting for the cycle boundary.
# Must fail base_at_boundary (formal/mode_switch/mode_switch.sby neg_early).
s/default: if (switch_i) begin               \/\/ L_READY: the boundary/default: if (1'b1) begin/
