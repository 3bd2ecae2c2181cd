# target: rtl/albatross_transfer.v
# Controller mutant: a fragmented value's first fragment is taken for its
# last (a publish after the first fragment): the destination's Actual is
# stored after words [0, frag) alone, before the value is whole.  The
# controller bench's scenario frag must fail
# (test-controller-negative-frag_publish_first: "frag whole: fragment 0
# publishes nothing").
s/    wire        lastf    = !fr_on || f_sum >= {1'b0, words_i};/    wire        lastf    = !fr_on || !cont_q || f_sum >= {1'b0, words_i};/
