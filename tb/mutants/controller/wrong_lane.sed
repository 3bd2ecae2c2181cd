# Controller mutant: the store of a destination's Actual uses the ReadLocked
# byte lane, a byte only the consumer may write.
s/(state_d == S_DA_ST)  ? 4'b0001 : 4'b1111;/(state_d == S_DA_ST)  ? 4'b0011 : 4'b1111;/
