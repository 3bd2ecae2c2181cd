/*
 * albatross.h -- the ALBATROSS channel: the paper's three-buffer kind (seed
 * 3.1, figures 2-4) and the wait-free four-slot kind (Simpson's
 * four-slot mechanism on single-writer bytes, docs/four_slot.md).
 *
 * A channel carries one variable from one producer to one consumer through a
 * dual-ported RAM, without locks, interrupts or waiting: alb_export() never
 * blocks and alb_import() always returns a complete, published value.  The
 * memory layout is in albatross_layout.h; all RAM accesses go through the
 * port layer (alb_port.h).  C99, freestanding, no heap.
 *
 * Start-up.  Each side owns the control bytes it writes: the producer Actual
 * (and, four-slot, Slot0 and Slot1), the consumer ReadLocked.  A RAM image can
 * set them all to Buffer1 (the paper, figure 2; the schedule compiler emits
 * one); then each side calls alb_*_attach().  Without the image (a zeroed
 * RAM, a cold start) each side calls its own init, in either order, while the
 * other may already run: alb_producer_init() writes the initial value into
 * Buffer1 and then Actual (and the slot bytes), alb_consumer_init() writes
 * ReadLocked.  A byte its writer has not set yet holds ALB_NOT_STARTED (0),
 * which is no error: an Import that finds Actual = 0 returns ALB_OLD and
 * reads nothing (*dst unchanged: nothing has been published yet); an Export
 * that finds ReadLocked = 0 returns ALB_OK and picks the buffer that
 * ReadLocked = Buffer1 (the value the consumer's init stores) gives, so the
 * channel runs exactly as from the RAM image, except that the consumer reads
 * nothing before the producer's init.  A consumer that starts later is safe:
 * it reads a buffer only after its own ReadLocked store and a load of Actual
 * that confirms it.  A side that restarts while its partner runs calls
 * alb_*_attach() instead, which recovers its private copy from the RAM (it
 * needs its own bytes set: ALB_ERR_ARG for 0, call the init).  docs/protocol.md, "Cold
 * start", states the whole contract, the controller's part included.
 *
 * Each side keeps a private copy (shadow) of the control byte it owns, so in
 * the uncontended case the RAM accesses beyond the payload are:
 *   alb_export                 2  (load ReadLocked, store Actual)
 *   alb_import, no new data    1  (load Actual)
 *   alb_import, new data       3  (load Actual, store ReadLocked, load Actual)
 * and the payload takes ceil(size / 4) word accesses.
 *
 * The four-slot kind (alb_channel_setup_kind(..., ALB_FOUR_SLOT)) uses the
 * reserved bytes 2 and 3 as the producer's slot bytes and a fourth buffer
 * (ALB_FS_CHANNEL_BYTES).  Its Import is wait-free, whatever the producer does:
 *   alb_export                 3  (load control word, store Slot, store Actual)
 *   alb_import, no new data    1  (load control word)
 *   alb_import, otherwise      3  (load control word, store ReadLocked,
 *                                  load control word)
 * plus the payload.  Both sides of a channel must use the same kind (the
 * compiler guarantees it).  A four-slot consumer that restarts
 * (alb_consumer_attach) has forgotten the last value it read: its first
 * Import returns ALB_NEW.
 *
 * Kinds compiled in.  A board with little program RAM may build the driver
 * (albatross.c) with only the kinds and directions it uses, each macro 0 or
 * 1, default 1:
 *   ALB_THREE_BUFFER_EXPORT  ALB_THREE_BUFFER_IMPORT
 *   ALB_FOUR_SLOT_EXPORT     ALB_FOUR_SLOT_IMPORT
 * A direction compiled out is not linked, and every call for it returns
 * ALB_ERR_ARG, never a wrong result: alb_producer_init / _attach and
 * alb_export for an Export, alb_consumer_init / _attach, alb_import and
 * alb_read for an Import (no RAM access).  alb_channel_setup_kind accepts
 * both kinds whatever the build.  The FPGA sensor (tools/mk/fpga.mk) is
 * built with -DALB_FOUR_SLOT_EXPORT=0 -DALB_THREE_BUFFER_IMPORT=0.
 */
#ifndef ALBATROSS_H
#define ALBATROSS_H

#include <stdbool.h>
#include <stdint.h>
#include "albatross_layout.h"

/* The kinds compiled in, per direction (see above): 1 each unless the build
 * says otherwise. */
#ifndef ALB_THREE_BUFFER_EXPORT
#define ALB_THREE_BUFFER_EXPORT 1
#endif
#ifndef ALB_THREE_BUFFER_IMPORT
#define ALB_THREE_BUFFER_IMPORT 1
#endif
#ifndef ALB_FOUR_SLOT_EXPORT
#define ALB_FOUR_SLOT_EXPORT 1
#endif
#ifndef ALB_FOUR_SLOT_IMPORT
#define ALB_FOUR_SLOT_IMPORT 1
#endif

