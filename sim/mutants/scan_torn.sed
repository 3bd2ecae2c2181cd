# Firmware mutant: the radar puts one word of the next scan (its sequence
# number one higher) in the middle of every RadarScan value, as a value mixed
# from two scans would have it.  Navigation's word check (slow_ok0,
# sim/firmware/mobot_check.h) must catch it: test-sim-slow-negative-torn.
s/^\(            slow_make(scan.word, ALB_RADARSCAN_WORDS, MOBOT_SCAN_SHIFT, ++scan_seq);\)$/\1\n            scan.word[ALB_RADARSCAN_WORDS \/ 2u] += 1u << MOBOT_SCAN_SHIFT;/
