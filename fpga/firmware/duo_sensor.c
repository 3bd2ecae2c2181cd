/*
 * duo_sensor.c -- board 'sensor' of the FPGA demonstration (fpga/duo.toml,
 * fpga/duo_system.v): exports Sample, a sequence number with check words
 * (board.h pair_value_t), as fast as it can.  STAT 0
 * bit 0 toggles every 2**DUO_BEAT_SHIFT (256) Exports (a heartbeat LED); a failed call ends the
 * program with its code in TOHOST (an error LED): 0x1 Export error, 0x3
 * attach error.
 */
#include "albatross.h"
#include "sensor.h"

#ifndef DUO_BEAT_SHIFT
#define DUO_BEAT_SHIFT 8   /* heartbeat: STAT 0 bit 0 toggles every 2**N */
#endif

int main(void)
{
    static pair_value_t v;
    uint32_t seq = 0u;

    if (alb_sensor_attach_all(BOARD_DPRAM_BASE) != ALB_OK)
        return 0x3;
    for (;;) {
        pair_make(&v, ++seq);
        if (MakeSampleAvailable(&v) != ALB_OK)
            return 0x1;
        board_stat(0u, seq >> DUO_BEAT_SHIFT);
    }
}
