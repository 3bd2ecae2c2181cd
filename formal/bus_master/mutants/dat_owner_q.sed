# dat_owner_q: the store data passed through (HOLD_FIELDS 0) come from the last
# clock's owner, not the present one: the same while an access is pending,
# but in the first clock of a new owner's access -- the hand-over, when one
# requester drops cyc and the other gets the bus -- the slave is sent the old
# owner's data with the new owner's address.  (With HOLD_FIELDS 1 the held
# register carries the same wrong first-clock value.)  Must fail fld_pass at
# the controller's configuration (bus_master.sby neg_ctrl_dat_owner_q).
s/r_sel_i\[owner\*4 +: 4\], r_dat_i\[owner\*32 +: 32\]};/r_sel_i[owner*4 +: 4], r_dat_i[owner_q*32 +: 32]};/
