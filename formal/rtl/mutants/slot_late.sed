# target: rtl/albatross_sequencer.v
# Controller mutant (formal only): the entry fetch takes one clock more (go is
# decided in FETCH clock 6 instead of 5), so every slot's first access is one
# clock after its planned time.
s/go_q      <= !rst_i \&\& state_q == ST_FETCH \&\& step_q == 3'd5 \&\& kind/go_q      <= !rst_i \&\& state_q == ST_FETCH \&\& step_q == 3'd6 \&\& kind/
