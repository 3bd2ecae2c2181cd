# early_slot4: the four-slot Export stores the slot byte right after the last
# value word, before taken_at (a buffer completed before its last word).
# Must fail fs_slot_store (export.sby four_neg_early_slot4).
s/if (last_word) begin_access(TAKEN_AT ? S_STORE_TAKEN : after_data, first_d);/if (last_word) begin_access(after_data, first_d);/
