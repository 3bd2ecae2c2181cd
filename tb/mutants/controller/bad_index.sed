# Controller mutant: the buffer choice can yield index 0, an invalid Actual.
s/pick = (a != 2'd3 \&\& r != 2'd3) ? 2'd3 : (a != 2'd2 \&\& r != 2'd2) ? 2'd2 : 2'd1;/pick = (a != 2'd3 \&\& r != 2'd3) ? 2'd3 : (a != 2'd2 \&\& r != 2'd2) ? 2'd2 : 2'd0;/
