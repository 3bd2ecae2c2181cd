# target: rtl/albatross_sequencer.v
# Controller mutant (formal/sequencer/mutants/start_bad_crc.sed on the
# controller): the start-up pass starts the first cycle at its end whatever
# the CRC (error_o is still raised), so the slots run from an image the check
# refused.  The system test on a ROM image with one bit flipped must fail
# (test-system-negative-rom-start-crc): the controller makes bus accesses.
s/(state_q == ST_CHECK \&\& pass_done \&\& crc_ok);/(state_q == ST_CHECK \&\& pass_done);/
# (the read of entry 0's E6 at the same moment is skipped with it, or the
# first cycles would run on an E6 never read: the mutant is the CRC check
# skipped, nothing else)
s/hdr_e6    = state_q == ST_CHECK \&\& pass_done \&\& crc_ok;/hdr_e6    = state_q == ST_CHECK \&\& pass_done;/
