/*
 * Port layer for the Verilator testbench.  Every call is one Wishbone
 * transaction on the RTL RAM: the calling simulated CPU (a coroutine) posts
 * the request and yields to the clock loop until the RAM acknowledges it
 * (tb/common/sim_cpu.cpp).  The CPUs are strictly sequential, so the fence is empty.
 */
#ifndef ALB_PORT_IMPL_H
#define ALB_PORT_IMPL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif
/* One bus access of the current simulated CPU: addr is a byte address, sel
 * the byte lanes of the addressed word, returns the word read. */
uint32_t tb_bus_access(uintptr_t addr, uint32_t wdata, unsigned sel, int we);
#ifdef __cplusplus
}
#endif

static inline uint8_t alb_rd8(uintptr_t addr)
{
    unsigned lane = (unsigned)(addr & 3u);
    return (uint8_t)(tb_bus_access(addr, 0u, 1u << lane, 0) >> (8u * lane));
}

static inline void alb_wr8(uintptr_t addr, uint8_t v)
{
    unsigned lane = (unsigned)(addr & 3u);
    (void)tb_bus_access(addr, (uint32_t)v << (8u * lane), 1u << lane, 1);
}

static inline uint32_t alb_rd32(uintptr_t addr)
{
    return tb_bus_access(addr, 0u, 0xFu, 0);
}

static inline void alb_wr32(uintptr_t addr, uint32_t v)
{
    (void)tb_bus_access(addr, v, 0xFu, 1);
}

static inline void alb_fence(void)
{
}

/* The current simulated CPU's local timer (alb_clock.c), supplied by a
 * testbench that links alb_clock.c. */
#ifdef __cplusplus
extern "C" {
#endif
uint32_t tb_local_time(void);
#ifdef __cplusplus
}
#endif
#define ALB_PORT_HAS_LOCAL_TIME 1
static inline uint32_t alb_local_time(void)
{
    return tb_local_time();
}

#endif
