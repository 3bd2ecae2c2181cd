/*
 * consumer.c -- PicoRV32 consumer of the pair test (tb/pico/).  Waits for the
 * producer's start flag, attaches with the real driver and imports until it
 * has seen value PAIR_VALUES, checking every import:
 *   0x20 + e  alb_import returned error e (or attach failed: 0x30 + e)
 *   0x3       torn value (check words do not match the sequence number)
 *   0x4       the sequence number went back
 *   0x5       ALB_NEW with a sequence number that is not newer
 *   0x6       ALB_OLD with a newer sequence number
 * Built with -DPAIR_KIND=ALB_FOUR_SLOT, the channel is of the four-slot kind
 * and the consumer starts with alb_consumer_init (a four-slot attach forgets
 * the value read last, so its first Import would return value 0 New; the
 * producer has not touched Buffer1 or ReadLocked since it released the start
 * flag, so Buffer1's value 0 counts as read).
 * The exit code is that code | sequence number << 8 (0 = pass).  STAT:
 * 0 imports that returned New, 1 imports, 2 cycles in alb_import, 3 retired
 * instructions.
 * Built with -DPAIR_EVENTS, every Import is announced to the harness as board
 * EVENTs (PAIR_EV_*, soc/firmware/board.h), before the call and with its
 * result after it.
 * Built with -DPAIR_COUNT_FAULTS (a negative test that must say how many
 * values were wrong), a torn or out-of-order value does not end the program:
 * it is counted (a whole value out of order is taken as the last value
 * read, a torn one is not), the exit code is the
 * first fault's, and STAT 3 is the number of faulty imports instead of the
 * retired instructions.
 */
#include "albatross.h"
#include "alb_port.h"
#include "board.h"

#ifndef PAIR_KIND
#define PAIR_KIND ALB_THREE_BUFFER   /* the channel kind: ALB_THREE_BUFFER or ALB_FOUR_SLOT */
#endif

static alb_channel_t ch;

int main(void)
{
    pair_value_t v;
    uint32_t last = 0u, news = 0u, calls = 0u, t0, cycles = 0u, code;
#ifdef PAIR_COUNT_FAULTS
    uint32_t faults = 0u, first = 0u;
#endif
    int r;

    if (alb_channel_setup_kind(&ch, BOARD_CHANNEL, sizeof v, PAIR_KIND) != ALB_OK)
        return 0x31;
    while (alb_rd32(BOARD_START_FLAG) != BOARD_START_MAGIC)
        ;
    alb_fence();
    r = PAIR_KIND == ALB_FOUR_SLOT ? alb_consumer_init(&ch) : alb_consumer_attach(&ch);
    if (r != ALB_OK)
        return 0x30 - r;

    while (last != PAIR_VALUES) {
#ifdef PAIR_EVENTS
        board_event(PAIR_EV_BEGIN, calls);
#endif
        t0 = board_cycles();
        r = alb_import(&ch, &v);
        cycles += board_cycles() - t0;
        ++calls;
#ifdef PAIR_EVENTS
        board_event(r == ALB_NEW ? PAIR_EV_NEW : PAIR_EV_OLD, v.seq);
#endif
        if (r != ALB_NEW && r != ALB_OLD)
            return (0x20 - r) | (int)(last << 8);
        code = pair_check(&v, r, last, 0);
#ifdef PAIR_COUNT_FAULTS
        if (code != 0u) {
            if (faults++ == 0u)
                first = code;
            if (pair_ok(&v))   /* whole but out of order: the checks go on from it */
                last = v.seq;
            continue;
        }
#else
        if (code != 0u)
            return (int)code;
#endif
        if (r == ALB_NEW)
            ++news;
        last = v.seq;
    }
    board_stat(0u, news);
    board_stat(1u, calls);
    board_stat(2u, cycles);
#ifdef PAIR_COUNT_FAULTS
    board_stat(3u, faults);
    return (int)first;
#else
    board_stat(3u, board_instret());
    return 0;
#endif
}
