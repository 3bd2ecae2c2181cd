# drop_total: the run of failures is not cleared when an access succeeds, so
# K failures anywhere in the Export drop the destination that meets the K-th,
# not K failures of one access in a row (close to the fixed rule of earlier versions,
# which dropped a destination at its second failure in the Export).  Must fail
# retry_same (the access after a failure is not repeated although no access
# failed K times in a row) or complete_export.
s|^                run_q <= 8'd0;                              // the next access: a new run$|                // (the run is kept)|
