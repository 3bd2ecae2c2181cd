# Mutant: the writer ignores ReadLocked and may pick the buffer being read.
s/if (buffer != ch->actual \&\& buffer != copy_of_read_locked)/if (buffer != ch->actual)/
