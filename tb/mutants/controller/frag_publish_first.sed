# target: rtl/albatross_transfer_fsm.v
# Controller mutant: a fragmented value's first fragment is taken for its
# last (a publish after the first fragment): taken_at and the destination's
# Actual are stored after words [0, frag) alone, before the value is whole.  The
# controller bench's scenario frag must fail
# (test-controller-negative-frag_publish_first: "frag whole: fragment 0
# publishes nothing").
s/                        if (lastf) begin/                        if (lastf || !cont_q) begin/
