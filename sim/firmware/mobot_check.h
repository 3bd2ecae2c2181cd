/*
 * mobot_check.h -- payloads and on-core checks of the four-board PicoRV32
 * system (sim/pico_boards.v, sim/firmware/mobot_<board>.c).  Every value of
 * the MOBOT-III channels carries a sequence number and a checksum derived
 * from it, in the channel's own type (sim/mobot3_types.h):
 *   RadarShot      range_mm[0..1] = seq, [2..30] = mix words, [31] = rotate-xor sum
 *   RobotPosition  x = seq, y = mix(seq), heading = x ^ y ^ SALT
 *   MotorCommand   left/right = seq low/high half, flags = mix(seq) ^ SALT
 *   RadarScanData, NavLogData (the slow channels, sim/mobot3_slow.toml)
 *                  word k = seq << shift | k (slow_make, slow_ok0 below)
 * The all-zero start value of the RAM images counts as sequence 0 and is
 * accepted once, as the first New (the controller's cold-start Import
 * delivers it).  Exit code (TOHOST) = check | channel id << 4 | seq << 12:
 *   1 alb_import error, 2 attach error, 3 checksum, 4 sequence went back,
 *   5 New without a newer value, 6 Old with a newer value, 7 export error.
 * Every Import and Export is also reported to the harness as a board event
 * (board_event, soc/firmware/board.h): EVENT = kind | channel id << 4 |
 * cycles << 8, where cycles (24 bits, saturating) is the rdcycle count of the
 * call, and ARG as listed at MOBOT_EV_*.
 * Local time (built with -DALB_LOCAL_TIMER_ADDR=... and
 * c-driver/alb_clock.c; without it mobot_clock_* do nothing): each board
 * syncs its alb_clock_t on every New GlobalTime (taken_at, TIMER read right
 * after the Import) and, once per loop, reports alb_clock_now() as
 * MOBOT_EV_CLOCK with the clock's state (alb_clock_state) in the channel-id
 * field; the harness compares it with the controller's time at that
 * estimate's TIMER read (the board's last one before the event).
 * Sampling read: mobot_read is alb_read with the Import
 * event; mobot_now gives the global time it needs (the clock's estimate, or
 * the last GlobalTime value) and MOBOT_NOW_LEAD_CLOCKS how far that can lead
 * the controller's time.
 */
#ifndef MOBOT_CHECK_H
#define MOBOT_CHECK_H

#include <stdint.h>
#include "albatross.h"
#include "board.h"
#include "mobot3_types.h"

#define MOBOT_SALT     0x5A5A5A5Au
#define MOBOT_NEWS     40u   /* New values every consumer must see per channel */
#define MOBOT_EXPORTS  40u   /* exports before a producer reports */

/* Time budgets of the application, in controller clocks (50 MHz). */
#ifndef ALB_RADARSCAN_ID
#define MOBOT_RADAR_SCAN_CLOCKS 20000u  /* the radar publishes a map at least this often (400 us) */
#else
/* With the full scan (sim/mobot3_slow.toml) the radar's loop also fills and
 * exports 4 KB every 20 ms: a map at least every 2 ms. */
#define MOBOT_RADAR_SCAN_CLOCKS 100000u
#endif

/* Board event kinds (ARG). */
#define MOBOT_EV_NEW     1u  /* alb_import returned New (taken_at)            */
#define MOBOT_EV_OLD     2u  /* alb_import returned Old (taken_at)            */
#define MOBOT_EV_ERROR   3u  /* alb_import returned an error (the error)      */
#define MOBOT_EV_BEGIN   4u  /* an Export begins (its sequence number)        */
#define MOBOT_EV_EXPORT  5u  /* an Export returned (its sequence number)      */
#define MOBOT_EV_STALE   6u  /* a consumer found its channel stale (the age)  */
#define MOBOT_EV_FRESH   7u  /* ... and fresh again (the age)                 */
#define MOBOT_EV_STATUS  8u  /* a new STATUS (retries summed over channels;
                                the cycles field: abandoned summed)           */
#define MOBOT_EV_CLOCK   9u  /* the global-time estimate alb_clock_now() (the
                                id field: alb_clock_state)                    */
#define MOBOT_EV_MODE   10u  /* a New Mode value (the id field: the mode; ARG:
                                the time its first cycle began)               */

