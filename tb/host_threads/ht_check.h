/*
 * ht_check.h -- the payload and the checker of every Import, shared by the
 * host thread test (host_threads.c: two real threads) and the store-buffer
 * model (sb_model.c: two coroutines over a modelled memory system).
 *
 * The producer exports sequence numbers 1, 2, 3, ...; word i of the payload
 * holds seq XOR ht_salt(i), so a mix of two values shows.  ht_judge counts,
 * for one Import (its result r, its payload w), each violation:
 *   torn          the words name different sequence numbers
 *   back in time  older than the value the previous Import returned (*last)
 *   stale         older than `fresh`, the newest value whose alb_export had
 *                 returned before the Import began
 *   wrong New     ALB_NEW but not newer than the previous value
 *   wrong Old     ALB_OLD but a different value than the previous one
 * and returns a mask of HT_V_* bits (0: the Import checks out).
 */
#ifndef HT_CHECK_H
#define HT_CHECK_H

#include <stdint.h>
#include "albatross.h"

enum { HT_V_TORN = 1, HT_V_BACK = 2, HT_V_STALE = 4, HT_V_WRONG_NEW = 8, HT_V_WRONG_OLD = 16 };

struct ht_tally {
    uint64_t news, olds, torn, back, stale, wrong_new, wrong_old, violations;
    uint64_t first_violation;     /* index of the first Import with a violation (+1; 0: none) */
};

static inline uint32_t ht_salt(unsigned i)
{
    return 0x9E3779B9u * (i + 1u) ^ 0x5A5A5A5Au;
}

static inline void ht_fill(uint32_t *w, unsigned words, uint32_t seq)
{
    unsigned i;
    for (i = 0; i < words; ++i)
        w[i] = seq ^ ht_salt(i);
}

/* The name of the lowest violation bit of mask. */
static inline const char *ht_violation_name(unsigned mask)
{
    return mask & HT_V_TORN ? "torn" : mask & HT_V_BACK ? "back in time" : mask & HT_V_STALE ? "stale" :
           mask & HT_V_WRONG_NEW ? "New but not newer" : "Old but another value";
}

/* Judge Import number i (0-based). */
static inline unsigned ht_judge(struct ht_tally *t, unsigned words, int r, const uint32_t *w,
                                uint32_t *last, uint32_t fresh, uint64_t i)
{
    uint32_t s = w[0] ^ ht_salt(0);
    unsigned k, bad = 0;

    for (k = 1; k < words; ++k)
        if ((w[k] ^ ht_salt(k)) != s)
            break;
    if (k != words) {
        ++t->torn;
        bad |= HT_V_TORN;
    } else {
        if (s < *last) {
            ++t->back;
            bad |= HT_V_BACK;
        }
        if (s < fresh) {
            ++t->stale;
            bad |= HT_V_STALE;
        }
        if (r == ALB_NEW && s <= *last) {
            ++t->wrong_new;
            bad |= HT_V_WRONG_NEW;
        }
        if (r == ALB_OLD && s != *last) {
            ++t->wrong_old;
            bad |= HT_V_WRONG_OLD;
        }
        if (s > *last)
            *last = s;
    }
    if (r == ALB_NEW)
        ++t->news;
    else
        ++t->olds;
    if (bad) {
        if (t->violations == 0u)
            t->first_violation = i + 1u;
        ++t->violations;
    }
    return bad;
}

#endif
