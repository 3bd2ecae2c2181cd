# target: rtl/albatross_transfer_frag.v
# Controller mutant: the source's lock released between fragments: every run
# of a fragmented channel begins with a fresh Import (the ReadLocked store
# and the control loads), as if no value were in progress.  The controller
# bench's scenario frag must fail (test-controller-negative-frag_reimport:
# "frag whole: fragment 1 makes no access to the source's control word").
s/    wire        cont     = HAS_FRAGMENTS != 0 \&\& copy_i/    wire        cont     = 1'b0 \&\& HAS_FRAGMENTS != 0 \&\& copy_i/
