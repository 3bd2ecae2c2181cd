/*
 * board.h -- memory map of the PicoRV32 test boards (tb/pico/pico_pair.v).
 * Each core has its own program RAM and board registers; the DPRAM window is
 * one port of the shared albatross_dpram.  Plain numbers (no C suffixes), so
 * crt0.S can include this file too.
 *
 *   0x0000_0000  16 KiB   local program RAM (code, data, stack)
 *   0x1000_0000   4 KiB   DPRAM window (albatross_dpram, ADDR_WIDTH 10)
 *   0x2000_0000   word    TOHOST: a store ends the program, the value is the
 *                         exit code (0 = pass)
 *   0x2000_0010  4 words  STAT(0..3): figures the harness reads at the end
 *   0x2000_0020   word    EVENT: a store hands the value and ARG to the
 *                         harness in that clock (soc/board_memmap.v)
 *   0x2000_0024   word    ARG: the argument of the next EVENT
 *   0x2000_0040   word    TIMER (read-only): the board's local timer, ticks
 *                         since reset, one per board clock (a load never
 *                         stalls and changes nothing; stores are ignored).
 *                         The driver reads it as alb_local_time() with
 *                         -DALB_LOCAL_TIMER_ADDR=0x20000040u (c-driver/alb_clock.h)
 */
#ifndef BOARD_H
#define BOARD_H

/* Where the core sees the DPRAM window and the board registers: override
 * both for a core whose view differs.  A core with a data cache must see
 * them uncached: VexRiscv (soc/vexriscv_core.v, an address with bit 31 set
 * is I/O) is built with -DBOARD_DPRAM_BASE=0x90000000
 * -DBOARD_REGS_BASE=0xA0000000 (tools/mk/vexriscv.mk). */
#ifndef BOARD_DPRAM_BASE
#define BOARD_DPRAM_BASE   0x10000000
#endif
#ifndef BOARD_REGS_BASE
#define BOARD_REGS_BASE    0x20000000
#endif
#define BOARD_RAM_BYTES    0x4000
#define BOARD_DPRAM_BYTES  0x1000
#define BOARD_TOHOST       (BOARD_REGS_BASE + 0x00)
#define BOARD_STAT0        (BOARD_REGS_BASE + 0x10)
#define BOARD_EVENT        (BOARD_REGS_BASE + 0x20)
#define BOARD_EVENT_ARG    (BOARD_REGS_BASE + 0x24)
#define BOARD_TIMER        (BOARD_REGS_BASE + 0x40)

#ifndef __ASSEMBLER__
#include <stdint.h>
#include "albatross.h"

/* Channel of the pair test: DPRAM offset 0; a start flag word after it.
 * BOARD_CHANNEL_BASE moves the channel alone (the start flag stays in the
 * window): the VexRiscv negative test reaches the channel through the cached
 * alias 0x1000_0000 (tools/mk/vexriscv.mk). */
#ifndef BOARD_CHANNEL_BASE
#define BOARD_CHANNEL_BASE BOARD_DPRAM_BASE
#endif
#define BOARD_CHANNEL      ((uintptr_t)BOARD_CHANNEL_BASE)
#define BOARD_START_FLAG   ((uintptr_t)BOARD_DPRAM_BASE + 0x100u)
#define BOARD_START_MAGIC  0x5354u

static inline void board_stat(unsigned k, uint32_t v)
{
    *(volatile uint32_t *)((uintptr_t)BOARD_STAT0 + 4u * k) = v;
}

/* One event for the harness: ARG first, then EVENT (the store that counts). */
static inline void board_event(uint32_t ev, uint32_t arg)
{
    *(volatile uint32_t *)(uintptr_t)BOARD_EVENT_ARG = arg;
    *(volatile uint32_t *)(uintptr_t)BOARD_EVENT = ev;
}

/* The local timer (TIMER): one load. */
static inline uint32_t board_timer(void)
{
    return *(volatile const uint32_t *)(uintptr_t)BOARD_TIMER;
}

