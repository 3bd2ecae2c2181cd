# skip_confirm: after the store of ReadLocked the Import selects that buffer at
# once, without the confirming load of Actual (figure 3's loop cut short): the
# producer may be writing that buffer.  Must fail load_not_written
# (formal/import/import.sby neg_skip_confirm).
/            S_STORE_RL: if (wb_ack_i) begin/,/            end/s/                nst = four_q ? S_LOAD_SLOT : S_LOAD_ACTUAL;/                nst = S_SELECTED;/
