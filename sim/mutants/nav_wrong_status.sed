# Firmware mutant (applied to sim/firmware/mobot_navigation.c): navigation sums
# the wrong STATUS counter, so the retries it reports stay 0.  The bus fault
# test must catch it (test-pico-boards-negative-nav_wrong_status).
s/retries += ALB_STATUS_RETRIES(s->word, id);/retries += ALB_STATUS_CORRUPT(s->word, id);/
