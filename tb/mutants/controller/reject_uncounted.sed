# target: rtl/albatross_controller.v
# Controller mutant: a rejected mode request (one for a mode the image does
# not declare) is not counted as a corrupt value of the request channel, so
# STATUS never shows it.  The system test's exact count of rejections must
# fail (test-system-negative-modes-reject-count); before it, only the
# controller bench noticed (scenario modes), and system-modes only on a run
# that made two or more such requests.
s/    wire \[2:0\] corrupts = slot_end ? tr_corrupt + {2'd0, mode_reject} : 3'd0;/    wire [2:0] corrupts = slot_end ? tr_corrupt : 3'd0;/
