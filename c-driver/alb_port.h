/*
 * alb_port.h -- the port layer: the only way the driver reaches the
 * dual-ported RAM.  Each target supplies a header "alb_port_impl.h" (chosen by
 * the include path) that defines, usually as static inline functions:
 *
 *   uint8_t  alb_rd8 (uintptr_t addr);               one byte access
 *   void     alb_wr8 (uintptr_t addr, uint8_t v);
 *   uint32_t alb_rd32(uintptr_t addr);               one aligned word access
 *   void     alb_wr32(uintptr_t addr, uint32_t v);   (little-endian lanes)
 *   void     alb_fence(void);                        full fence: orders every
 *                                                    earlier access (loads and
 *                                                    stores) before every later one
 *   uint32_t alb_local_time(void);                   the board's free-running local
 *                                                    timer (only alb_clock.c uses it;
 *                                                    one read, disturbs nothing); a
 *                                                    port that has it also defines
 *                                                    ALB_PORT_HAS_LOCAL_TIME (without
 *                                                    it alb_clock.c stops with #error)
 *
 * Each call is exactly one access of the RAM port: never merged, split,
 * elided or reordered by the compiler.  Targets:
 *   c-driver/port/mmio/   memory-mapped RAM (volatile accesses, CPU fence;
 *                         alb_local_time when the build defines
 *                         ALB_LOCAL_TIMER_ADDR)
 *   tb/common/port/       Verilator testbench (each access is a bus
 *                         transaction on the RTL; the calling simulated CPU
 *                         yields to the clock loop until it completes)
 *   tb/unit/port/         host unit tests: a byte array, every access
 *                         counted and checked
 *   tb/clock/port/        host unit test of alb_clock.c: the local timer only
 */
#ifndef ALB_PORT_H
#define ALB_PORT_H

#include <stdint.h>
#include "alb_port_impl.h"

#endif
