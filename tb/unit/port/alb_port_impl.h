/*
 * Port layer for the host unit tests of the driver (tb/unit/test_driver.c).
 *
 * The dual-ported RAM is a plain byte array, unit_port.ram, seen by the driver
 * at the made-up address UNIT_RAM_BASE (so a stray address can never reach
 * host memory).  Every access is counted per kind and appended to a log;
 * fences are logged too but are not RAM accesses.  An access outside the
 * array, outside the window of the channel under test, or a misaligned word
 * access is a trap: it is counted and described, never performed (a trapped
 * load returns 0).  All state lives in unit_port, defined in unit_helpers.c.
 *
 * Checker self-test (driver-unit-negative): compiled with -DUNIT_BROKEN_PORT=N
 * the port is deliberately broken and the test program must fail:
 *   1  alb_wr32 drops byte lane 3 (the highest address of the word)
 *   2  alb_fence is lost (neither performed nor logged)
 */
#ifndef ALB_PORT_IMPL_H
#define ALB_PORT_IMPL_H

#include <stddef.h>
#include <stdint.h>

#define UNIT_RAM_BASE   0x10000u
#define UNIT_RAM_BYTES  1024u
#define UNIT_LOG_MAX    1024u
/* RAM index of an address already checked to lie in the RAM (the modulo,
 * a mask, only keeps the compiler's array-bounds analysis quiet). */
#define UNIT_IDX(addr)  ((size_t)((addr) - UNIT_RAM_BASE) % UNIT_RAM_BYTES)

enum unit_kind { UNIT_RD8, UNIT_WR8, UNIT_RD32, UNIT_WR32, UNIT_FENCE, UNIT_KINDS };

struct unit_access {
    enum unit_kind kind;
    uintptr_t      addr;   /* 0 for a fence */
    uint32_t       value;  /* value loaded or stored */
};

struct unit_port {
    uint8_t            ram[UNIT_RAM_BYTES];
    uintptr_t          win_lo, win_hi;     /* allowed addresses [lo, hi) */
    unsigned long      count[UNIT_KINDS];  /* accesses per kind */
    unsigned long      traps;
    char               trap_msg[160];      /* the first trap since reset */
    struct unit_access log[UNIT_LOG_MAX];
    unsigned long      nlog;               /* may exceed UNIT_LOG_MAX */
    /* Scripted partner: just before access number hook_at (1-based, since
     * the last reset) the byte at hook_addr becomes hook_value. */
    unsigned long      hook_at;            /* 0: no hook */
    uintptr_t          hook_addr;
    uint8_t            hook_value;
};

extern struct unit_port unit_port;

/* Defined in unit_helpers.c (not inline: it formats a message). */
void unit_trap(enum unit_kind kind, uintptr_t addr, const char *why);

/* Watchdog: a driver call that loops for ever on valid control bytes never
 * returns to the test.  More RAM accesses than this since the last reset of
 * the port (a call takes a few, every test under 1000 between resets) end the
 * program: unit_runaway (unit_helpers.c) names the test and exits with 1. */
#ifndef UNIT_MAX_ACCESSES
#define UNIT_MAX_ACCESSES 1000000ul
#endif
void unit_runaway(unsigned long accesses);

/* Count, log, run the scripted partner; returns 0 if the access may go on. */
static inline int unit_touch(enum unit_kind kind, uintptr_t addr,
                              unsigned width, uint32_t value)
{
    struct unit_port *p = &unit_port;
    unsigned long n = p->count[UNIT_RD8] + p->count[UNIT_WR8] +
                      p->count[UNIT_RD32] + p->count[UNIT_WR32] + 1u;

    p->count[kind]++;
    if (n > UNIT_MAX_ACCESSES)
        unit_runaway(n);
    if (p->nlog < UNIT_LOG_MAX) {
        p->log[p->nlog].kind = kind;
        p->log[p->nlog].addr = addr;
        p->log[p->nlog].value = value;
    }
    p->nlog++;
    if (addr < UNIT_RAM_BASE || addr - UNIT_RAM_BASE > UNIT_RAM_BYTES - width) {
        unit_trap(kind, addr, "outside the RAM");
        return -1;
    }
    if (addr < p->win_lo || addr + width > p->win_hi) {
        unit_trap(kind, addr, "outside the channel under test");
        return -1;
    }
    if (width == 4u && (addr & 3u) != 0u) {
        unit_trap(kind, addr, "misaligned word access");
        return -1;
    }
    if (p->hook_at != 0u && n == p->hook_at) {
        p->ram[UNIT_IDX(p->hook_addr)] = p->hook_value;
        p->hook_at = 0u;
    }
    return 0;
}

static inline uint8_t alb_rd8(uintptr_t addr)
{
    uint8_t v;

    if (unit_touch(UNIT_RD8, addr, 1u, 0u) != 0)
        return 0u;
    v = unit_port.ram[UNIT_IDX(addr)];
    if (unit_port.nlog <= UNIT_LOG_MAX)
        unit_port.log[unit_port.nlog - 1u].value = v;
    return v;
}

static inline void alb_wr8(uintptr_t addr, uint8_t v)
{
    if (unit_touch(UNIT_WR8, addr, 1u, v) != 0)
        return;
    unit_port.ram[UNIT_IDX(addr)] = v;
}

static inline uint32_t alb_rd32(uintptr_t addr)
{
    const uint8_t *b;
    uint32_t v;

    if (unit_touch(UNIT_RD32, addr, 4u, 0u) != 0)
        return 0u;
    b = &unit_port.ram[UNIT_IDX(addr)];
    v = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
        (uint32_t)b[3] << 24;
    if (unit_port.nlog <= UNIT_LOG_MAX)
        unit_port.log[unit_port.nlog - 1u].value = v;
    return v;
}

static inline void alb_wr32(uintptr_t addr, uint32_t v)
{
    uint8_t *b;

    if (unit_touch(UNIT_WR32, addr, 4u, v) != 0)
        return;
    b = &unit_port.ram[UNIT_IDX(addr)];
    b[0] = (uint8_t)v;
    b[1] = (uint8_t)(v >> 8);
    b[2] = (uint8_t)(v >> 16);
#if defined(UNIT_BROKEN_PORT) && UNIT_BROKEN_PORT == 1
    (void)b;                    /* broken: byte lane 3 is dropped */
#else
    b[3] = (uint8_t)(v >> 24);
#endif
}

static inline void alb_fence(void)
{
#if defined(UNIT_BROKEN_PORT) && UNIT_BROKEN_PORT == 2
    /* broken: the fence is lost */
#else
    struct unit_port *p = &unit_port;

    p->count[UNIT_FENCE]++;
    if (p->nlog < UNIT_LOG_MAX) {
        p->log[p->nlog].kind = UNIT_FENCE;
        p->log[p->nlog].addr = 0u;
        p->log[p->nlog].value = 0u;
    }
    p->nlog++;
#endif
}

#endif
