/*
 * albatross.c -- Import and Export of the three-buffer channel (the paper, section 3.1,
 * figures 3 and 4), written to follow the paper line by line, and of the
 * wait-free four-slot channel (docs/four_slot.md: the statement order and
 * why each other order fails).
 *
 * Memory ordering.  The consumer stores ReadLocked and then loads Actual; the
 * producer stores Actual and, in its next Export, loads ReadLocked.  That is
 * the store-buffering pattern: on a CPU with a store buffer each side needs a
 * store-load fence between the two, or both may read stale values and the
 * producer could pick the buffer the consumer is about to read.  The producer
 * also needs its data stores ordered before the store of Actual (release) and
 * the consumer its load of Actual before the data loads (acquire).  Each is an
 * alb_fence() below; on in-order cores without a store buffer they cost
 * almost nothing.  None of them is a RAM access.  The four-slot kind has the
 * same pattern (the ReadLocked store before the second control-word load,
 * the Actual store before the next Export's control-word load) and orders
 * its data stores before the Slot store and the Slot store before the
 * Actual store.
 */
#include "albatross.h"
#include "alb_port.h"

/* Whether this build exports / imports channels of a kind (0 or 1); like
 * the dispatch below, any kind but ALB_FOUR_SLOT counts as three-buffer
 * (so that the default build folds the test away). */
#define ALB_EXPORTS(kind) ((kind) == ALB_FOUR_SLOT ? ALB_FOUR_SLOT_EXPORT : ALB_THREE_BUFFER_EXPORT)
#define ALB_IMPORTS(kind) ((kind) == ALB_FOUR_SLOT ? ALB_FOUR_SLOT_IMPORT : ALB_THREE_BUFFER_IMPORT)

#ifdef __GNUC__
typedef uint32_t alb_word __attribute__((__may_alias__, __aligned__(4)));
#else
typedef uint32_t alb_word;
#endif

/* The helpers below sit on the path of every Import and Export: force them
 * inline (at -Os GCC keeps them out of line, and on a small in-order core the
 * calls, spills and re-loads of ch cost more than the copy of a short
 * payload). */
#ifdef __GNUC__
#define ALB_INLINE static inline __attribute__((__always_inline__))
#else
#define ALB_INLINE static inline
#endif

/* Address of buffer 1..4: base + 4 + (buffer - 1) * stride, without a
 * multiply (rv32i has none).  Only the low two bits of buffer - 1 count, so
 * a buffer index of 0 (impossible with valid control bytes) lands on Buffer4
 * (just past Buffer3), never on a control byte. */
ALB_INLINE uintptr_t buffer_addr(const alb_channel_t *ch, uint8_t buffer)
{
    uint32_t stride = ALB_STRIDE(ch->size), k = (uint32_t)buffer - 1u;
    uint32_t off = ALB_OFF_BUFFERS;

    if (k & 1u)
        off += stride;
    if (k & 2u)
        off += stride << 1;
    return ch->base + off;
}

/* ReadFrom (the paper, figure 3): ceil(size/4) word loads from the RAM, in address
 * order.  An aligned destination takes four words per loop pass. */
ALB_INLINE void read_from(const alb_channel_t *ch, uint8_t buffer, void *dst)
{
    uintptr_t src = buffer_addr(ch, buffer), end;
    uint8_t *d = (uint8_t *)dst;
    uint32_t n = ch->size, w;

    if (((uintptr_t)d & 3u) == 0u) {
        for (end = src + (n & ~15u); src != end; src += 16u, d += 16u) {
            ((alb_word *)d)[0] = alb_rd32(src);
            ((alb_word *)d)[1] = alb_rd32(src + 4u);
            ((alb_word *)d)[2] = alb_rd32(src + 8u);
            ((alb_word *)d)[3] = alb_rd32(src + 12u);
        }
        for (end = src + (n & 12u); src != end; src += 4u, d += 4u)
            *(alb_word *)d = alb_rd32(src);
    } else {
        for (end = src + (n & ~3u); src != end; src += 4u, d += 4u) {
            w = alb_rd32(src);
            d[0] = (uint8_t)w;
            d[1] = (uint8_t)(w >> 8);
            d[2] = (uint8_t)(w >> 16);
            d[3] = (uint8_t)(w >> 24);
        }
    }
    n &= 3u;
    if (n != 0u) { /* tail: one word load, the padding bytes are dropped */
        w = alb_rd32(src);
        for (; n != 0u; --n, ++d, w >>= 8)
            *d = (uint8_t)w;
    }
}

