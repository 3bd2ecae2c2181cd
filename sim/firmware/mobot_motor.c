/*
 * mobot_motor.c -- board 'motor' of the four-board PicoRV32 system
 * (sim/pico_boards.v): imports MotorCmd and GlobalTime through the
 * compiler-generated motor.c.  Reports 0 after MOBOT_NEWS New values of
 * each, then keeps checking.  STAT: 0 MotorCmd New, 1 GlobalTime New.
 * Checks and events: sim/firmware/mobot_check.h.
 */
#include "albatross.h"
#include "motor.h"
#include "mobot_check.h"

int main(void)
{
    static MotorCmd_msg cmd;
    static GlobalTime_msg gt;
    static mobot_clock_t clk;
    mobot_track_t tm = {0u, 0u, 0u, 0u}, tt = {0u, 0u, 0u, 0u};
    uint32_t code, reported = 0u;
    int r;

#ifdef MOBOT_COLD_START
    r = alb_motor_init_all(BOARD_DPRAM_BASE);     /* a zeroed RAM, no image */
#else
    r = alb_motor_attach_all(BOARD_DPRAM_BASE);
#endif
    if (r != ALB_OK)
        return (int)MOBOT_CODE(2, 0xfu, (uint32_t)-r);
    mobot_clock_init(&clk);
    for (;;) {
        mobot_clock_report(&clk);
        r = mobot_import(&alb_ch_MotorCmd, ALB_MOTORCMD_ID, &cmd, &cmd.taken_at);
        code = mobot_check(&tm, ALB_MOTORCMD_ID, r, motor_ok0(&cmd.value), motor_seq(&cmd.value));
        if (code)
            return (int)code;
        r = mobot_import(&alb_ch_GlobalTime, ALB_GLOBALTIME_ID, &gt, &gt.taken_at);
        mobot_clock_sync(&clk, r, gt.taken_at);
        code = mobot_check(&tt, ALB_GLOBALTIME_ID, r, 1, gt.value);
        if (code)
            return (int)code;
        if (!reported && tm.news >= MOBOT_NEWS && tt.news >= MOBOT_NEWS) {
            board_stat(0u, tm.news);
            board_stat(1u, tt.news);
            mobot_tohost(0u);
            reported = 1u;
        }
    }
}
