# skip_confirm: after the store of ReadLocked the Import selects that buffer at
# once, without the confirming load of Actual (figure 3's loop cut short): the
# producer may be writing that buffer.  Must fail load_not_written
# (formal/import/import.sby neg_skip_confirm).
s/                    stb_q      <= may_access_i;/                    stb_q      <= 1'b0;/
s/                    state_q    <= may_access_i ? S_LOAD_ACTUAL : S_IDLE;/                    state_q    <= may_access_i ? S_SELECTED : S_IDLE;/
