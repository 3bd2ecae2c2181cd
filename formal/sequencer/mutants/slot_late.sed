# slot_late: a slot's fetch starts one clock after its planned start S (the
# WAIT state waits for rel > start), so go_o comes in clock S + FETCH_CYCLES.
# (edits rtl/albatross_slot_timing.v, where the start compare lives)
# Must fail go_time (formal/sequencer/sequencer.sby neg_slot_late).
s/wire         start_now = wait_i \&\& next_rel_q > {1'b0, start_q};/wire         start_now = wait_i \&\& next_rel_q > {1'b0, start_q} + 1'b1;/
