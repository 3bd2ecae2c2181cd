/*
 * duo_actuator.c -- board 'actuator' of the FPGA demonstration
 * (fpga/duo.toml, fpga/albatross_soc.v): imports Sample and GlobalTime and
 * checks every Sample as the pair test's consumer does (firmware/consumer.c):
 * complete (check words), never going back, New exactly when newer.  The
 * all-zero start value of the RAM image passes once, as sequence 0.  STAT 0
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

static int zero(const pair_value_t *v)
{
    return (v->seq | v->h1 | v->h2 | v->sum) == 0u;
}

int main(void)
{
    static Sample_msg m;
    static GlobalTime_msg gt;
    uint32_t last = 0u, news = 0u;
    int r;

    if (alb_actuator_attach_all(BOARD_DPRAM_BASE) != ALB_OK)
        return 0x7;
    for (;;) {
        r = alb_import(&alb_ch_Sample, &m);
        if (r != ALB_NEW && r != ALB_OLD)
            return 0x2 | (int)(last << 8);
        if (!pair_ok(&m.value) && !(zero(&m.value) && last == 0u))
            return 0x3 | (int)(last << 8);
        if (m.value.seq < last)
            return 0x4 | (int)(m.value.seq << 8);
        if (r == ALB_NEW && m.value.seq == last && last != 0u)
            return 0x5 | (int)(last << 8);
        if (r == ALB_OLD && m.value.seq != last)
            return 0x6 | (int)(m.value.seq << 8);
        if (r == ALB_NEW)
            ++news;
        last = m.value.seq;
        r = alb_import(&alb_ch_GlobalTime, &gt);
        if (r != ALB_NEW && r != ALB_OLD)
            return 0x2 | (int)(last << 8);
        board_stat(0u, news >> DUO_BEAT_SHIFT);
    }
}