/* WriteTo (the paper, figure 4): ceil(size/4) word stores into the RAM, in address
 * order.  An aligned source takes four words per loop pass. */
ALB_INLINE void write_to(const alb_channel_t *ch, uint8_t buffer, const void *src)
{
    uintptr_t dst = buffer_addr(ch, buffer), end;
    const uint8_t *s = (const uint8_t *)src;
    uint32_t n = ch->size, w, k;

    if (((uintptr_t)s & 3u) == 0u) {
        for (end = dst + (n & ~15u); dst != end; dst += 16u, s += 16u) {
            alb_wr32(dst, ((const alb_word *)s)[0]);
            alb_wr32(dst + 4u, ((const alb_word *)s)[1]);
            alb_wr32(dst + 8u, ((const alb_word *)s)[2]);
            alb_wr32(dst + 12u, ((const alb_word *)s)[3]);
        }
        for (end = dst + (n & 12u); dst != end; dst += 4u, s += 4u)
            alb_wr32(dst, *(const alb_word *)s);
    } else {
        for (end = dst + (n & ~3u); dst != end; dst += 4u, s += 4u)
            alb_wr32(dst, (uint32_t)s[0] | (uint32_t)s[1] << 8 |
                              (uint32_t)s[2] << 16 | (uint32_t)s[3] << 24);
    }
    n &= 3u;
    if (n != 0u) { /* tail: one word store, padding bytes written as 0 */
        for (w = 0u, k = 0u; k < n; ++k)
            w |= (uint32_t)s[k] << (8u * k);
        alb_wr32(dst, w);
    }
}

/* The byte at offset off (0..3) of a control word loaded with alb_rd32. */
ALB_INLINE uint8_t ctl_byte(uint32_t word, uint32_t off)
{
    return (uint8_t)(word >> (8u * off));
}

int alb_channel_setup_kind(alb_channel_t *ch, uintptr_t base, uint32_t size, unsigned kind)
{
    if (ch == 0 || (base & 3u) != 0u || size == 0u ||
        (kind != ALB_THREE_BUFFER && kind != ALB_FOUR_SLOT))
        return ALB_ERR_ARG;
    ch->base = base;
    ch->size = size;
    ch->kind = (uint8_t)kind;
    ch->actual = 0u;
    ch->read_locked = 0u;
    ch->fs_actual = 0u;
    ch->fs_read_locked = 0u;
    ch->last = 0u;
    ch->slot[0] = ch->slot[1] = 0u;
    ch->received = 0u;
    return ALB_OK;
}

int alb_channel_setup(alb_channel_t *ch, uintptr_t base, uint32_t size)
{
    return alb_channel_setup_kind(ch, base, size, ALB_THREE_BUFFER);
}

/* ------------------------------------------------------------------------
 * The four-slot kind.  Buffer b (1..4) is pair (b-1)>>1, slot (b-1)&1.  The
 * producer owns Actual, Slot0 and Slot1 (private copies, it is their only
 * writer), the consumer ReadLocked and its private L (ch->last), the buffer
 * it read last.  Export: the three-buffer Export plus one byte store;
 * Import: 1 + W accesses if Actual still names L, else 3 + W.  The helpers
 * below make the control accesses only: the payload copy is the one in
 * alb_import / alb_export, shared by both kinds, so that the driver holds
 * one inlined copy loop per direction (a board's program RAM is small).
 */