/* Results.  alb_import: ALB_OLD or ALB_NEW (the paper, figure 3: Old, New). */
enum {
    ALB_OK          = 0,   /* alb_export and set-up: done                      */
    ALB_OLD         = 0,   /* alb_import: value already read before            */
    ALB_NEW         = 1,   /* alb_import: value never read before              */
    ALB_ERR_CORRUPT = -1,  /* the partner's control byte holds a value that
                              names no buffer and is not ALB_NOT_STARTED (0):
                              4..255 (four-slot 5..255, a slot byte 2..255),
                              written by a faulty partner or a RAM fault.  A
                              partner that has not started yet leaves 0,
                              which is not an error; see the functions        */
    ALB_ERR_ARG     = -2   /* bad argument: misaligned base, size 0, or the
                              side was never initialised or attached           */
};

/* Channel kinds (alb_channel_setup_kind). */
enum { ALB_THREE_BUFFER = 0, ALB_FOUR_SLOT = 1 };

typedef struct alb_channel {
    uintptr_t base;        /* channel address in this CPU's view of the RAM   */
    uint32_t  size;        /* payload bytes                                    */
    uint8_t   kind;        /* ALB_THREE_BUFFER or ALB_FOUR_SLOT                */
    uint8_t   actual;      /* producer's private copy of Actual (0: none)      */
    uint8_t   read_locked; /* consumer's private copy of ReadLocked (0: none)  */
    /* The four-slot kind keeps actual and read_locked at 0 and uses these: */
    uint8_t   fs_actual;   /* producer's private copy of Actual (0: none)      */
    uint8_t   fs_read_locked; /* consumer's private copy of ReadLocked (0: none) */
    uint8_t   last;        /* consumer: the buffer it read last (0: none,
                              after a restart)                                 */
    uint8_t   slot[2];     /* producer: private copies of Slot0 and Slot1      */
    uint8_t   received;    /* consumer, alb_read: a New value came since
                              alb_channel_setup (0: never received)            */
} alb_channel_t;

/* Describe a three-buffer channel; no RAM access.  ALB_ERR_ARG if base is
 * not 4-aligned or size is 0. */
int alb_channel_setup(alb_channel_t *ch, uintptr_t base, uint32_t size);
/* The same for either kind (ALB_THREE_BUFFER, ALB_FOUR_SLOT); ALB_ERR_ARG
 * also for an unknown kind. */
int alb_channel_setup_kind(alb_channel_t *ch, uintptr_t base, uint32_t size, unsigned kind);

/* Producer, cold start: Buffer1 := *initial, (four-slot: Slot0 := Slot1 :=
 * 0,) Actual := Buffer1. */
int alb_producer_init(alb_channel_t *ch, const void *initial);
/* Producer, restart while the consumer runs: private copies := Actual (and
 * four-slot: Slot0, Slot1, from one load of the control word).
 * ALB_ERR_ARG if Actual is 0 (never started: call alb_producer_init),
 * ALB_ERR_CORRUPT if it holds no valid index (or a slot byte no slot). */
int alb_producer_attach(alb_channel_t *ch);
/* Consumer, cold start: ReadLocked := Buffer1 (Buffer1's value counts as
 * read). */
int alb_consumer_init(alb_channel_t *ch);
/* Consumer, restart: private copy := ReadLocked (ALB_ERR_ARG if 0, never
 * started: call alb_consumer_init; ALB_ERR_CORRUPT if out of range).
 * Four-slot: the last value read is forgotten, the next Import returns New. */
int alb_consumer_attach(alb_channel_t *ch);

/* Import (the paper, figure 3): copy the newest published value into *dst.
 * Returns ALB_NEW or ALB_OLD.  ALB_OLD with *dst unchanged and no buffer read
 * if Actual is 0 (nothing published yet).  ALB_ERR_CORRUPT if Actual is out
 * of range (4..255): then no buffer is read and *dst is unchanged.  Three-buffer: lock-free, not
 * wait-free: the selection loop repeats only while the producer publishes
 * again between two loads of Actual.  Four-slot: wait-free, 1 + W or 3 + W
 * accesses; ALB_ERR_CORRUPT also for a slot byte that is not 0 or 1. */
int alb_import(alb_channel_t *ch, void *dst);

/* Export (the paper, figure 4): publish *src.  Never blocks; a fixed number
 * of accesses.  Returns ALB_OK (also when ReadLocked is 0: the consumer has
 * not started), or ALB_ERR_CORRUPT if ReadLocked was out of range (4..255,
 * four-slot 5..255): the value is published all the same (a faulty consumer
 * must not stop the producer), into a buffer other than Actual. */
int alb_export(alb_channel_t *ch, const void *src);

