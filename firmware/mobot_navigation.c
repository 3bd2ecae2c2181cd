/*
 * mobot_navigation.c -- board 'navigation' of the four-board PicoRV32 system
 * (tb/rtl/pico_boards.v): imports RadarMap, Position and GlobalTime, exports
 * MotorCmd, through the compiler-generated navigation.c.  Reports 0 after
 * MOBOT_NEWS New values of every import and MOBOT_EXPORTS exports, then keeps
 * going.  STAT: 0 RadarMap New, 1 Position New, 2 GlobalTime New, 3 exports.
 * Checks: firmware/mobot_check.h.
 */
#include "albatross.h"
#include "navigation.h"
#include "mobot_check.h"

int main(void)
{
    static RadarMap_msg map;
    static Position_msg pos;
    static GlobalTime_msg gt;
    static MotorCommand cmd;
    mobot_track_t tr = {0u, 0u, 0u, 0u}, tp = {0u, 0u, 0u, 0u}, tt = {0u, 0u, 0u, 0u};
    uint32_t seq = 0u, code, reported = 0u;
    int r;

    r = alb_navigation_attach_all(BOARD_DPRAM_BASE);
    if (r != ALB_OK)
        return (int)MOBOT_CODE(2, 0xfu, (uint32_t)-r);
    for (;;) {
        r = alb_import(&alb_ch_RadarMap, &map);
        code = mobot_check(&tr, ALB_RADARMAP_ID, r, radar_ok0(&map.value), radar_seq(&map.value));
        if (code)
            return (int)code;
        r = alb_import(&alb_ch_Position, &pos);
        code = mobot_check(&tp, ALB_POSITION_ID, r, position_ok0(&pos.value), (uint32_t)pos.value.x_mm);
        if (code)
            return (int)code;
        r = alb_import(&alb_ch_GlobalTime, &gt);
        code = mobot_check(&tt, ALB_GLOBALTIME_ID, r, 1, gt.value);
        if (code)
            return (int)code;
        motor_make(&cmd, ++seq);
        if (MakeMotorCmdAvailable(&cmd) != ALB_OK)
            return (int)MOBOT_CODE(7, ALB_MOTORCMD_ID, seq);
        if (!reported && seq >= MOBOT_EXPORTS && tr.news >= MOBOT_NEWS && tp.news >= MOBOT_NEWS &&
            tt.news >= MOBOT_NEWS) {
            board_stat(0u, tr.news);
            board_stat(1u, tp.news);
            board_stat(2u, tt.news);
            board_stat(3u, seq);
            mobot_tohost(0u);
            reported = 1u;
        }
    }
}
