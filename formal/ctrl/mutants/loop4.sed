# target: rtl/albatross_transfer_fsm.v
# loop4 (formal/import/mutants/loop4.sed on the datapath): the four-slot
# Import loads Actual again after its ReadLocked store (not wait-free).  Must
# fail src_wait_free.
s/                    begin_access(four_i ? S_SRC_SLOT : S_SRC_ACT, 2'd0);/                    begin_access(S_SRC_ACT, 2'd0);/
