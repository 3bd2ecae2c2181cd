# loop4: the four-slot Import goes back to the three-buffer loop after its
# ReadLocked store (load Actual again until it matches): not wait-free.
# Must fail fs_wait_free (formal/import/import.sby four_neg_loop4).
s/                nst = four_q ? S_LOAD_SLOT : S_LOAD_ACTUAL;/                nst = S_LOAD_ACTUAL;/
