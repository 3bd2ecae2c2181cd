/*
 * duo_sensor.c -- board 'sensor' of the FPGA demonstration (fpga/duo.toml,
 * fpga/duo_system.v): exports Sample, a sequence number with check words
 * (board.h pair_value_t), as fast as it can, and after every Export imports
 * GlobalTime (a four-slot channel: a wait-free Import).  The
 * accesses of each Import are counted outside the core, at its DPRAM port,
 * by the simulation harness (fpga/test_fpga_soc.cpp), against the bound the
 * compiler generated (sensor.h ALB_GLOBALTIME_IMPORT_MAX_ACCESSES); the
 * program keeps no count, so that it fits its 2 KB.  STAT 0 bit 0 toggles
 * every 2**DUO_BEAT_SHIFT (256) Exports (a heartbeat LED); a failed call ends
 * the program with its code in TOHOST (an error LED): 0x1 Export error, 0x3
 * attach error, 0x4 Import error.
 */
#include "albatross.h"
#include "sensor.h"

#ifndef DUO_BEAT_SHIFT
#define DUO_BEAT_SHIFT 8   /* heartbeat: STAT 0 bit 0 toggles every 2**N */
#endif

int main(void)
{
    static pair_value_t v;
    static GlobalTime_msg gt;
    uint32_t seq = 0u;

    if (alb_sensor_attach_all(BOARD_DPRAM_BASE) != ALB_OK)
        return 0x3;
    for (;;) {
        pair_make(&v, ++seq);
        if (MakeSampleAvailable(&v) != ALB_OK)
            return 0x1;
        board_stat(0u, seq >> DUO_BEAT_SHIFT);
        if (alb_import(&alb_ch_GlobalTime, &gt) < 0)
            return 0x4;
    }
}
