/*
 * four_slot.pml -- SPIN model of one ALBATROSS four-slot channel
 * (Simpson's four-slot mechanism, IEE Proc. E 1990, on the byte-wide
 * channel layout of rtl/albatross_contract.toml [layout.four_slot]).
 *
 * Channel: byte 0 Actual (producer), byte 1 ReadLocked (consumer), byte 2
 * Slot[0] and byte 3 Slot[1] (producer), then Buffer1..Buffer4.  Buffer b is
 * pair(b) = (b-1)>>1, slot(b) = (b-1)&1; buf(p,s) = 1 + 2p + s.  Initially
 * Actual = ReadLocked = 1, Slot[0] = Slot[1] = 0, the initial value in Buffer1.
 *
 * One producer does Exports forever, one consumer does Imports forever, over
 * all interleavings.  The abstraction (the same as albatross.pml):
 *
 *   - Each control byte is written by one side only.  A load or a store of one
 *     control byte is one atomic step: each byte is indivisible, nothing more.
 *     The drivers load the control word with one word load, which need NOT be
 *     indivisible.  Every such load uses exactly ONE byte of the word (the
 *     producer ReadLocked, the consumer Actual in step 1 and Slot[pair(A)] in
 *     step 4; the producer has private copies of the bytes it writes), so the
 *     model makes it one atomic load of that byte.  This is exact, not an
 *     approximation: a word load whose bytes are sampled at different instants
 *     and in any order behaves, for the one byte used, like an atomic load of
 *     that byte at its own sampling instant, and SPIN places that instant at
 *     every point of the interleaving.  The unused bytes cannot influence
 *     anything.  (Tearing between the bytes of one word is therefore covered.)
 *     The one load that uses more than one byte, step 1 of the controller's
 *     rule (-DOLD_BY_SLOT, below), is modelled as its byte loads in any order.
 *   - The producer reads nothing but ReadLocked: its private copies equal the
 *     RAM bytes it alone writes (the controller, which loads its Slot bytes
 *     back, gets the same values while its stores land; dropped or cut-off
 *     stores are not modelled here).
 *   - Nothing else is shared, so the local work goes into the step of the
 *     shared access it goes with.
 *   - A buffer is W data words (W = 1 or 2, default 2), h1 and h2.  The
 *     producer stores them in order, the consumer loads them in order, each
 *     its own step, so with W = 2 a read overlapping a write is visible (torn).
 *   - Data are stamps 0..NSTAMP-1 from a ghost allocator (the smallest stamp
 *     nothing holds any more), so equal stamps mean the same Export and the
 *     model is finite though both sides run forever.  Buffers 2..4 start as
 *     garbage (halves GARB1 != GARB2).  Ghost masks after[s] (bit t: t's write
 *     completed after s's) order the values without counters.
 *
 * Producer Export (private copies wa of Actual, ws[] of the slot bytes):
 *   1. R = ReadLocked; p = 1 - pair(R)          (one load)
 *   2. s = 1 - ws[p]                            (local)
 *   3. write the W words into buf(p,s)          (W stores)
 *   4. Slot[p] := s                             (one store)
 *   5. Actual := buf(p,s)                       (one store)     = W + 3
 * Consumer Import (private L = the buffer it read last, 0 = none):
 *   1. A = Actual                               (one load)
 *   2. if A == L: read the W words of L; Old     (1 + W accesses)
 *   3. else ReadLocked := A                     (one store)
 *   4. b = buf(pair(A), Slot[pair(A)])          (one load)
 *   5. read the W words of b; New if b != L, else Old; L := b   (3 + W)
 * The test "b != L" in step 5 is NOT in the mapping as first proposed: that
 * mapping returns New whenever A != L.  Built with -DNEW_IF_A_NE_L the model
 * is the mapping exactly, and CHECK_NEWOLD fails on it (the same value New
 * twice; see check.py and docs/verification.md).  Step 5 costs no access.
 *
 * Checks (one pan run each; formal/spin/check.py --model four_slot):
 *   CHECK_MUTEX      the producer never stores into the buffer the consumer has
 *                    chosen to read, from the choice to its last data load, and
 *                    the consumer never loads a word of the buffer being written
 *   CHECK_DEFINITE   an Import returns W equal words of one complete Export
 *                    (a real stamp), from a valid index 1..4; the producer's
 *                    buffer is valid and ReadLocked is valid when it reads it
 *   CHECK_ACTUALITY  the value is the one in Actual's buffer when the Import
 *                    began, or newer
 *   CHECK_NEWOLD     the value is never older than the previous Import's (never
 *                    back in time), and New exactly when it is newer than the
 *                    value the previous Import returned (first Import after
 *                    start or restart, L = 0: New)
 *   CHECK_BOUND      an Import makes exactly 1 + W shared accesses when it
 *                    takes the Old path and 3 + W otherwise (so at most 3 + W);
 *                    an Export exactly W + 3
 *   ltl reader_wait_free, writer_wait_free (weak fairness), lock_free: hold
 *
 * Options:
 *   -DW=1            one data word (default 2)
 *   -DL_INIT=1       consumer_init sets L = 1 (the initial value counts as
 *                    read: the first Import returns Old); default L = 0
 *   -DOLD_BY_SLOT    the controller's Import rule (docs/controller.md, rtl/
 *                    albatross_import.v): step 1 loads the control word and
 *                    takes Actual AND c = buf(pair(A), Slot[pair(A)]) from it;
 *                    Old if c == L, else steps 3-5 and always New.  That word
 *                    load uses three bytes, so it is modelled as three byte
 *                    loads (Actual, Slot0, Slot1) in any order with the
 *                    producer free to run between them (the word is not
 *                    indivisible, each byte is).
 *   -DCOLD_START     a zeroed RAM (docs/protocol.md "Cold start"): Actual,
 *                    ReadLocked and the slot bytes start as 0, every buffer as
 *                    garbage; the producer first runs alb_producer_init
 *                    (Buffer1 := v0, Slot0 := Slot1 := 0, Actual := 1), the
 *                    consumer first alb_consumer_init (ReadLocked := 1), each
 *                    at any point of the other's run.  An Import that loads
 *                    Actual = 0 reads nothing; an Export that loads
 *                    ReadLocked = 0 takes it as Buffer1 (writes pair 1).
 *                    Run with -DL_INIT=1, as the driver's consumer_init.
 *   -DCOLD_PAIR_OF_ACTUAL  with COLD_START, broken: ReadLocked = 0 makes the
 *                    producer write the pair other than its own Actual's
 *                    (the driver's rule before the cold-start contract)
 *   -DCRASH          the consumer may crash instead of any of its accesses
 *                    (any number of times) and restart with L = 0;
 *                    -DCRASH_ONCE: at most one crash (smaller state space)
 * Broken variants (each must fail the check named in check.py):
 *   -DWRONG_ORDER        consumer loads Slot[pair(A)] before storing ReadLocked
 *   -DINDEX_FROM_ACTUAL  consumer stores ReadLocked and reads buffer A itself
 *   -DIGNORE_READLOCKED  producer picks p = 1 - pair(own Actual), no ReadLocked
 *   -DRL_AS_LAST         consumer decides New by A != its copy of ReadLocked
 *   -DSLOT_AFTER_ACTUAL  producer stores Actual before Slot[p]
 *   -DNEW_IF_A_NE_L      the lead's mapping as written: New whenever A != L
 *   -DREREAD             consumer re-loads Actual after its data loads and, if
 *                        it changed, announces it and reads again (the
 *                        three-buffer While on top of the four slots):
 *                        the negative of reader_wait_free and CHECK_BOUND
 */