#if ALB_FOUR_SLOT_EXPORT
static int fs_producer_attach(alb_channel_t *ch)
{
    uint32_t word = alb_rd32(ch->base);
    uint8_t actual = ctl_byte(word, ALB_OFF_ACTUAL);
    uint8_t s0 = ctl_byte(word, ALB_OFF_SLOT0), s1 = ctl_byte(word, ALB_OFF_SLOT1);

    if (actual == ALB_NOT_STARTED)
        return ALB_ERR_ARG;            /* never started: alb_producer_init */
    if (!ALB_FS_VALID_INDEX(actual) || !ALB_FS_VALID_SLOT(s0) || !ALB_FS_VALID_SLOT(s1))
        return ALB_ERR_CORRUPT;
    ch->fs_actual = actual;
    ch->slot[0] = s0;
    ch->slot[1] = s1;
    return ALB_OK;
}
#endif

#if ALB_FOUR_SLOT_IMPORT
/* read_locked: the RAM's ReadLocked, not 0 (alb_consumer_attach loaded it). */
static int fs_consumer_attach(alb_channel_t *ch, uint8_t read_locked)
{
    if (!ALB_FS_VALID_INDEX(read_locked))
        return ALB_ERR_CORRUPT;
    ch->fs_read_locked = read_locked;
    ch->last = 0u;                     /* forgotten: the next Import is New */
    return ALB_OK;
}
#endif

#if ALB_FOUR_SLOT_EXPORT
/* Export steps 1 and 2: the buffer to write, *buffer.  ALB_OK (also for
 * ReadLocked = 0, a consumer not started yet: read as Buffer1, the value its
 * init stores, so the producer keeps out of pair 0 as with the RAM image),
 * or ALB_ERR_CORRUPT for a ReadLocked of 5..255 (the value is published all
 * the same, in the pair other than Actual's). */
static int fs_select_write(alb_channel_t *ch, uint8_t *buffer)
{
    uint32_t word;
    uint8_t read_locked;
    unsigned pair, slot;
    int result = ALB_OK;

    /* 1. the consumer's pair: write the other one */
    alb_fence();       /* the last store of Actual before loading ReadLocked */
    word = alb_rd32(ch->base);
    read_locked = ctl_byte(word, ALB_OFF_READLOCKED);
    if (read_locked == ALB_NOT_STARTED)
        read_locked = ALB_BUFFER1;     /* consumer not started: as its init will */
    if (ALB_FS_VALID_INDEX(read_locked)) {
        pair = 1u - ALB_FS_PAIR(read_locked);
    } else {
        pair = 1u - ALB_FS_PAIR(ch->fs_actual);   /* a faulty consumer: keep going */
        result = ALB_ERR_CORRUPT;
    }
    /* 2. the slot of that pair not completed last */
    slot = 1u - ch->slot[pair];
    *buffer = (uint8_t)ALB_FS_BUFFER(pair, slot);
    return result;
}

/* Export step 4 (after the payload and a release fence): the pair's slot
 * byte names the completed slot; then a fence, the slot byte before Actual. */
static void fs_complete(alb_channel_t *ch, uint8_t buffer)
{
    unsigned pair = ALB_FS_PAIR(buffer), slot = ALB_FS_SLOT(buffer);

    alb_wr8(ch->base + ALB_OFF_SLOT(pair), (uint8_t)slot);
    ch->slot[pair] = (uint8_t)slot;
    alb_fence();                       /* the slot byte before Actual */
}
#endif

#if ALB_FOUR_SLOT_IMPORT
/* Import steps 1 to 4: the buffer to read, *buffer, and the result:
 * ALB_NEW, ALB_OLD, ALB_ERR_CORRUPT (nothing to read) or ALB_ERR_ARG;
 * FS_NOTHING (negative, private) for Actual = 0, nothing published yet:
 * fs_import reads nothing and returns ALB_OLD. */
