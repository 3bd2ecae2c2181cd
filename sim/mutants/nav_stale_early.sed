# Firmware mutant (applied to sim/firmware/mobot_navigation.c): the staleness
# limit is below what the controller guarantees, so navigation reports a
# healthy RadarMap stale.  The fault-free run must catch it
# (test-pico-boards-negative-nav_stale_early).
s/^#define NAV_RADAR_STALE_CLOCKS (.*)$/#define NAV_RADAR_STALE_CLOCKS (ALB_RADARMAP_LATENCY_CLOCKS \/ 4u)/
