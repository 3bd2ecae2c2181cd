/*
 * tb/host_threads/sbport/alb_port_impl.h -- the port layer of the
 * store-buffer model (tb/host_threads/sb_model.c, tools/mk/host_threads.mk):
 * every access of the driver goes to the modelled memory system, and is a
 * point where the model's scheduler may switch to the other thread or drain
 * a store buffer.  alb_fence() becomes a macro, so the model knows the line
 * of albatross.c it was called from and can drop the fences it is told to
 * (--drop), one at a time, in pairs, or all.
 */
#ifndef SB_PORT_IMPL_H
#define SB_PORT_IMPL_H

#include <stdint.h>

uint8_t  sb_rd8(uintptr_t addr);
void     sb_wr8(uintptr_t addr, uint8_t v);
uint32_t sb_rd32(uintptr_t addr);
void     sb_wr32(uintptr_t addr, uint32_t v);
void     sb_fence(int line);

static inline uint8_t alb_rd8(uintptr_t addr) { return sb_rd8(addr); }
static inline void alb_wr8(uintptr_t addr, uint8_t v) { sb_wr8(addr, v); }
static inline uint32_t alb_rd32(uintptr_t addr) { return sb_rd32(addr); }
static inline void alb_wr32(uintptr_t addr, uint32_t v) { sb_wr32(addr, v); }

#define alb_fence() sb_fence(__LINE__)

#endif
