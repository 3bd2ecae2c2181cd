# target: rtl/albatross_sequencer.v
# Controller mutant: an entry run in a wrong minor cycle: the minor-cycle count
# starts at 1 instead of 0 after start-up, so every entry of a multi-rate image
# runs one minor cycle before the cycles its E6 makes it due in.  The system
# checker's due_cycle must catch it (test-system-negative-wrong-cycle; the
# sequencer proof's own negative is formal/sequencer/mutants/wrong_cycle.sed).
s/            n_q       <= {CB{1'b0}};/            n_q       <= {{(CB-1){1'b0}}, 1'b1};/