/* Schedule modes (a description with the modes cruise and dock,
 * sim/mobot3_modes.toml): navigation asks for dock after about
 * MOBOT_CRUISE_CLOCKS in cruise and for cruise after about MOBOT_DOCK_CLOCKS
 * in dock (controller clocks from the mode's start, as Mode publishes it;
 * each stay drawn up to MOBOT_MODE_SPREAD_CLOCKS longer, so the requests fall
 * at varied places of the cycle), and asks again if the mode has not changed
 * MOBOT_MODE_RETRY_CLOCKS after a request. */
#ifndef ALB_RADARSCAN_ID
#define MOBOT_CRUISE_CLOCKS     300000u  /* 6 ms */
#else
/* With the slow channels (cruise only): stays of 60 ms in cruise, so the
 * 20 ms scan and the 100 ms log are delivered and judged between switches. */
#define MOBOT_CRUISE_CLOCKS    3000000u  /* 60 ms */
#endif
#define MOBOT_DOCK_CLOCKS       200000u  /* 4 ms */
#define MOBOT_MODE_SPREAD_CLOCKS 131072u /* 2.6 ms, a power of two */
#define MOBOT_MODE_RETRY_CLOCKS  20000u  /* 400 us: far above a switch's latency */

#define MOBOT_CODE(chk, id, seq) ((uint32_t)(chk) | ((uint32_t)(id) << 4) | ((uint32_t)(seq) << 12))

static inline void mobot_tohost(uint32_t code)
{
    *(volatile uint32_t *)(uintptr_t)BOARD_TOHOST = code;
}

static inline void mobot_event(uint32_t kind, uint32_t id, uint32_t cycles, uint32_t arg)
{
    if (cycles > 0xFFFFFFu)
        cycles = 0xFFFFFFu;
    board_event(kind | id << 4 | cycles << 8, arg);
}

/* alb_import with its event; taken_at is the message's taken_at field. */
static inline int mobot_import(alb_channel_t *ch, uint32_t id, void *msg, const uint32_t *taken_at)
{
    uint32_t c0 = board_cycles(), c1;
    int r = alb_import(ch, msg);
    c1 = board_cycles();
    if (r == ALB_NEW || r == ALB_OLD)
        mobot_event(r == ALB_NEW ? MOBOT_EV_NEW : MOBOT_EV_OLD, id, c1 - c0, *taken_at);
    else
        mobot_event(MOBOT_EV_ERROR, id, c1 - c0, (uint32_t)r);
    return r;
}

/* alb_read (the sampling read) with the same event as mobot_import. */
static inline int mobot_read(alb_channel_t *ch, uint32_t id, void *msg, const uint32_t *taken_at,
                             uint32_t max_age, uint32_t now, alb_sample_t *st)
{
    uint32_t c0 = board_cycles(), c1;
    int r = alb_read(ch, msg, max_age, now, st);
    c1 = board_cycles();
    if (r == ALB_NEW || r == ALB_OLD)
        mobot_event(r == ALB_NEW ? MOBOT_EV_NEW : MOBOT_EV_OLD, id, c1 - c0, *taken_at);
    else
        mobot_event(MOBOT_EV_ERROR, id, c1 - c0, (uint32_t)r);
    return r;
}

#ifdef ALB_LOCAL_TIMER_ADDR
#include "alb_clock.h"
#include "alb_port.h"
typedef alb_clock_t mobot_clock_t;
static uint32_t mobot_sync_cycles;  /* rdcycle count of the last alb_clock_sync */
/* After the Import of GlobalTime that returned r: a New value is a sample. */
static inline void mobot_clock_sync(mobot_clock_t *clk, int r, uint32_t taken_at)
{
    uint32_t c0;
    if (r != ALB_NEW)
        return;
    c0 = board_cycles();
    alb_clock_sync(clk, taken_at, alb_local_time());
    mobot_sync_cycles = board_cycles() - c0;
}
/* The estimate now, as an event (nothing before the first sample); the
 * cycles field: the rdcycle counts of this alb_clock_now (bits 0..11) and
 * of the last alb_clock_sync (bits 12..23), each saturating at 4095. */
