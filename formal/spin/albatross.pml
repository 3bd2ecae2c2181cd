/*
 * albatross.pml -- SPIN model of one ALBATROSS three-buffer channel
 * (the paper, section 3.1, figures 2-4; c-driver/albatross.c alb_import/alb_export).
 *
 * One writer process does Exports forever, one reader process does Imports
 * forever, over all interleavings.  The abstraction:
 *
 *   - Actual and ReadLocked are one byte each; a load or a store of one of
 *     them is one atomic step (byte atomicity is all the RAM guarantees).
 *     Nothing else is shared, so every other statement may be merged into
 *     the step of the shared access it goes with.
 *   - A buffer is two halves, h1 and h2.  WriteTo stores h1 then h2, ReadFrom
 *     loads h1 then h2: four separate steps, so a read that overlaps a write
 *     returns halves from different Exports (a torn read) and the model sees it.
 *   - The data of an Export is a stamp 0..NSTAMP-1.  A ghost allocator gives
 *     each Export the smallest stamp that nobody holds any more (no buffer
 *     half, not the reader's half-read register, not the values the checks
 *     remember), so equal stamps mean the same Export and the model stays
 *     finite though the writer runs forever.  Buffers 2 and 3 start as
 *     garbage (two halves that differ: GARB1, GARB2).
 *   - Ghost "completed after" masks (after[s] = set of stamps whose Export
 *     finished writing after stamp s's) give the order of values without
 *     unbounded counters.
 *
 * The properties (each a separate run of pan; see tools/mk/formal_spin.mk):
 *   CHECK_MUTEX      mutual exclusion (the paper's proof point "Mutual exclusion")
 *   CHECK_DEFINITE   definite results (the paper's proof point "Definite results")
 *   CHECK_ACTUALITY  actuality (the paper's proof point "Actuality", demand b)
 *   CHECK_NEWOLD     the Import's New/Old result (LookForNew: "is this
 *                    information ever being read before?")
 *   CHECK_RETRY      every extra pass of the reader's While is paid for by
 *                    an Export completed in between (lock-freedom, step form)
 *   ltl reader_wait_free  must FAIL under weak fairness: a fast writer
 *                    starves the reader (the paper's proof point "Termination" holds
 *                    only for a writer that stops)
 *   ltl writer_wait_free, ltl lock_free  hold
 *
 * -DCOLD_START: the cold start on a zeroed RAM (docs/protocol.md, "Cold
 * start"): Actual, ReadLocked and every buffer start as 0 / garbage; the
 * writer first runs alb_producer_init (Buffer1 := stamp 0, then Actual := 1),
 * the reader first alb_consumer_init (ReadLocked := 1), each at any point of
 * the other's run; an Import that loads Actual = 0 reads nothing (ALB_OLD,
 * *dst unchanged) and an Export that loads ReadLocked = 0 excludes no buffer
 * for it.  Every property above is checked this way too (cold_*).
 *
 * Broken variants (the driver mutants of tb/mutants/):
 *   -DWHILE_AS_IF        while_as_if.sed: the reader's While becomes an If
 *   -DIGNORE_READLOCKED  ignore_readlocked.sed: the writer does not exclude
 *                        the buffer named by ReadLocked
 *   -DCOLD_READ_ZERO     with COLD_START: an Import that loads Actual = 0
 *                        reads Buffer1 as if the RAM image had set Actual
 *                        (it may meet alb_producer_init writing it)
 */

#define NSTAMP 8          /* at most 4 stamps in the buffers + r1 + last + base */
#define NONE   255
#define GARB1  14         /* initial garbage halves of buffers 2 and 3 */
#define GARB2  15
#define OLD    0
#define NEW    1

/* shared: the two control bytes (figure 2), initial value Buffer1 (the RAM
 * image), or 0 on a zeroed RAM (COLD_START) */
#ifdef COLD_START
byte Actual = 0;
byte ReadLocked = 0;
#else
byte Actual = 1;
byte ReadLocked = 1;
#endif
/* shared: the three buffers (index 0 unused), two halves each */
byte h1[4];
byte h2[4];