#ifndef W
#define W 2
#endif
#ifdef CRASH_ONCE
#define CRASH
#define MAXCRASH 1
#endif
#ifndef L_INIT
#define L_INIT 0
#endif
#ifdef RL_AS_LAST
#undef L_INIT
#define L_INIT 1          /* the variant keeps L only to have a buffer to read */
#endif

#define NSTAMP 8          /* stamps in 4 buffers + r1 + last + base, and 1 free */
#define NONE   255
#define GARB1  14         /* initial garbage halves of buffers 2..4 */
#define GARB2  15
#define OLD    0
#define NEW    1    /* printed as result 1 = New, 0 = Old */

/* count one shared access (saturating, so a retry loop stays finite) */
#define ACC       acc = (acc < 15 -> acc + 1 : acc)
#define PAIR(b)   (((b) - 1) >> 1)
#define SLOTOF(b) (((b) - 1) & 1)
#define BUF(p, s) (1 + 2 * (p) + (s))

/* shared: the four control bytes and the four buffers (index 0 unused) */
#ifdef COLD_START
byte Actual = 0;
byte ReadLocked = 0;
#else
byte Actual = 1;
byte ReadLocked = 1;
#endif
byte Slot[2];
byte h1[5];
byte h2[5];

/* ghost state of the checks (never read by the protocol) */
bool reading = 0;         /* consumer between choosing its buffer and its last load */
byte rbuf = 0;            /* the buffer it chose */
bool writing = 0;         /* producer between its first and last data store */
byte wbuf = 0;            /* the buffer it writes */
bool importing = 0;
bool exporting = 0;
byte r1 = NONE;           /* consumer's register: the first word read */
byte last = NONE;         /* stamp the previous Import returned (NONE: nothing) */
byte base = NONE;         /* stamp in Actual's buffer when this Import began */
byte after[NSTAMP];       /* after[s] bit t: t's write completed after s's */
#ifdef CRASH
#ifndef MAXCRASH
#define MAXCRASH 255      /* crashes explored per run (255: unbounded) */
#endif
byte crashes = 0;         /* crashes so far (saturates when unbounded) */
#if MAXCRASH == 255
#define CRASHES :: goto restart
#else
#define CRASHES :: crashes < MAXCRASH -> goto restart
#endif
#else
#define CRASHES
#endif

