/*
 * duo_sensor.c -- board 'sensor' of the FPGA demonstration (fpga/duo.toml,
 * fpga/albatross_soc.v): exports Sample, a sequence number with check words
 * (board.h pair_value_t), as fast as it can, and imports GlobalTime.  STAT 0
 * bit 0 toggles every 4096 Exports (a heartbeat LED); a failed call ends the
 * program with its code in TOHOST (an error LED): 0x1 Export error, 0x2
 * GlobalTime Import error, 0x3 attach error.
 */
#include "albatross.h"
#include "sensor.h"

int main(void)
{
    static pair_value_t v;
    static GlobalTime_msg gt;
    uint32_t seq = 0u;
    int r;

    if (alb_sensor_attach_all(BOARD_DPRAM_BASE) != ALB_OK)
        return 0x3;
    for (;;) {
        pair_make(&v, ++seq);
        if (MakeSampleAvailable(&v) != ALB_OK)
            return 0x1;
        r = alb_import(&alb_ch_GlobalTime, &gt);
        if (r != ALB_NEW && r != ALB_OLD)
            return 0x2;
        board_stat(0u, seq >> 12);
    }
}