/* ghost state of the checks (never read by the protocol) */
bool reading = 0;         /* reader between leaving Phase 1 and end of ReadFrom */
bool writing = 0;         /* writer between its first and last half store */
byte wbuf = 0;            /* the buffer the writer is writing */
bool importing = 0;       /* reader inside an Import */
bool exporting = 0;       /* writer inside an Export */
byte r1 = NONE;           /* reader's register: the half it has read */
#ifdef CHECK_NEWOLD
byte last = 0;            /* stamp the previous Import returned (initial value) */
#else
byte last = NONE;
#endif
byte base = NONE;         /* stamp in Actual's buffer when this Import began */
byte after[NSTAMP];       /* after[s] bit t: t finished writing after s */
bool exp_done = 0;        /* an Export completed since the reader last loaded Actual */

/* Which ghosts a run needs: the data stamps only for the checks that look at
 * the data, the order of the values only for actuality and New/Old.  A run
 * without them writes stamp 0 everywhere (fewer states, same protocol). */
#if defined(CHECK_DEFINITE) || defined(CHECK_ACTUALITY) || defined(CHECK_NEWOLD)
#define STAMPS
#endif
#if defined(CHECK_ACTUALITY) || defined(CHECK_NEWOLD)
#define ORDER
#endif

inline in_use(t, u) {
    u = (t == r1 || t == last || t == base ||
         t == h1[1] || t == h1[2] || t == h1[3] ||
         t == h2[1] || t == h2[2] || t == h2[3])
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

proctype writer()
{
    byte wa = 1;                     /* the writer's shadow of Actual */
    byte copy, buffer, w, s, t, i;
    bool u;

#ifdef COLD_START
    /* alb_producer_init: Buffer1 := the initial value (stamp 0), two half
     * stores, then Actual := Buffer1 */
    d_step {
        exporting = 1;
#ifdef CHECK_MUTEX
        assert(!(reading && ReadLocked == 1));
#endif
        writing = 1; wbuf = 1;
        h1[1] = 0
    };
    d_step {
#ifdef CHECK_MUTEX
        assert(!(reading && ReadLocked == 1));
#endif
        h2[1] = 0;
        writing = 0; wbuf = 0
    };
    d_step { Actual = 1; exporting = 0 };
#endif
    do
    :: /* --- Phase 1: select a buffer for write-access (one shared load) */
       d_step {
           exporting = 1;
           copy = ReadLocked;        /* CopyOfReadLocked:= ReadLocked */
           w = 0;
           buffer = 1;
           do
           :: buffer <= 3 ->
#ifdef IGNORE_READLOCKED
              if :: buffer != wa -> w = buffer :: else -> skip fi;
#else
              if :: buffer != wa && buffer != copy -> w = buffer :: else -> skip fi;
#endif
              buffer++
           :: else -> break
           od;
           buffer = 0; copy = 0
       };
       /* --- Phase 2: WriteTo, two half stores; a ghost picks a fresh stamp */
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
           assert(w >= 1 && w <= 3);     /* a valid WriteBuffer */
#endif
#ifdef CHECK_MUTEX
           assert(!(reading && w == ReadLocked));
#endif
           writing = 1; wbuf = w;
           h1[w] = s;
           gc(t, i, u)
       };
       d_step {
#ifdef CHECK_MUTEX
           assert(!(reading && w == ReadLocked));
#endif
           h2[w] = s;
           writing = 0; wbuf = 0;
#ifdef ORDER
           /* s is now the newest complete value */
           do
           :: t < NSTAMP -> after[t] = after[t] | (1 << s); t++
           :: else -> break
           od;
           after[s] = 0;
           t = 0;
#endif
           gc(t, i, u)
       };
       /* --- Phase 3: assign the completely written buffer as actual */
       d_step {
           Actual = w;
           wa = w;
#ifdef CHECK_RETRY
           exp_done = 1;
#endif
           w = 0; s = 0;
           exporting = 0
       }
    od
}

