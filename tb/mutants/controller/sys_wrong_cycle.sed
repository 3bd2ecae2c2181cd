# target: rtl/albatross_minor_cycles.v
# Controller mutant: an entry run in a wrong minor cycle: the minor-cycle count
# starts at 1 instead of 0 after start-up, so every entry of a multi-rate image
# runs one minor cycle before the cycles its E6 makes it due in.  The system
# checker's due_cycle must catch it (test-system-negative-wrong-cycle; the
# sequencer proof's own negative is formal/sequencer/mutants/wrong_cycle.sed).
s/        if (rst_i || !MR)  n_q <= {CB{1'b0}};/        if (rst_i || !MR)  n_q <= {{(CB-1){1'b0}}, 1'b1};/
