# target: rtl/albatross_transfer_frag.v
# frag_reimport (tb/mutants/controller/frag_reimport.sed): the source's lock
# released between runs: every run Imports afresh.  Must fail
# frag_held (the source's control word accessed in a run that goes on).
s/    wire        cont  = FR \&\& copy_i/    wire        cont  = 1'b0 \&\& FR \&\& copy_i/