#if defined(CHECK_DEFINITE) || defined(CHECK_ACTUALITY) || defined(CHECK_NEWOLD)
#define STAMPS
#endif
#if defined(CHECK_ACTUALITY) || defined(CHECK_NEWOLD)
#define ORDER
#endif

inline in_use(t, u) {
    u = (t == r1 || t == last || t == base ||
         t == h1[1] || t == h1[2] || t == h1[3] || t == h1[4] ||
         t == h2[1] || t == h2[2] || t == h2[3] || t == h2[4])
}

/* Forget the order facts of stamps nobody holds (keeps states canonical). */
inline gc(t, i, u) {
#ifdef ORDER
    t = 0;
    do
    :: t < NSTAMP ->
       in_use(t, u);
       if
       :: !u ->
          after[t] = 0;
          i = 0;
          do
          :: i < NSTAMP -> after[i] = after[i] & ~(1 << t); i++
          :: else -> break
          od
       :: else -> skip
       fi;
       t++
    :: else -> break
    od;
    t = 0; i = 0; u = 0
#else
    skip
#endif
}

/* the last data store: the write of stamp s is complete */
inline write_done(t, i, u) {
    writing = 0; wbuf = 0;
#ifdef ORDER
    do
    :: t < NSTAMP -> after[t] = after[t] | (1 << s); t++
    :: else -> break
    od;
    after[s] = 0;
    t = 0;
#endif
    gc(t, i, u)
}

