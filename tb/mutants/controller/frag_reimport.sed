# target: rtl/albatross_transfer_frag.v
# Controller mutant: the source's lock released between the runs of a value:
# no run goes on with a value (cont is 0), every run of the channel begins
# with a fresh Import (the ReadLocked store and the control loads).  The
# controller bench's scenario frag must fail
# (test-controller-negative-frag_reimport: "frag whole: run 1 makes no
# access to the source's control word").
s/    wire        cont  = FR \&\& copy_i/    wire        cont  = 1'b0 \&\& FR \&\& copy_i/
