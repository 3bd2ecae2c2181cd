/*
 * mobot3_types.h -- the value types of the MOBOT-III-inspired example
 * (compiler/examples/mobot3*.toml).  Each has exactly the size the
 * description declares; the generated board headers check that.
 */
#ifndef MOBOT3_TYPES_H
#define MOBOT3_TYPES_H

#include <stdint.h>

/* One laser-radar shot: 32 ranges over the front half-plane. */
typedef struct {
    uint16_t range_mm[32];
} RadarShot;                                   /* 64 bytes */

/* Odometry: position in the plane and heading. */
typedef struct {
    int32_t x_mm;
    int32_t y_mm;
    int32_t heading_urad;
} RobotPosition;                               /* 12 bytes */

/* Wheel speeds for the motor controller. */
typedef struct {
    int16_t left_mm_s;
    int16_t right_mm_s;
    uint32_t flags;                            /* bit 0: enable, bit 1: brake */
} MotorCommand;                                /* 8 bytes */

/* The slow channels (sim/mobot3_slow.toml).  Every word of a value is
 * seq << SHIFT | index (sim/firmware/mobot_check.h), so a consumer catches a
 * torn, mixed or shifted value. */
typedef struct {
    uint32_t word[1024];                       /* the radar's full scan */
} RadarScanData;                               /* 4096 bytes */

typedef struct {
    uint32_t word[64];                         /* navigation's log */
} NavLogData;                                  /* 256 bytes */

#endif
