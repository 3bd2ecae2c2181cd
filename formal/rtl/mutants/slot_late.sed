# Controller mutant (formal only): the entry fetch takes one clock more, so
# every slot's first access is one clock after its planned time.
s/localparam FETCH_CYCLES = 10; /localparam FETCH_CYCLES = 11; /
