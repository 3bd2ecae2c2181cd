# Four-slot mutant (kind mismatch): the producer runs the three-buffer Export
# on a four-slot channel (its consumer is four-slot): it never stores a slot
# byte, and it ignores the consumer's pair.
s/const int four_slot = ch != 0 \&\& src != 0 \&\& ch->kind == ALB_FOUR_SLOT;/const int four_slot = 0;/
