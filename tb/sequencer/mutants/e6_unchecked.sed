# e6_unchecked: the entry check forgets E6 (rep above the mode's cluster, the
# one E6 rule of the --multirate image the controller checks: it does not
# check base < 2^rep): such an entry runs in the minor cycles its low base
# bits give and rom_errors misses it.  tb_sequencer_multirate must fail (make
# test-sequencer-multirate-negative-e6_unchecked).
s/(pe_df\[TB\] \&\& due_i) || e6_bad;/(pe_df[TB] \&\& due_i);/