proctype reader()
{
    byte rl = 1;                     /* the reader's shadow of ReadLocked */
    byte actual, v1, v2, t, i;
    bool result, expect, u;
    bool nothing = 0;                /* COLD_START: Actual was 0, nothing read */

#ifdef COLD_START
    d_step { ReadLocked = 1; rl = 1 };   /* alb_consumer_init */
#endif
    do
    :: /* ghost: the Import begins; remember the newest completed value */
       d_step {
           importing = 1;
#ifdef CHECK_ACTUALITY
           /* nothing published yet (Actual = 0): any value is new enough */
           if :: Actual != 0 -> base = h1[Actual] :: else -> base = NONE fi;
#endif
           result = OLD                  /* Import:= Old */
       };
       /* --- Phase 1: select a buffer for read-access (driver form: the
        * While compares with the reader's own copy of ReadLocked) */
       d_step {
           actual = Actual;
#ifdef COLD_READ_ZERO
           if :: actual == 0 -> actual = 1 :: else -> skip fi;
#endif
#ifdef CHECK_RETRY
           exp_done = 0;
#endif
           reading = (actual == rl)      /* confirmed: the lock holds from here */
       };
#ifdef WHILE_AS_IF
       if
       :: actual != rl ->
#else
       do
       :: actual == 0 -> nothing = 1; break   /* nothing published: ALB_OLD */
       :: actual != 0 && actual != rl ->
#endif
#ifdef WHILE_AS_IF
          /* ReadLocked:= Actual; Import:= New; and no re-check */
          d_step { rl = actual; ReadLocked = actual; reading = 1; result = NEW }
#else
          d_step { rl = actual; ReadLocked = actual };   /* ReadLocked:= Actual */
#endif
#ifndef WHILE_AS_IF
          d_step {
              actual = Actual;
#ifdef COLD_READ_ZERO
              if :: actual == 0 -> actual = 1 :: else -> skip fi;
#endif
#ifdef CHECK_RETRY
              /* a further pass happens only if an Export completed */
              assert(actual == rl || exp_done);
              exp_done = 0;
#endif
              reading = (actual == rl);
              result = NEW
          }
#endif
#ifdef WHILE_AS_IF
       :: else -> skip
       fi;
#else
       :: else -> break
       od;
#endif
       if
       :: nothing ->
          d_step { nothing = 0; actual = 0; result = 0; base = NONE; importing = 0 }
       :: else ->
       /* --- Phase 2: ReadFrom(ReadLocked), two half loads (atomic, not
        * d_step: the While's break jumps here) */
       atomic {
#ifdef CHECK_DEFINITE
           assert(rl >= 1 && rl <= 3);   /* a valid buffer index */
#endif
#ifdef CHECK_MUTEX
           assert(!(writing && wbuf == rl));
#endif
           v1 = h1[rl];
#ifdef STAMPS
           r1 = v1
#endif
       };
       d_step {
#ifdef CHECK_MUTEX
           assert(!(writing && wbuf == rl));
#endif
           v2 = h2[rl];
           reading = 0
       };
       /* ghost: the Import returns (v1, v2) and result; the checks */
       d_step {
#ifdef CHECK_DEFINITE
           /* both halves from one Export whose write was complete: a real
            * stamp (not garbage) and the same in both halves */
           assert(v1 == v2 && v1 < NSTAMP);
#endif
#ifdef CHECK_ACTUALITY
           /* at least as new as the last Export completed before the start */
           assert(base == NONE || v1 == base || (after[base] & (1 << v1)) != 0);
#endif
#ifdef CHECK_NEWOLD
           /* New exactly when newer than the previous Import's value, and
            * never older than it */
           expect = (v1 != last && (after[last] & (1 << v1)) != 0);
           assert(v1 == last || expect);
           assert(result == expect);
#endif
#ifdef CHECK_NEWOLD
           if :: v1 < NSTAMP -> last = v1 :: else -> skip fi;
#endif
           r1 = NONE; base = NONE;
           v1 = 0; v2 = 0; actual = 0; result = 0; expect = 0;
           gc(t, i, u);
           importing = 0
       }
       fi
    od
}

init {
    /* producer_init: Buffer1 holds stamp 0; buffers 2, 3 garbage (a cold
     * start: every buffer garbage, the writer's init writes Buffer1) */
    d_step {
#ifdef COLD_START
        h1[1] = GARB1; h2[1] = GARB2;
#else
        h1[1] = 0; h2[1] = 0;
#endif
        h1[2] = GARB1; h2[2] = GARB2;
        h1[3] = GARB1; h2[3] = GARB2
    };
    atomic { run writer(); run reader() }
}

/* Termination of Import: "the reader's Import always eventually finishes".
 * Expected to FAIL (pan -a -f): a writer that keeps exporting changes Actual
 * between the reader's store of ReadLocked and its re-check, forever. */
ltl reader_wait_free { [] <> !importing }
/* Export has no loop: it always finishes (pan -a -f). */
ltl writer_wait_free { [] <> !exporting }
/* Lock-freedom: in every infinite run some operation keeps completing,
 * with no fairness assumption at all (pan -a). */
ltl lock_free { [] <> (!importing || !exporting) }
