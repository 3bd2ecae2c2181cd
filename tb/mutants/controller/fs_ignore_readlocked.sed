# target: rtl/albatross_transfer_pick.v
# Controller mutant: the four-slot Export ignores the destination's
# ReadLocked when it picks the pair to write: it takes the pair opposite to
# Actual's, as if no consumer were reading.  A consumer still reading the
# value it locked is overtaken: the second Export writes the other slot of
# its pair, the fourth the very buffer it reads (a torn value).  Only a
# consumer overtaken by four or more Exports during one Import shows it.
s/wire       pk_p     = r_valid ? !r_pair : r_zero ? 1'b1 : a_valid ? !a_pair : 1'b1;/wire       pk_p     = a_valid ? !a_pair : 1'b1;/
