/*
 * duo_actuator.c -- board 'actuator' of the FPGA demonstration
 * (fpga/duo.toml, fpga/duo_system.v): imports Sample and GlobalTime and
 * checks every Sample as the pair test's consumer does (pair_check,
 * soc/firmware/board.h): complete (check words), never going back, New exactly
 * when newer.  The all-zero start value of the RAM image passes once, as
 * sequence 0.  STAT 0
 * bit 0 toggles every 2**DUO_BEAT_SHIFT (256) New Samples (a heartbeat LED); a failed check
 * ends the program with code | sequence << 8 in TOHOST (an error LED):
 * 0x2 Import error, 0x3 torn value, 0x4 sequence went back, 0x5 New without
 * a newer value, 0x6 Old with a newer value, 0x7 attach error.
 */
#include "albatross.h"
#include "actuator.h"

#ifndef DUO_BEAT_SHIFT
#define DUO_BEAT_SHIFT 8   /* heartbeat: STAT 0 bit 0 toggles every 2**N */
#endif

int main(void)
{
    static Sample_msg m;
    static GlobalTime_msg gt;
    uint32_t last = 0u, news = 0u, code;
    int r;

    if (alb_actuator_attach_all(BOARD_DPRAM_BASE) != ALB_OK)
        return 0x7;
    for (;;) {
        r = alb_import(&alb_ch_Sample, &m);
        if (r != ALB_NEW && r != ALB_OLD)
            return 0x2 | (int)(last << 8);
        code = pair_check(&m.value, r, last, 1);
        if (code != 0u)
            return (int)code;
        if (r == ALB_NEW)
            ++news;
        last = m.value.seq;
        r = alb_import(&alb_ch_GlobalTime, &gt);
        if (r != ALB_NEW && r != ALB_OLD)
            return 0x2 | (int)(last << 8);
        board_stat(0u, news >> DUO_BEAT_SHIFT);
    }
}
