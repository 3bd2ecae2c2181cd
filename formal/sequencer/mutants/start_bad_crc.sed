# start_bad_crc: the start-up pass starts the first cycle at its end whatever
# the CRC (error_o is still raised): slots run from an invalid ROM.
# Must fail idle_on_error (formal/sequencer/sequencer.sby neg_start_bad_crc).
s/(state_q == ST_CHECK \&\& pass_done \&\& crc_ok);/(state_q == ST_CHECK \&\& pass_done);/