#define FS_NOTHING (-3)
static int fs_select_read(alb_channel_t *ch, uint8_t *buffer)
{
    uint32_t word;
    uint8_t latest, slot;
    unsigned pair;
    int result;

    if (!ALB_FS_VALID_INDEX(ch->fs_read_locked))
        return ALB_ERR_ARG;
    /* 1. the latest buffer */
    word = alb_rd32(ch->base);
    latest = ctl_byte(word, ALB_OFF_ACTUAL);
    if (!ALB_FS_VALID_INDEX(latest))   /* 0: nothing published yet (cold start) */
        return latest == ALB_NOT_STARTED ? FS_NOTHING : ALB_ERR_CORRUPT;
    /* 2. nothing new: the buffer read last, still protected by ReadLocked */
    if (latest == ch->last) {
        *buffer = latest;
        return ALB_OLD;
    }
    /* 3. announce its pair: from now on the producer writes the other one */
    pair = ALB_FS_PAIR(latest);
    alb_wr8(ch->base + ALB_OFF_READLOCKED, latest);
    ch->fs_read_locked = latest;
    alb_fence();          /* store ReadLocked before loading the slot byte */
    /* 4. the slot of that pair completed last, loaded after the announcement */
    word = alb_rd32(ch->base);                     /* after the announcement */
    slot = ctl_byte(word, ALB_OFF_SLOT(pair));
    if (!ALB_FS_VALID_SLOT(slot))
        return ALB_ERR_CORRUPT;
    *buffer = (uint8_t)ALB_FS_BUFFER(pair, slot);
    /* 5. (the caller reads it) New unless it is the buffer read last */
    result = *buffer == ch->last ? ALB_OLD : ALB_NEW;
    ch->last = *buffer;
    return result;
}
#endif

/* The four-slot Import and Export: the helpers above, and one copy loop per
 * direction of their own, out of line (fs_copy_in, fs_copy_out) so that the
 * three-buffer path, below, keeps the paper's code and its cost: a load and
 * a branch for the kind are all it pays. */
#ifdef __GNUC__
#define ALB_NOINLINE static __attribute__((__noinline__))
#else
#define ALB_NOINLINE static
#endif
#if ALB_FOUR_SLOT_IMPORT
ALB_NOINLINE void fs_copy_in(const alb_channel_t *ch, uint8_t buffer, void *dst)
{
    read_from(ch, buffer, dst);
}

ALB_NOINLINE int fs_import(alb_channel_t *ch, void *dst)
{
    uint8_t buffer;
    int result = fs_select_read(ch, &buffer);   /* steps 1-4 */

    if (result < 0)     /* an error, or nothing published yet: Old, no read */
        return result == FS_NOTHING ? ALB_OLD : result;
    alb_fence();              /* acquire: the control loads before the data */
    fs_copy_in(ch, buffer, dst);                 /* step 5 */
    alb_fence();   /* release: these data loads before the next ReadLocked store */
    return result;
}
#define ALB_FS_IMPORT(ch, dst) fs_import(ch, dst)
#else
#define ALB_FS_IMPORT(ch, dst) ALB_ERR_ARG
#endif

#if ALB_FOUR_SLOT_EXPORT
ALB_NOINLINE void fs_copy_out(const alb_channel_t *ch, uint8_t buffer, const void *src)
{
    write_to(ch, buffer, src);
}

ALB_NOINLINE int fs_export(alb_channel_t *ch, const void *src)
{
    uint8_t buffer;
    int result;

    if (!ALB_FS_VALID_INDEX(ch->fs_actual))
        return ALB_ERR_ARG;
    result = fs_select_write(ch, &buffer);      /* steps 1-2 */
    fs_copy_out(ch, buffer, src);               /* step 3 */
    alb_fence();                 /* release: the data before the slot byte */
    fs_complete(ch, buffer);                     /* step 4, fence */
    alb_wr8(ch->base + ALB_OFF_ACTUAL, buffer);  /* step 5 */
    ch->fs_actual = buffer;
    return result;
}
#define ALB_FS_EXPORT(ch, src) fs_export(ch, src)
#else
#define ALB_FS_EXPORT(ch, src) ALB_ERR_ARG
#endif

/* ------------------------------------------------------------------------
 * Set-up, and the three-buffer kind (the four-slot kind branches off at the
 * top of each function). */

