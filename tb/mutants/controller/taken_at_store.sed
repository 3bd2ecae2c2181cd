# target: rtl/albatross_export.v
# Controller mutant: the taken_at word a destination gets is the controller's
# input at the time of that store, near the end of the transfer (for a New
# copy time_o then, tb/mutants/controller/taken_at_end.sed keeps the right
# first delivery), not the time sampled when the Export started, at the final
# source Actual load.  Every New delivery carries a time a few accesses late,
# still between the producer's and the destination's publication.
s/                          state_q == S_STORE_TAKEN ? taken_q :/                          state_q == S_STORE_TAKEN ? taken_at_i :/
