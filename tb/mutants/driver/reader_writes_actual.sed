# Mutant: the consumer stores into Actual instead of ReadLocked, a variable
# only the producer may write (the paper, figure 2).
s/alb_wr8(ch->base + ALB_OFF_READLOCKED, actual);/alb_wr8(ch->base + ALB_OFF_ACTUAL, actual);/
