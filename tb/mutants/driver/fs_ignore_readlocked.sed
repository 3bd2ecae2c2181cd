# Four-slot mutant: the producer ignores ReadLocked and writes the pair that
# does not hold Actual, so it can write the slot the consumer is reading.
s/pair = 1u - ALB_FS_PAIR(read_locked);/pair = 1u - ALB_FS_PAIR(ch->fs_actual);/
