/*
 * tb/host_threads/port/alb_port_impl.h -- the negative port of the host
 * thread test (tools/mk/host_threads.mk): the mmio port layer
 * (c-driver/port/mmio/alb_port_impl.h, included, not copied: the same
 * volatile accesses) with its fence taken out, everywhere or at one site.
 *
 *   -DHT_DROP_LINE=0   alb_fence() does nothing at every site
 *   -DHT_DROP_LINE=N   only the alb_fence() on line N of albatross.c does
 *                      nothing; every other site keeps the mmio fence
 *   -DHT_DROP_LINE2=M  (with N) the one on line M does nothing too
 *
 * alb_fence() becomes a macro, so __LINE__ is the line of the call in
 * albatross.c.  A dropped fence keeps a compiler barrier: every RAM access
 * of the driver is volatile, so the compiler keeps their order with or
 * without it; the barrier only also pins the driver's private (non-RAM)
 * accesses, which no other thread reads.  What is left out is the CPU's
 * fence instruction alone (mfence on x86-64), so a failure of this build is
 * the CPU's store buffer at work, not the compiler.
 */
#ifndef HT_PORT_IMPL_H
#define HT_PORT_IMPL_H

#ifndef HT_DROP_LINE
#error "HT_DROP_LINE: 0 (every fence) or the line of one alb_fence() in albatross.c"
#endif

/* The mmio port, its fence renamed out of the way. */
#define alb_fence ht_mmio_fence
#include "../../../c-driver/port/mmio/alb_port_impl.h"
#undef alb_fence

#ifndef HT_DROP_LINE2
#define HT_DROP_LINE2 (-1)
#endif

static inline void ht_fence(int line)
{
    if (HT_DROP_LINE == 0 || line == HT_DROP_LINE || line == HT_DROP_LINE2)
        __asm__ volatile("" ::: "memory");        /* compiler barrier only */
    else
        ht_mmio_fence();
}

#define alb_fence() ht_fence(__LINE__)

#endif