int alb_producer_init(alb_channel_t *ch, const void *initial)
{
    if (ch == 0 || ch->size == 0u || initial == 0 || !ALB_EXPORTS(ch->kind))
        return ALB_ERR_ARG;
    write_to(ch, ALB_BUFFER1, initial);
    alb_fence();
    if (ALB_FOUR_SLOT_EXPORT && ch->kind == ALB_FOUR_SLOT) {   /* both slot bytes, then Actual */
        alb_wr8(ch->base + ALB_OFF_SLOT0, (uint8_t)ALB_FS_INITIAL_SLOT);
        alb_wr8(ch->base + ALB_OFF_SLOT1, (uint8_t)ALB_FS_INITIAL_SLOT);
        ch->slot[0] = ch->slot[1] = (uint8_t)ALB_FS_INITIAL_SLOT;
        alb_fence();
        alb_wr8(ch->base + ALB_OFF_ACTUAL, ALB_BUFFER1);
        ch->fs_actual = ALB_BUFFER1;
        return ALB_OK;
    }
    alb_wr8(ch->base + ALB_OFF_ACTUAL, ALB_BUFFER1);
    ch->actual = ALB_BUFFER1;
    return ALB_OK;
}

int alb_producer_attach(alb_channel_t *ch)
{
    uint8_t actual;

    if (ch == 0 || ch->size == 0u || !ALB_EXPORTS(ch->kind))
        return ALB_ERR_ARG;
#if ALB_FOUR_SLOT_EXPORT
    if (ch->kind == ALB_FOUR_SLOT)
        return fs_producer_attach(ch);
#endif
    actual = alb_rd8(ch->base + ALB_OFF_ACTUAL);
    if (!ALB_VALID_INDEX(actual))      /* 0: never started, alb_producer_init */
        return actual == ALB_NOT_STARTED ? ALB_ERR_ARG : ALB_ERR_CORRUPT;
    ch->actual = actual;
    return ALB_OK;
}

int alb_consumer_init(alb_channel_t *ch)
{
    if (ch == 0 || ch->size == 0u || !ALB_IMPORTS(ch->kind))
        return ALB_ERR_ARG;
    alb_wr8(ch->base + ALB_OFF_READLOCKED, ALB_BUFFER1);
    alb_fence();
    if (ALB_FOUR_SLOT_IMPORT && ch->kind == ALB_FOUR_SLOT) {
        ch->fs_read_locked = ALB_BUFFER1;
        ch->last = ALB_BUFFER1;        /* Buffer1's value counts as read */
        return ALB_OK;
    }
    ch->read_locked = ALB_BUFFER1;
    return ALB_OK;
}

int alb_consumer_attach(alb_channel_t *ch)
{
    uint8_t read_locked;

    if (ch == 0 || ch->size == 0u || !ALB_IMPORTS(ch->kind))
        return ALB_ERR_ARG;
    read_locked = alb_rd8(ch->base + ALB_OFF_READLOCKED);
    if (read_locked == ALB_NOT_STARTED)
        return ALB_ERR_ARG;            /* never started: alb_consumer_init */
#if ALB_FOUR_SLOT_IMPORT
    if (ch->kind == ALB_FOUR_SLOT)
        return fs_consumer_attach(ch, read_locked);
#endif
    if (!ALB_VALID_INDEX(read_locked))
        return ALB_ERR_CORRUPT;
    ch->read_locked = read_locked;
    return ALB_OK;
}

int alb_import(alb_channel_t *ch, void *dst)
{
#if ALB_THREE_BUFFER_IMPORT
    int result = ALB_OLD;
    uint8_t actual;

    /* A four-slot channel keeps ch->read_locked at 0: it takes the branch
     * for a side never set up, so the three-buffer path pays nothing. */
    if (ch == 0 || dst == 0 || !ALB_VALID_INDEX(ch->read_locked))
        return ch != 0 && dst != 0 && ch->kind == ALB_FOUR_SLOT ? ALB_FS_IMPORT(ch, dst) : ALB_ERR_ARG;

    /* --- Phase 1: select a buffer for read-access */
    actual = alb_rd8(ch->base + ALB_OFF_ACTUAL);
    while (actual != ch->read_locked) {
        if (!ALB_VALID_INDEX(actual))  /* 0: nothing published yet (cold start) */
            return actual == ALB_NOT_STARTED ? ALB_OLD : ALB_ERR_CORRUPT;
        ch->read_locked = actual;                           /* ReadLocked:= Actual */
        alb_wr8(ch->base + ALB_OFF_READLOCKED, actual);
        alb_fence();                  /* store ReadLocked before loading Actual */
        actual = alb_rd8(ch->base + ALB_OFF_ACTUAL);
        result = ALB_NEW;
    }
    alb_fence();                  /* acquire: load Actual before the data loads */

    /* --- Phase 2: read-access to the selected buffer */
    read_from(ch, ch->read_locked, dst);
    alb_fence();   /* release: these data loads before the next ReadLocked store */
    return result;
#else
    return ch != 0 && dst != 0 && ch->kind == ALB_FOUR_SLOT ? ALB_FS_IMPORT(ch, dst) : ALB_ERR_ARG;
#endif
}