/* Cycle and retired-instruction counters.  By default the CSRs cycle and
 * instret (PicoRV32 ENABLE_COUNTERS), encoded with .insn: csrrs rd,
 * cycle/instret, x0 needs Zicsr, not in -march=rv32i.  Build with
 * -DBOARD_NO_COUNTERS for a core without them (SERV: rdcycle would read
 * another CSR, not trap): the counters are then loaded from the board
 * registers CYCLE and INSTRET, which serv_core provides (soc/serv_bridge.v),
 * and vexriscv_core too (soc/vexriscv_bridge.v: CYCLE only, INSTRET reads 0),
 * and which read 0 on a board without them (board_memmap), so the figures
 * are 0 there and the programs still run. */
#define BOARD_CYCLE        (BOARD_REGS_BASE + 0x80)
#define BOARD_INSTRET      (BOARD_REGS_BASE + 0x84)

static inline uint32_t board_cycles(void)
{
#ifdef BOARD_NO_COUNTERS
    return *(volatile uint32_t *)(uintptr_t)BOARD_CYCLE;
#else
    uint32_t v;
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -1024" : "=r"(v)); /* 0xC00 */
    return v;
#endif
}

static inline uint32_t board_instret(void)
{
#ifdef BOARD_NO_COUNTERS
    return *(volatile uint32_t *)(uintptr_t)BOARD_INSTRET;
#else
    uint32_t v;
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -1022" : "=r"(v)); /* 0xC02 */
    return v;
#endif
}

/* The payload of the pair test: 16 bytes, a sequence number and check words
 * derived from it, so a value mixed from two exports (torn) is detected. */
typedef struct {
    uint32_t seq;
    uint32_t h1;   /* mix(seq)              */
    uint32_t h2;   /* mix(h1)               */
    uint32_t sum;  /* seq ^ h1 ^ h2 ^ SALT  */
} pair_value_t;

#define PAIR_SALT   0x5A5A5A5Au
/* Events of a consumer built with -DPAIR_EVENTS (tb/pico/test_vex_pair.cpp
 * checks actuality from them, whatever reaches the RAM): before each
 * alb_import EVENT PAIR_EV_BEGIN (ARG: the call's number), after it
 * PAIR_EV_NEW or PAIR_EV_OLD (ARG: the sequence number returned). */
#define PAIR_EV_BEGIN 0x1u
#define PAIR_EV_NEW   0x2u
#define PAIR_EV_OLD   0x3u
/* Values the producer exports (and the consumer waits for): override with
 * -DPAIR_VALUES=n for a slow core (tools/mk/serv.mk). */
#ifndef PAIR_VALUES
#define PAIR_VALUES 2000u
#endif

static inline uint32_t pair_mix(uint32_t x)
{
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return x + 0x9E3779B9u;
}

static inline void pair_make(pair_value_t *v, uint32_t seq)
{
    v->seq = seq;
    v->h1 = pair_mix(seq);
    v->h2 = pair_mix(v->h1);
    v->sum = seq ^ v->h1 ^ v->h2 ^ PAIR_SALT;
}

static inline int pair_ok(const pair_value_t *v)
{
    return v->h1 == pair_mix(v->seq) && v->h2 == pair_mix(v->h1) &&
           v->sum == (v->seq ^ v->h1 ^ v->h2 ^ PAIR_SALT);
}

/* The consumer's check of one Import that returned r (ALB_NEW or ALB_OLD)
 * with value v, after the value with sequence number last: 0, or the code
 * 0x3 torn value, 0x4 sequence went back, 0x5 New without a newer value,
 * 0x6 Old with a newer value, with the sequence number concerned << 8.
 * zero_start: an all-zero value (a RAM image's start value) passes while
 * last is 0, as sequence 0. */
static inline uint32_t pair_check(const pair_value_t *v, int r, uint32_t last, int zero_start)
{
    int zero = (v->seq | v->h1 | v->h2 | v->sum) == 0u;
    if (!pair_ok(v) && !(zero_start && zero && last == 0u))
        return 0x3u | last << 8;
    if (v->seq < last)
        return 0x4u | v->seq << 8;
    if (r == ALB_NEW && v->seq == last && !(zero_start && last == 0u))
        return 0x5u | last << 8;
    if (r != ALB_NEW && v->seq != last)
        return 0x6u | v->seq << 8;
    return 0u;
}
#endif

#endif
