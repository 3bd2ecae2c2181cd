/*
 * Port layer of the host unit test of alb_clock (tb/clock/test_clock.c): no
 * RAM, only the local timer, a variable the test sets (unit_local_now).
 */
#ifndef ALB_PORT_IMPL_H
#define ALB_PORT_IMPL_H

#include <stdint.h>

extern uint32_t unit_local_now;

#define ALB_PORT_HAS_LOCAL_TIME 1
static inline uint32_t alb_local_time(void)
{
    return unit_local_now;
}

#endif
