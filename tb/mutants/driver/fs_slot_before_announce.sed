# Four-slot mutant (wrong statement order): the consumer takes the slot byte
# from its first control-word load, made before it announced its pair, and
# does not load it again: an Export that chose that pair before the
# announcement completes the other slot and then writes this one.
/word = alb_rd32(ch->base);                     \/\* after the announcement \*\//d
