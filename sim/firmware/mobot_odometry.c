/*
 * mobot_odometry.c -- board 'odometry' of the four-board PicoRV32 system
 * (sim/pico_boards.v): exports Position, imports GlobalTime through the
 * compiler-generated odometry.c.  Reports 0 after MOBOT_EXPORTS exports and
 * MOBOT_NEWS New times, then keeps exporting.  STAT: 1 GlobalTime New,
 * 3 exports.  Checks and events: sim/firmware/mobot_check.h.  With the slow
 * channels (sim/mobot3_slow.toml: ALB_NAVLOG_ID defined) it also imports
 * and checks navigation's log NavLog every MOBOT_SLOW_EVERY-th loop, and
 * reports 0 only after MOBOT_LOG_NEWS New logs too.
 */
#include "albatross.h"
#include "odometry.h"
#include "mobot_check.h"

int main(void)
{
    static RobotPosition p;
    static GlobalTime_msg gt;
    static mobot_clock_t clk;
    mobot_track_t tt = {0u, 0u, 0u, 0u};
    uint32_t seq = 0u, code, reported = 0u, k;
    int r;
#ifdef ALB_NAVLOG_ID
    static NavLog_msg lg;
    mobot_track_t tl = {0u, 0u, 0u, 0u};
#endif

#ifdef MOBOT_COLD_START
    r = alb_odometry_init_all(BOARD_DPRAM_BASE);     /* a zeroed RAM, no image */
#else
    r = alb_odometry_attach_all(BOARD_DPRAM_BASE);
#endif
    if (r != ALB_OK)
        return (int)MOBOT_CODE(2, 0xfu, (uint32_t)-r);
    mobot_clock_init(&clk);
    for (;;) {
        mobot_clock_report(&clk);
        position_make(&p, ++seq);
        if (mobot_export(&alb_ch_Position, ALB_POSITION_ID, &p, seq) != ALB_OK)
            return (int)MOBOT_CODE(7, ALB_POSITION_ID, seq);
        r = mobot_import(&alb_ch_GlobalTime, ALB_GLOBALTIME_ID, &gt, &gt.taken_at);
        mobot_clock_sync(&clk, r, gt.taken_at);
        code = mobot_check(&tt, ALB_GLOBALTIME_ID, r, 1, gt.value);
        if (code)
            return (int)code;
#ifdef ALB_NAVLOG_ID
        if ((seq & (MOBOT_SLOW_EVERY - 1u)) == 1u) {
            r = mobot_import(&alb_ch_NavLog, ALB_NAVLOG_ID, &lg, &lg.taken_at);
            code = mobot_check(&tl, ALB_NAVLOG_ID, r, slow_ok0(lg.value.word, ALB_NAVLOG_WORDS, MOBOT_LOG_SHIFT),
                               slow_seq(lg.value.word, MOBOT_LOG_SHIFT));
            if (code)
                return (int)code;
        }
#endif
        for (k = seq & 255u; k != 0u; --k)   /* vary the phase against the controller */
            __asm__ volatile("" ::: "memory");
        if (!reported && seq >= MOBOT_EXPORTS && tt.news >= MOBOT_NEWS
#ifdef ALB_NAVLOG_ID
            && tl.news >= MOBOT_LOG_NEWS
#endif
            ) {
            board_stat(1u, tt.news);
            board_stat(3u, seq);
            mobot_tohost(0u);
            reported = 1u;
        }
    }
}