/*
 * Sampling read, beside the paper's New/Old: the status
 * an ARINC 653 sampling port or an AUTOSAR last-is-best receiver gives.  For
 * a destination channel of the controller, whose payload ends with the word
 * taken_at (the controller's global time when it took the value).
 *
 *   r = alb_read(ch, dst, max_age_clocks, now, &st);
 *
 * Imports like alb_import (same result, same *dst) and then sets st:
 *   st.age_clocks  now - taken_at, modulo 2^32, 0 if taken_at is after now
 *   st.is_new      1 if the Import returned ALB_NEW
 *   st.status      ALB_SAMPLE_NEVER  no New value since alb_channel_setup
 *                                    (*dst holds the start image's value, or
 *                                    after a restart one of unknown origin)
 *                  ALB_SAMPLE_STALE  age_clocks > max_age_clocks (New or Old)
 *                  ALB_SAMPLE_NEW    fresh and never read before
 *                  ALB_SAMPLE_OLD    fresh and read before
 * On an error (ALB_ERR_ARG, also for a payload that is not whole words with
 * at least taken_at; ALB_ERR_CORRUPT) st is not written.
 *
 * now is the global time, read BEFORE the call: the last GlobalTime value
 * imported before it, or alb_clock_now() (alb_clock.h).  The value the Import
 * returns was the newest one published at some instant t of the call, and
 * now <= t (up to the lead of a clock estimate), so age_clocks never exceeds
 * the value's true age at t, whatever delays the CPU suffers between reading
 * now and the Import.  max_age_clocks is the channel's refresh bound at this
 * consumer: a value's true age at any instant is at most the compiler's
 * bound (the board header's ALB_<NAME>_MAX_AGE_CLOCKS(producer period):
 * latency + the producer's period for a copy channel, the age bound for time
 * and status), plus the lead of now over the true global time (0 for a
 * GlobalTime value; see docs/protocol.md, "Sampling read").  Times wrap: now
 * and taken_at must be less than 2^31 clocks apart.
 */
enum {
    ALB_SAMPLE_NEVER = 0,  /* nothing received yet                            */
    ALB_SAMPLE_NEW   = 1,  /* a fresh value never read before                 */
    ALB_SAMPLE_OLD   = 2,  /* a fresh value read before                       */
    ALB_SAMPLE_STALE = 3   /* older than the refresh bound (is_new tells New)  */
};

typedef struct alb_sample {
    uint8_t  status;       /* ALB_SAMPLE_*                                     */
    uint8_t  is_new;       /* the Import returned ALB_NEW                      */
    uint32_t age_clocks;   /* now - taken_at (0 if taken_at is after now)      */
} alb_sample_t;

int alb_read(alb_channel_t *ch, void *dst, uint32_t max_age_clocks, uint32_t now, alb_sample_t *st);

/*
 * The typed task interface (the paper, section 3.1):
 *
 *   ALB_CHANNEL(RadarMap, RadarShot)
 *
 * declares the channel object alb_ch_RadarMap (define it once with
 * ALB_CHANNEL_DEFINE(RadarMap) and set it up with alb_channel_setup) and
 *
 *   bool LookForNewRadarMap(RadarShot *v);          true: never read before
 *   int  MakeRadarMapAvailable(const RadarShot *v); ALB_OK or ALB_ERR_CORRUPT
 *
 * LookForNew returns false on ALB_OLD and on errors (then *v is unchanged);
 * call alb_import() directly to tell the two apart.
 */
#define ALB_CHANNEL(Name, Type)                                              \
    extern alb_channel_t alb_ch_##Name;                                      \
    static inline bool LookForNew##Name(Type *v)                             \
    {                                                                        \
        return alb_import(&alb_ch_##Name, v) == ALB_NEW;                     \
    }                                                                        \
    static inline int Make##Name##Available(const Type *v)                   \
    {                                                                        \
        return alb_export(&alb_ch_##Name, v);                                \
    }

#define ALB_CHANNEL_DEFINE(Name) alb_channel_t alb_ch_##Name

/*
 * The typed sampling read, beside LookForNew<Name> of a destination channel
 * (after ALB_CHANNEL(Name, Msg), Msg = {value, taken_at}):
 *
 *   ALB_SAMPLING(RadarMap, RadarMap_msg)
 *
 * declares
 *
 *   int ReadRadarMap(RadarMap_msg *m, alb_sample_t *st, uint32_t now,
 *                    uint32_t max_age_clocks);   alb_read's result
 */
#define ALB_SAMPLING(Name, Msg)                                              \
    static inline int Read##Name(Msg *m, alb_sample_t *st, uint32_t now,      \
                                 uint32_t max_age_clocks)                    \
    {                                                                        \
        return alb_read(&alb_ch_##Name, m, max_age_clocks, now, st);         \
    }

#endif
