# Four-slot mutant (wrong statement order): the consumer reads the buffer
# Actual named at its first load instead of the one the slot byte names
# after its announcement: the producer may still be writing it (an Export
# that chose its pair before the announcement).
/^static int fs_select_read/,/^}/s/*buffer = (uint8_t)ALB_FS_BUFFER(pair, slot);/*buffer = latest;/
