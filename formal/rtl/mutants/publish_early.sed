# Controller mutant (formal only): after the last value word, the Export stores
# Actual instead of the taken_at word, publishing a buffer one word short.
/dat_sel = DS_TAKEN;             \/\/ taken_at$/{
s/DS_TAKEN/DS_CTRL_W/
n
s/access(S_DW_ST);/access(S_DA_ST);/
}
