# target: rtl/albatross_transfer_pick.v
# Controller mutant: the rule from before the cold-start contract.  A control
# byte of 0 (not started, a zeroed RAM) is out of range like 4..255: a source
# Actual of 0 and a destination's Actual or ReadLocked of 0 count corrupt, and
# the four-slot Export, finding ReadLocked 0, writes the pair other than its
# Actual copy's.  Caught by test_controller's scenario cold
# (make test-controller-negative-cold).
s/wire       a_zero   = a_byte == NOT_STARTED;/wire       a_zero   = 1'b0 \&\& a_byte == NOT_STARTED;/
s/wire       r_zero   = r_byte == NOT_STARTED;/wire       r_zero   = 1'b0 \&\& r_byte == NOT_STARTED;/
