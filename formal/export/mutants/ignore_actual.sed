# ignore_actual: the buffer choice ignores d's Actual copy (known or read back),
# so the engine may overwrite the buffer Actual names, the newest complete value.
# Must fail no_actual_write.
s/wire \[1:0\] pick3     = (copy_d != BUFFER3 && rl_lock != BUFFER3) ? BUFFER3 :/wire [1:0] pick3     = (rl_lock != BUFFER3) ? BUFFER3 :/
s/^\( *\)(copy_d != BUFFER2 && rl_lock != BUFFER2) ? BUFFER2 : BUFFER1;/\1(rl_lock != BUFFER2) ? BUFFER2 : BUFFER1;/
