# Four-slot mutant: the consumer reports New whenever Actual differs from the
# buffer it read last (the mapping as first proposed): when it
# has read a value the producer completed (Slot stored) but not yet published
# (Actual not yet stored), its next Import reads the same value again and
# reports it New a second time.
s/result = \*buffer == ch->last ? ALB_OLD : ALB_NEW;/result = ALB_NEW;/
