# cold_zero_corrupt.sed -- the driver's behaviour before the cold-start
# contract: a control byte of 0 (its writer has not started) is ALB_ERR_CORRUPT
# like any value out of range, and a four-slot Export that finds ReadLocked = 0
# takes the pair other than Actual's.  The cold-start unit test must catch it.
s/return actual == ALB_NOT_STARTED ? ALB_OLD : ALB_ERR_CORRUPT;/return ALB_ERR_CORRUPT;/
s/return latest == ALB_NOT_STARTED ? FS_NOTHING : ALB_ERR_CORRUPT;/return ALB_ERR_CORRUPT;/
s/ && copy_of_read_locked != ALB_NOT_STARTED)/)/
s/read_locked = ALB_BUFFER1;     \/\* consumer not started/(void)0;     \/* mutant/
