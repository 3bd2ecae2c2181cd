# Firmware mutant: the radar producer stores a wrong checksum word in every
# RadarMap value whose sequence number has bit 2 set.  The navigation core's
# check must catch it (test-pico-boards-negative-radar_bad_checksum).
s/    v->range_mm\[31\] = (uint16_t)(sum ^ MOBOT_SALT);/    v->range_mm[31] = (uint16_t)(sum ^ MOBOT_SALT ^ (seq \& 4u));/
