# Export engine mutant: Actual is stored after W-1 words, before the last
# word of the value: a buffer is published incompletely written.  Caught by:
# definite_results (the consumer reads a value no Export wrote).
s/wire       last_word = take_k_q == words_q;/wire       last_word = take_k_q == words_q - 1'b1;/
