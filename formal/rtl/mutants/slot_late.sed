# target: rtl/albatross_sequencer.v
# Controller mutant (formal only): the entry fetch takes one clock more, so
# every slot's first access is one clock after its planned time.
s/wire        go_now   = state_q == ST_FETCH \&\& step_q == 3'd6 \&\& !bad_q/wire        go_now   = state_q == ST_FETCH \&\& step_q == 3'd7 \&\& !bad_q/
