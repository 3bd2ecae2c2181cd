# Mutant: the reader's loop (the paper, figure 3) waits for a buffer index that
# never comes (0), so Import never returns, two RAM accesses a pass.  It
# checks the watchdogs themselves: they must stop it and name the call.
s/while (actual != ch->read_locked) {/while (actual != 0u) {/
