# target: rtl/albatross_transfer_fsm.v
# drop_total (formal/export/mutants/drop_total.sed on the datapath): the run
# of failures is not cleared when an access succeeds, so K failures anywhere
# in the Export drop a destination.  Must fail retry_same or drop_k.
s/            if (adv) run_q <= 8'd0;/            \/\/ (the run is kept)/