proctype producer()
{
    byte wa = 1;                     /* private copy of Actual */
    byte ws[2];                      /* private copies of Slot[0], Slot[1] */
    byte r, p, sl, w, s, t, i, acc;
    bool u;

#ifdef COLD_START
    /* alb_producer_init: Buffer1 := v0 (two stores), the slot bytes := 0
     * (already 0 on a zeroed RAM), Actual := Buffer1 */
    d_step {
        exporting = 1;
#ifdef CHECK_MUTEX
        assert(!(reading && rbuf == 1));
#endif
        writing = 1; wbuf = 1; h1[1] = 0;
        printf("P: init: store Buffer1 word1 := v0\n")
    };
    d_step {
#ifdef CHECK_MUTEX
        assert(!(reading && rbuf == 1));
#endif
        h2[1] = 0; writing = 0; wbuf = 0;
        printf("P: init: store Buffer1 word2 := v0\n")
    };
    d_step { Actual = 1; exporting = 0; printf("P: init: store Actual := 1\n") };
#endif
    do
    :: /* 1. load the control word, use ReadLocked; 2. choose the slot */
       d_step {
           exporting = 1;
           r = ReadLocked;
           acc = 1;
#ifdef COLD_START
#ifdef COLD_PAIR_OF_ACTUAL
           if :: r == 0 -> r = 1 + 2 * (1 - PAIR(wa)) :: else -> skip fi;  /* broken */
#else
           if :: r == 0 -> r = 1 :: else -> skip fi;   /* not started: Buffer1 */
#endif
#endif
#ifdef CHECK_DEFINITE
           assert(r >= 1 && r <= 4);
#endif
#ifdef IGNORE_READLOCKED
           p = 1 - PAIR(wa);
#else
           p = 1 - PAIR(r);
#endif
           sl = 1 - ws[p];
           w = BUF(p, sl);
           printf("P: load ReadLocked=%d -> write Buffer%d (pair %d slot %d)\n", r, w, p, sl);
           r = 0
       };
       /* 3. the W data stores; a ghost picks a fresh stamp */
       d_step {
#ifdef STAMPS
           s = NONE; t = 0;
           do
           :: t < NSTAMP ->
              in_use(t, u);
              if :: !u && s == NONE -> s = t :: else -> skip fi;
              t++
           :: else -> break
           od;
           t = 0; u = 0;
           assert(s != NONE);            /* the model's own bound */
#else
           s = 0;
#endif
#ifdef CHECK_DEFINITE
           assert(w >= 1 && w <= 4);
#endif
#ifdef CHECK_MUTEX
           assert(!(reading && rbuf == w));
#endif
           writing = 1; wbuf = w;
           h1[w] = s;
           printf("P: store Buffer%d word1 := v%d\n", w, s);
           ACC;
#if W == 1
           h2[w] = s;                    /* ghost: one word, h2 mirrors h1 */
           write_done(t, i, u)
#else
           gc(t, i, u)
#endif
       };
#if W == 2
       d_step {
#ifdef CHECK_MUTEX
           assert(!(reading && rbuf == w));
#endif
           h2[w] = s;
           printf("P: store Buffer%d word2 := v%d\n", w, s);
           ACC;
           write_done(t, i, u)
       };
#endif
#ifdef SLOT_AFTER_ACTUAL
       d_step { Actual = w; wa = w; ACC; printf("P: store Actual := %d\n", w) };
       d_step {
           Slot[p] = sl; ws[p] = sl; ACC;
           printf("P: store Slot%d := %d\n", p, sl);
#else
       /* 4. Slot[p] := s;  5. Actual := buf(p,s) */
       d_step { Slot[p] = sl; ws[p] = sl; ACC; printf("P: store Slot%d := %d\n", p, sl) };
       d_step {
           Actual = w; wa = w; ACC;
           printf("P: store Actual := %d\n", w);
#endif
#ifdef CHECK_BOUND
           assert(acc == W + 3);
#endif
           acc = 0; w = 0; s = 0; p = 0; sl = 0;
           exporting = 0
       }
    od
}

proctype consumer()
{
    byte L = L_INIT;                 /* private: the buffer read last, 0 = none */
    byte rl = 1;                     /* private copy of the ReadLocked it stored */
    byte a, b, v1, v2, t, i, acc;
    bool result, expect, newpath, u;
#ifdef OLD_BY_SLOT
    byte got, c0, c1, c;
#endif

#ifdef COLD_START
    d_step { ReadLocked = 1; rl = 1; printf("C: init: store ReadLocked := 1\n") };
#endif

    /* CRASHES: with -DCRASH every access below may instead be a crash (the
     * access does not happen; the consumer restarts).  Crashing before each
     * access also covers crashing after the last one (no shared effect). */
again:
    do
    :: /* ghost: the Import begins; remember the newest published value */
       d_step {
           importing = 1;
#ifdef CHECK_ACTUALITY
           if :: Actual != 0 -> base = h1[Actual] :: else -> base = NONE fi;
#endif
           result = OLD; acc = 0
       };
#ifdef OLD_BY_SLOT
       /* 1. (the controller's rule) one word load of Actual, Slot0, Slot1:
        * three byte loads in any order, the producer free to run between
        * them; c = buf(pair(A), Slot[pair(A)]) of that word; Old if c == L */
       if
       :: got = 0
       CRASHES
       fi;
       do
       :: !(got & 1) -> d_step { a = Actual; got = got | 1;
                                 printf("C: load Actual=%d (byte of word 1)\n", a) }
       :: !(got & 2) -> d_step { c0 = Slot[0]; got = got | 2;
                                 printf("C: load Slot0=%d (byte of word 1)\n", c0) }
       :: !(got & 4) -> d_step { c1 = Slot[1]; got = got | 4;
                                 printf("C: load Slot1=%d (byte of word 1)\n", c1) }
       :: got == 7 -> break
       od;
       atomic {           /* not d_step: the break jumps here */
           ACC;
           c = BUF(PAIR(a), (PAIR(a) == 0 -> c0 : c1));
           printf("C: word 1: Actual=%d c=%d (L=%d)\n", a, c, L);
           newpath = (c != L);
           if
           :: !newpath -> b = L; reading = 1; rbuf = b
           :: else -> skip
           fi;
           got = 0; c0 = 0; c1 = 0; c = 0
       };
#else
       /* 1. load the control word, use Actual */
       if
       :: d_step {
           a = Actual;
           ACC;
           printf("C: load Actual=%d (L=%d)\n", a, L);
#ifdef RL_AS_LAST
           newpath = (a != rl);
#else
           newpath = (a != L);
#endif
           if
           :: !newpath -> b = L; reading = 1; rbuf = b
           :: else -> skip
           fi
          }
       CRASHES
       fi;
#endif
#ifdef COLD_START
       if       /* Actual = 0: nothing published yet, the Import reads nothing */
       :: a == 0 -> d_step { reading = 0; rbuf = 0; b = 0; newpath = 0; acc = 0;
                             base = NONE; importing = 0; printf("C: Actual=0: Old, nothing read\n") };
                    goto again
       :: else -> skip
       fi;
#endif
       if
       :: newpath ->
#ifdef WRONG_ORDER
          /* the slot byte first, then ReadLocked */
          if :: d_step { b = BUF(PAIR(a), Slot[PAIR(a)]); ACC; reading = 1; rbuf = b;
                   printf("C: load Slot%d -> Buffer%d\n", PAIR(a), b) } CRASHES fi;
          if :: d_step { ReadLocked = a; rl = a; ACC;
                   printf("C: store ReadLocked := %d\n", a) } CRASHES fi
#elif defined(INDEX_FROM_ACTUAL)
          /* ReadLocked, then the buffer Actual named (the slot byte unread) */
          if :: d_step { ReadLocked = a; rl = a; ACC;
                   printf("C: store ReadLocked := %d\n", a) } CRASHES fi;
          d_step { b = a; ACC; reading = 1; rbuf = b;
                   printf("C: (no slot load) Buffer%d\n", b) }
#else
          /* 3. ReadLocked := A;  4. load the control word, use Slot[pair(A)] */
#ifdef REREAD
retry:
#endif
          if :: d_step { ReadLocked = a; rl = a; ACC;
                   printf("C: store ReadLocked := %d\n", a) } CRASHES fi;
          if :: d_step { b = BUF(PAIR(a), Slot[PAIR(a)]); ACC; reading = 1; rbuf = b;
                   printf("C: load Slot%d -> Buffer%d\n", PAIR(a), b) } CRASHES fi
#endif
       :: else -> skip
       fi;
       /* the W data loads of buffer b */
       if
       :: d_step {
#ifdef CHECK_DEFINITE
           assert(b >= 1 && b <= 4);
#endif
#ifdef CHECK_MUTEX
           assert(!(writing && wbuf == b));
#endif
           v1 = h1[b];
           ACC;
           printf("C: load Buffer%d word1 = v%d\n", b, v1);
#ifdef STAMPS
           r1 = v1;
#endif
#if W == 1
           v2 = h2[b];
           reading = 0; rbuf = 0
#endif
          }
       CRASHES
       fi;
#if W == 2
       if
       :: d_step {
#ifdef CHECK_MUTEX
           assert(!(writing && wbuf == b));
#endif
           v2 = h2[b];
           ACC;
           printf("C: load Buffer%d word2 = v%d\n", b, v2);
           reading = 0; rbuf = 0
          }
       CRASHES
       fi;
#endif
#ifdef REREAD
       /* broken: re-check Actual after the read, start again if it moved */
       if
       :: d_step { ACC; t = Actual; printf("C: re-load Actual=%d\n", t) }
       CRASHES
       fi;
       if
       :: t != a -> d_step { a = t; t = 0; newpath = 1 }; goto retry
       :: else -> t = 0
       fi;
#endif
       /* 5. the result; ghost: the checks */
       d_step {
#if defined(NEW_IF_A_NE_L) || defined(OLD_BY_SLOT)
           result = newpath;
#else
           result = (newpath && b != L);
#endif
           printf("C: Import returns %d v%d (%d accesses)\n", result, v1, acc);
           L = b;
#ifdef CHECK_BOUND
           assert(acc <= 3 + W);
           assert((newpath && acc == 3 + W) || (!newpath && acc == 1 + W));
#endif
#ifdef CHECK_DEFINITE
           assert(v1 == v2 && v1 < NSTAMP);
#endif
#ifdef CHECK_ACTUALITY
           assert(base == NONE || v1 == base || (after[base] & (1 << v1)) != 0);
#endif
#ifdef CHECK_NEWOLD
           if
           :: last == NONE -> expect = NEW
           :: else ->
              expect = (v1 != last && (after[last] & (1 << v1)) != 0);
              assert(v1 == last || expect)      /* never back in time */
           fi;
           assert(result == expect);
           if :: v1 < NSTAMP -> last = v1 :: else -> skip fi;
#endif
           r1 = NONE; base = NONE;
           a = 0; b = 0; v1 = 0; v2 = 0; acc = 0;
           result = 0; expect = 0; newpath = 0;
           gc(t, i, u);
           importing = 0
       }
    od;
#ifdef CRASH
restart:
    /* the private state is lost, the shared bytes stay; attach: L = 0 */
    atomic {
        printf("C: crash, restart with L=0\n");
#if MAXCRASH != 255
        crashes++;
#endif
        L = 0; rl = ReadLocked;
        reading = 0; rbuf = 0;
        r1 = NONE; base = NONE; last = NONE;
        a = 0; b = 0; v1 = 0; v2 = 0; acc = 0;
        result = 0; expect = 0; newpath = 0;
        gc(t, i, u);
        importing = 0
    };
    goto again
#endif
}

init {
    /* producer_init: Buffer1 holds stamp 0 (the initial value); 2..4 garbage */
    d_step {
#ifdef COLD_START
        h1[1] = GARB1; h2[1] = GARB2;  /* the producer's init writes Buffer1 */
#else
        h1[1] = 0; h2[1] = 0;
#endif
        h1[2] = GARB1; h2[2] = GARB2;
        h1[3] = GARB1; h2[3] = GARB2;
        h1[4] = GARB1; h2[4] = GARB2;
#if L_INIT == 1
        last = 0                         /* the initial value counts as read */
#else
        skip
#endif
    };
    atomic { run producer(); run consumer() }
}

/* The consumer's Import always finishes, whatever the producer does (weak
 * fairness only keeps the consumer scheduled).  Fails for albatross.pml. */
ltl reader_wait_free { [] <> !importing }
/* Export has no loop. */
ltl writer_wait_free { [] <> !exporting }
/* Some operation always completes, no fairness assumption. */
ltl lock_free { [] <> (!importing || !exporting) }
