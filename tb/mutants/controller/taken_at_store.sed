# target: rtl/albatross_controller.v
# Controller mutant: the taken_at word a destination gets is the global time
# of that store, near the end of the transfer, not the time recorded when
# the value was chosen, at the final source Actual load.  Every delivery
# carries a time a few accesses late, still between the producer's and the
# destination's publication.
s/\.st_taken_i(st_taken)/.st_taken_i(time_o)/
