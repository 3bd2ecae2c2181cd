# target: rtl/albatross_slot_timing.v
# Controller mutant: the global time jumps back every 4096 clocks.
s/time_q     <= time_q + 32'd1;/time_q     <= (time_q[11:0] == 12'hFFF) ? time_q - 32'd4095 : time_q + 32'd1;/
