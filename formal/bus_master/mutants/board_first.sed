# board_first: the board field of m_adr_o is taken from the lowest-indexed
# requester with cyc, not from the owner (right unless a lower-indexed requester
# waits behind the owner).  Must fail adr_owner (bus_master.sby neg_board_first).
s/r_board_i\[owner\*BOARD_BITS +: BOARD_BITS\]/r_board_i[first*BOARD_BITS +: BOARD_BITS]/
