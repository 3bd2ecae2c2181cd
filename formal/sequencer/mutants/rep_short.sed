# rep_short: the due test reads the repetition one bit short (rep[2:0], its
# top bit lost): an entry of rep 8 runs as one of rep 0, in every minor cycle.
# Must fail go_time (formal/sequencer/sequencer.sby neg_rep_short, image rep8).
s/            due_q    <= !MR || agree\[e6_rep\];/            due_q    <= !MR || agree[{1'b0, e6_rep[2:0]}];/
