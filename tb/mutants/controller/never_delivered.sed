# Controller mutant: a published destination is never marked delivered, so
# every redundant slot publishes the same value again.
s/^                    need_op  = N_CLR;$/                    need_op  = N_HOLD;/
