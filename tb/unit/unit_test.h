/*
 * unit_test.h -- shared by the host unit tests of the ALBATROSS C driver
 * (test_driver.c, test_transfer.c, test_errors.c): the checks, the test
 * port helpers and the channel under test, defined in unit_helpers.c.
 */
#ifndef UNIT_TEST_H
#define UNIT_TEST_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "albatross.h"
#include "alb_port.h"

/* checks */
#define MAX_SHOWN 60
extern unsigned long g_checks, g_fails;
extern char g_ctx[160];
#define CTX(...) snprintf(g_ctx, sizeof g_ctx, __VA_ARGS__)

int fail_shown(void);
int check_int(const char *what, long expected, long got);
int check_true(const char *what, int cond, const char *detail);
int check_bytes(const char *what, const uint8_t *expected, const uint8_t *got, size_t n);
int check_fill(const char *what, const uint8_t *p, size_t n, uint8_t v);

/* the test port */
extern const char *kind_name[UNIT_KINDS];
void port_reset(uintptr_t lo, uintptr_t hi);
unsigned long ram_accesses(void);
uint8_t *ram(uintptr_t addr);
void check_no_trap(void);
void check_counts(const char *call, long rd8, long wr8, long rd32, long wr32);
void check_fence_between(const char *rule, enum unit_kind a, uintptr_t addr_a,
                         enum unit_kind b, uintptr_t addr_b);
void check_words_at(const char *what, enum unit_kind k, uintptr_t first, long n);

/* channels */
#define BIG      67u                       /* largest payload of the sweep  */
#define CH_OFF   64u                       /* channel offset in the RAM     */
#define RAM_FILL 0xc3u
extern uintptr_t ch_base;
extern uint32_t  ch_size;
uintptr_t a_actual(void);
uintptr_t a_rl(void);
uintptr_t a_buf(unsigned b);
long words(uint32_t size);
void new_channel(alb_channel_t *p, alb_channel_t *c, uint32_t size);
void set_control(unsigned actual, unsigned read_locked);
void pattern(uint8_t *p, size_t n, unsigned seed);
unsigned buffer_of(uintptr_t addr);
void check_ram_unchanged(const char *what, const uint8_t *snap,
                         uintptr_t lo, uintptr_t hi, int actual_may_change);

/* the tests outside test_driver.c */
void test_sweep(void);
void test_selection(void);
void test_corrupt_actual(void);
void test_import_loop(void);
void test_corrupt_read_locked(void);
void test_corrupt_attach(void);
void test_sequence(void);
void test_typed(void);
void test_four_slot(void);   /* test_four_slot.c */
void test_sample(void);      /* test_sample.c */
void test_cold_start(void);  /* test_cold_start.c */

#endif