static inline void mobot_clock_report(const mobot_clock_t *clk)
{
    uint32_t est, c0, c1;
    if (alb_clock_state(clk) == ALB_CLOCK_EMPTY)
        return;
    c0 = board_cycles();
    est = alb_clock_now(clk);
    c1 = board_cycles() - c0;
    mobot_event(MOBOT_EV_CLOCK, (uint32_t)alb_clock_state(clk),
                (c1 > 4095u ? 4095u : c1) | (mobot_sync_cycles > 4095u ? 4095u : mobot_sync_cycles) << 12, est);
}
#define mobot_clock_init(clk) alb_clock_init(clk)
/* The global time now, for alb_read: the clock's estimate once it has a
 * sample, else the last GlobalTime value gt.  The estimate can lead the
 * controller's time only through its rate error: by at most rho * (2 W + T)
 * (docs/robot.md, Local time: rho = 250 ppm, W = ALB_CLOCK_WINDOW, T the
 * longest gap between two New GlobalTime values, taken <= 2 W here), which
 * a sampling read's refresh bound must allow for. */
#define MOBOT_NOW_LEAD_CLOCKS ((4u * ALB_CLOCK_WINDOW + 3999u) / 4000u)
static inline uint32_t mobot_now(const mobot_clock_t *clk, uint32_t gt)
{
    return alb_clock_state(clk) == ALB_CLOCK_EMPTY ? gt : alb_clock_now(clk);
}
#else
typedef int mobot_clock_t;
#define mobot_clock_init(clk)           ((void)(clk))
#define mobot_clock_sync(clk, r, t)     ((void)(clk), (void)(r), (void)(t))
#define mobot_clock_report(clk)         ((void)(clk))
/* Without a clock the global time now is the last GlobalTime value: a
 * nominal slot start at or before its Import, so it never leads. */
#define MOBOT_NOW_LEAD_CLOCKS 0u
#define mobot_now(clk, gt)              ((void)(clk), (gt))
#endif

/* alb_export with its two events (begin, end). */
static inline int mobot_export(alb_channel_t *ch, uint32_t id, const void *v, uint32_t seq)
{
    uint32_t c0, c1;
    int r;
    mobot_event(MOBOT_EV_BEGIN, id, 0u, seq);
    c0 = board_cycles();
    r = alb_export(ch, v);
    c1 = board_cycles();
    mobot_event(MOBOT_EV_EXPORT, id, c1 - c0, seq);
    return r;
}

static inline uint32_t mobot_mix(uint32_t x)
{
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return x + 0x9E3779B9u;
}

static inline void radar_make(RadarShot *v, uint32_t seq)
{
    uint32_t k, h = seq, sum = 0u;
    v->range_mm[0] = (uint16_t)seq;
    v->range_mm[1] = (uint16_t)(seq >> 16);
    for (k = 2u; k < 31u; ++k) {
        h = mobot_mix(h);
        v->range_mm[k] = (uint16_t)h;
    }
    for (k = 0u; k < 31u; ++k)
        sum = ((sum << 5) | (sum >> 27)) ^ v->range_mm[k];   /* order-sensitive, no multiply */
    v->range_mm[31] = (uint16_t)(sum ^ MOBOT_SALT);
}

static inline uint32_t radar_seq(const RadarShot *v)
{
    return v->range_mm[0] | ((uint32_t)v->range_mm[1] << 16);
}

static inline int radar_ok(const RadarShot *v)
{
    RadarShot w;
    uint32_t k;
    radar_make(&w, radar_seq(v));
    for (k = 0u; k < 32u; ++k)
        if (w.range_mm[k] != v->range_mm[k])
            return 0;
    return 1;
}

static inline void position_make(RobotPosition *v, uint32_t seq)
{
    v->x_mm = (int32_t)seq;
    v->y_mm = (int32_t)mobot_mix(seq);
    v->heading_urad = (int32_t)(seq ^ mobot_mix(seq) ^ MOBOT_SALT);
}

static inline int position_ok(const RobotPosition *v)
{
    RobotPosition w;
    position_make(&w, (uint32_t)v->x_mm);
    return w.y_mm == v->y_mm && w.heading_urad == v->heading_urad;
}

static inline void motor_make(MotorCommand *v, uint32_t seq)
{
    v->left_mm_s = (int16_t)(uint16_t)seq;
    v->right_mm_s = (int16_t)(uint16_t)(seq >> 16);
    v->flags = mobot_mix(seq) ^ MOBOT_SALT;
}

