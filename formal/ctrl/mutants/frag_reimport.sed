# target: rtl/albatross_transfer_frag.v
# frag_reimport (tb/mutants/controller/frag_reimport.sed): the source's lock
# released between fragments: every run Imports afresh.  Must fail
# frag_held (the source's control word accessed in a later fragment).
s/    wire        cont     = HAS_FRAGMENTS != 0 \&\& copy_i/    wire        cont     = 1'b0 \&\& HAS_FRAGMENTS != 0 \&\& copy_i/
