# Four-slot mutant (kind mismatch): the producer takes the three-buffer
# side of the driver on a four-slot channel (its consumer is four-slot): its
# attach fills the three-buffer copy of Actual, so every Export runs the
# three-buffer code: it never stores a slot byte, and it ignores the
# consumer's pair.
s/    ch->fs_actual = actual;/    ch->actual = actual;/
