/*
 * Port layer for a CPU that sees the dual-ported RAM as ordinary memory.
 * Volatile accesses keep every access exactly as written; alb_fence() is the
 * CPU's full memory fence.  On in-order cores without a store buffer
 * (PicoRV32, SERV) the fence instruction costs a cycle and orders nothing
 * that was not already ordered; on a core with a store buffer it is the
 * store-load barrier the three-buffer protocol needs (see albatross.c).
 */
#ifndef ALB_PORT_IMPL_H
#define ALB_PORT_IMPL_H

#include <stdint.h>

static inline uint8_t alb_rd8(uintptr_t addr)
{
    return *(volatile const uint8_t *)addr;
}

static inline void alb_wr8(uintptr_t addr, uint8_t v)
{
    *(volatile uint8_t *)addr = v;
}

static inline uint32_t alb_rd32(uintptr_t addr)
{
    return *(volatile const uint32_t *)addr;
}

static inline void alb_wr32(uintptr_t addr, uint32_t v)
{
    *(volatile uint32_t *)addr = v;
}

static inline void alb_fence(void)
{
#if defined(__riscv)
    __asm__ volatile("fence iorw, iorw" ::: "memory");   /* also an I/O-mapped window */
#else
    __sync_synchronize();
#endif
}

/* The board's local timer (alb_clock.c): one load of the 32-bit read-only
 * register at ALB_LOCAL_TIMER_ADDR, which the target's build defines (the
 * soft-core boards: soc/firmware/board.h BOARD_TIMER, 0x2000_0040). */
#ifdef ALB_LOCAL_TIMER_ADDR
#define ALB_PORT_HAS_LOCAL_TIME 1
static inline uint32_t alb_local_time(void)
{
    return *(volatile const uint32_t *)(uintptr_t)(ALB_LOCAL_TIMER_ADDR);
}
#endif

#endif
