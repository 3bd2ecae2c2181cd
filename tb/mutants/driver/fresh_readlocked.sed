# Mutant: the writer reads ReadLocked afresh for every comparison instead of
# copying it once (the paper, figure 4, CopyOfReadLocked).
s/buffer != copy_of_read_locked)/buffer != alb_rd8(ch->base + ALB_OFF_READLOCKED))/
