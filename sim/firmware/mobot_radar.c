/*
 * mobot_radar.c -- board 'radar' of the four-board PicoRV32 system
 * (sim/pico_boards.v): exports RadarMap, imports Position and GlobalTime
 * through the compiler-generated radar.c (build/schedule/mobot3/).  Reports 0
 * after MOBOT_EXPORTS exports and MOBOT_NEWS New values per import, then
 * keeps going (a later failed check overwrites TOHOST).  STAT: 0 Position
 * New, 1 GlobalTime New, 2 -, 3 exports.  Checks and events:
 * sim/firmware/mobot_check.h.  With the slow channels (sim/mobot3_slow.toml:
 * ALB_RADARSCAN_ID defined) it also exports the full scan RadarScan at the
 * start and then every MOBOT_SCAN_PERIOD_CLOCKS of the global time.
 */
#include "albatross.h"
#include "radar.h"
#include "mobot_check.h"

int main(void)
{
    static RadarShot shot;
    static Position_msg pos;
    static GlobalTime_msg gt;
    static mobot_clock_t clk;
    mobot_track_t tp = {0u, 0u, 0u, 0u}, tt = {0u, 0u, 0u, 0u};
    uint32_t seq = 0u, code, reported = 0u;
    int r;
#ifdef ALB_RADARSCAN_ID
    static RadarScanData scan;
    uint32_t scan_seq = 0u, scan_at = 0u;
#endif

#ifdef MOBOT_COLD_START
    r = alb_radar_init_all(BOARD_DPRAM_BASE);     /* a zeroed RAM, no image */
#else
    r = alb_radar_attach_all(BOARD_DPRAM_BASE);
#endif
    if (r != ALB_OK)
        return (int)MOBOT_CODE(2, 0xfu, (uint32_t)-r);
    mobot_clock_init(&clk);
    for (;;) {
        mobot_clock_report(&clk);
        radar_make(&shot, ++seq);
        if (mobot_export(&alb_ch_RadarMap, ALB_RADARMAP_ID, &shot, seq) != ALB_OK)
            return (int)MOBOT_CODE(7, ALB_RADARMAP_ID, seq);
#ifdef ALB_RADARSCAN_ID
        if (scan_seq == 0u || gt.value - scan_at >= MOBOT_SCAN_PERIOD_CLOCKS) {
            scan_at = gt.value;
            slow_make(scan.word, ALB_RADARSCAN_WORDS, MOBOT_SCAN_SHIFT, ++scan_seq);
            if (mobot_export(&alb_ch_RadarScan, ALB_RADARSCAN_ID, &scan, scan_seq) != ALB_OK)
                return (int)MOBOT_CODE(7, ALB_RADARSCAN_ID, scan_seq);
        }
#endif
        r = mobot_import(&alb_ch_Position, ALB_POSITION_ID, &pos, &pos.taken_at);
        code = mobot_check(&tp, ALB_POSITION_ID, r, position_ok0(&pos.value), (uint32_t)pos.value.x_mm);
        if (code)
            return (int)code;
        r = mobot_import(&alb_ch_GlobalTime, ALB_GLOBALTIME_ID, &gt, &gt.taken_at);
        mobot_clock_sync(&clk, r, gt.taken_at);
        code = mobot_check(&tt, ALB_GLOBALTIME_ID, r, 1, gt.value);
        if (code)
            return (int)code;
        if (!reported && seq >= MOBOT_EXPORTS && tp.news >= MOBOT_NEWS && tt.news >= MOBOT_NEWS) {
            board_stat(0u, tp.news);
            board_stat(1u, tt.news);
            board_stat(3u, seq);
            mobot_tohost(0u);
            reported = 1u;
        }
    }
}
