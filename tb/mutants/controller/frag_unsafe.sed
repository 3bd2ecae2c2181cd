# target: rtl/albatross_transfer_fsm.v
# Controller mutant: a value goes on after a run cut off in its publication
# even when a destination still in it had a Slot or Actual store put on the
# bus in that run (safe_o always 1): the next run goes on from word W - 1
# and publishes again, where the rule ends the value (a begun store may have
# landed; only a fresh Import's control load can tell).  Seen only when a
# fault hits such a store and the deadline cuts its retry off:
# test-system-negative-frag-unsafe, on the image planned for 5 % faults,
# must be caught by fragment_word (a run without an Import while no value
# goes on).
s/    assign safe_o      = (att_q & live) == 4'd0;/    assign safe_o      = 1'b1;/