int alb_export(alb_channel_t *ch, const void *src)
{
#if ALB_THREE_BUFFER_EXPORT
    uint8_t buffer, write_buffer = 0u, copy_of_read_locked;
    int result = ALB_OK;

    /* A four-slot channel keeps ch->actual at 0 (see alb_import). */
    if (ch == 0 || src == 0 || !ALB_VALID_INDEX(ch->actual))
        return ch != 0 && src != 0 && ch->kind == ALB_FOUR_SLOT ? ALB_FS_EXPORT(ch, src) : ALB_ERR_ARG;

    /* --- Phase 1: select a buffer for write-access */
    alb_fence();         /* the last store of Actual before loading ReadLocked */
    copy_of_read_locked = alb_rd8(ch->base + ALB_OFF_READLOCKED);
    /* Out of range, it excludes no buffer (one stays free).  0: the consumer
     * has not started (cold start), not an error; the loop below then picks
     * the buffer ReadLocked = Buffer1 would give (Buffer1 is picked only when
     * both others are excluded), as with the RAM image.  4..255: a faulty
     * consumer. */
    if (!ALB_VALID_INDEX(copy_of_read_locked) && copy_of_read_locked != ALB_NOT_STARTED)
        result = ALB_ERR_CORRUPT;
    for (buffer = ALB_BUFFER1; buffer <= ALB_BUFFER3; ++buffer)
        if (buffer != ch->actual && buffer != copy_of_read_locked)
            write_buffer = buffer;

    /* --- Phase 2: write-access to the selected buffer */
    write_to(ch, write_buffer, src);
    alb_fence();                 /* release: the data before the store of Actual */

    /* --- Phase 3: assign completely written buffer as actual */
    alb_wr8(ch->base + ALB_OFF_ACTUAL, write_buffer);
    ch->actual = write_buffer;
    return result;
#else
    return ch != 0 && src != 0 && ch->kind == ALB_FOUR_SLOT ? ALB_FS_EXPORT(ch, src) : ALB_ERR_ARG;
#endif
}

/* ------------------------------------------------------------------------
 * Sampling read (albatross.h): alb_import, then the status from the
 * payload's last word, taken_at.  No RAM access of its own: taken_at is
 * read from *dst, in the byte order read_from wrote it. */
int alb_read(alb_channel_t *ch, void *dst, uint32_t max_age_clocks, uint32_t now, alb_sample_t *st)
{
    const uint8_t *p;
    uint32_t taken_at, age;
    int r;

    if (ch == 0 || dst == 0 || st == 0 || ch->size < 4u || (ch->size & 3u) != 0u)
        return ALB_ERR_ARG;
    r = alb_import(ch, dst);
    if (r != ALB_NEW && r != ALB_OLD)
        return r;
    p = (const uint8_t *)dst + (ch->size - 4u);
    if (((uintptr_t)p & 3u) == 0u)
        taken_at = *(const alb_word *)p;
    else
        taken_at = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    age = now - taken_at;
    if ((int32_t)age < 0)
        age = 0u;          /* taken after now was read: no older than 0 */
    if (r == ALB_NEW)
        ch->received = 1u;
    st->is_new = (uint8_t)(r == ALB_NEW);
    st->age_clocks = age;
    if (!ch->received)
        st->status = ALB_SAMPLE_NEVER;
    else if (age > max_age_clocks)
        st->status = ALB_SAMPLE_STALE;
    else
        st->status = r == ALB_NEW ? ALB_SAMPLE_NEW : ALB_SAMPLE_OLD;
    return r;
}
