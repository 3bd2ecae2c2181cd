# Mutant: Export writes one payload word too few: WriteTo (the paper, figure 4)
# drops its tail store, so the last word of a payload that is not a whole
# number of words (33 bytes in crash mode) is never written.
/^        alb_wr32(dst, w);$/d