static inline uint32_t motor_seq(const MotorCommand *v)
{
    return (uint16_t)v->left_mm_s | ((uint32_t)(uint16_t)v->right_mm_s << 16);
}

/* The start image (all zero) is sequence 0 and passes as such. */
static inline int radar_ok0(const RadarShot *v)
{
    uint32_t k, z = 0u;
    for (k = 0u; k < 32u; ++k) z |= v->range_mm[k];
    return z == 0u || radar_ok(v);
}
static inline int position_ok0(const RobotPosition *v)
{
    return (v->x_mm == 0 && v->y_mm == 0 && v->heading_urad == 0) || position_ok(v);
}
static inline int motor_ok0(const MotorCommand *v)
{
    return (v->left_mm_s == 0 && v->right_mm_s == 0 && v->flags == 0u) ||
           v->flags == (mobot_mix(motor_seq(v)) ^ MOBOT_SALT);
}

/* The slow channels (sim/mobot3_slow.toml, when the board's header has
 * them): RadarScan (radar -> navigation, 1024 words, a new scan every
 * MOBOT_SCAN_PERIOD_CLOCKS) and NavLog (navigation -> odometry, 64 words,
 * every MOBOT_LOG_PERIOD_CLOCKS).  Word k of value seq is seq << shift | k
 * (shift: the index bits), seq counting from 1; the start image (all zero)
 * is sequence 0.  slow_ok0 finds any word of another value (torn or mixed:
 * fragments of two scans), out of place (shifted) or wrong: exit code 3
 * (checksum) with the channel's id.  The consumers import them every
 * MOBOT_SLOW_EVERY-th loop (an Import copies the whole value, Old too). */
#define MOBOT_SCAN_SHIFT         10u       /* RadarScanData: 1024 words */
#define MOBOT_LOG_SHIFT           6u       /* NavLogData: 64 words */
#define MOBOT_SCAN_PERIOD_CLOCKS 1000000u  /* 20 ms */
#define MOBOT_LOG_PERIOD_CLOCKS  5000000u  /* 100 ms */
#define MOBOT_SLOW_EVERY         16u       /* a power of two */
#define MOBOT_SCAN_NEWS           3u       /* navigation's quota: New scans (the start value's and two) */
#define MOBOT_LOG_NEWS            1u       /* odometry's quota: New logs */

static inline void slow_make(uint32_t *w, uint32_t n, uint32_t shift, uint32_t seq)
{
    uint32_t k;
    for (k = 0u; k < n; ++k)
        w[k] = seq << shift | k;
}

static inline uint32_t slow_seq(const uint32_t *w, uint32_t shift)
{
    return w[0] >> shift;
}

static inline int slow_ok0(const uint32_t *w, uint32_t n, uint32_t shift)
{
    uint32_t k, z = 0u, top = w[0] & ~((1u << shift) - 1u);
    for (k = 0u; k < n; ++k)
        z |= w[k];
    if (z == 0u)
        return 1;                      /* the start image */
    if (top == 0u)
        return 0;                      /* sequence 0 with words that are not 0 */
    for (k = 0u; k < n; ++k)
        if (w[k] != (top | k))
            return 0;
    return 1;
}

/* Per imported channel: the last sequence, New count, whether any New came. */
typedef struct {
    uint32_t last, news, calls, started;
} mobot_track_t;

/* Check one Import result r (ALB_NEW / ALB_OLD / error) of sequence seq with
 * checksum verdict ok.  Returns 0 or the exit code. */
static inline uint32_t mobot_check(mobot_track_t *t, uint32_t id, int r, int ok, uint32_t seq)
{
    ++t->calls;
    if (r != ALB_NEW && r != ALB_OLD)
        return MOBOT_CODE(1, id, t->last);
    if (!ok)
        return MOBOT_CODE(3, id, seq);
    if (seq < t->last)
        return MOBOT_CODE(4, id, seq);
    if (r == ALB_NEW) {
        /* the first New may be the start value again (sequence 0) */
        if (seq == t->last && !(seq == 0u && !t->started))
            return MOBOT_CODE(5, id, seq);
        t->started = 1u;
        ++t->news;
    } else if (seq != t->last) {
        return MOBOT_CODE(6, id, seq);
    }
    t->last = seq;
    return 0u;
}

#endif
