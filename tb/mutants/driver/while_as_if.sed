# Mutant: the reader's While replaced by If (the paper, figure 3): the consumer
# takes one look at Actual and never re-checks it after storing ReadLocked.
s/while (actual != ch->read_locked) {/if (actual != ch->read_locked) {/
