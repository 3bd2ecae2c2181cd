# target: rtl/albatross_export.v
# Controller mutant (formal only): after the last value word, the Export stores
# Actual instead of the taken_at word, publishing a buffer one word short.
s/if (last_word) begin_access(TAKEN_AT ? S_STORE_TAKEN : after_data, first_d);/if (last_word) begin_access(S_STORE_ACTUAL, first_d);/
