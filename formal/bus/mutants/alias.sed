# alias: the board decode ignores the top bit of the board field, so board 8
# reaches board 0, which acks a request to an absent board.
# Must fail ack_selected (formal/bus/bus.sby neg_alias).
s/sel_b\[s\] = {1'b0, board} == s\[BOARD_BITS:0\];/sel_b[s] = board[BOARD_BITS-2:0] == s[BOARD_BITS-2:0];/
