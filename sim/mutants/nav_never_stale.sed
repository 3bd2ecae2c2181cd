# Firmware mutant (applied to sim/firmware/mobot_navigation.c): the staleness
# limit is so large that navigation never reports a stale RadarMap.  The radar
# crash test must catch it (test-pico-boards-negative-nav_never_stale).
s/^#define NAV_RADAR_STALE_CLOCKS (.*)$/#define NAV_RADAR_STALE_CLOCKS 0x7FFFFFFFu/
