# Controller mutant: the store of a destination's Actual uses the ReadLocked
# byte lane, a byte only the consumer may write.
s/(state_d == S_DA_ST)  ? SEL_ACT : 4'b1111;/(state_d == S_DA_ST)  ? (SEL_ACT | SEL_RL) : 4'b1111;/
