# tools/mk/host_threads.mk -- the real driver on two host threads over ordinary
# shared memory (tb/host_threads/host_threads.c, judged by
# tools/host_threads.py).  x86-64 has store buffers: the store-buffering
# pattern the driver's fences guard against really happens here.
#   make test-host-threads          the unchanged mmio port, both kinds, payloads
#                                   of 2 and 8 words, 15 M checked Imports each
#                                   (60 M in all, about 5 s on this machine)
# Every run goes on past its Imports until the producer has overtaken (an
# Export completed during the Import) the number of them given by
# --min-overtaken, up to 40 s, and fails if it cannot: on a busy machine the
# two threads run side by side only part of the time.
#   make test-host-threads-nofence-negative
#                                   the same with a port whose fence does nothing
#                                   (tb/host_threads/port/, HT_DROP_LINE=0): each
#                                   kind must fail within 60 M Imports and say how
#                                   many torn / stale values it saw (about 5 s)
#   make test-host-threads-sites    one build per alb_fence() of albatross.c with
#                                   only that fence dropped: the store-load fences
#                                   must each fail alone, the release and acquire
#                                   ones must pass (x86-64 is TSO); 20 M Imports
#                                   each, 100 M for those that must fail (they stop
#                                   at their 50th violation; make soak-host saw the
#                                   first one as late as 23 M); and HT_PAIR (two
#                                   fences dropped together) must fail; about 30 s
#   make soak-host                  300 M checked Imports, then the negative, each
#                                   store-load site and HT_PAIR 10 times: how
#                                   reliably they fail (several minutes)
# Each writes its section of build/reports/host_threads.json (docs/protocol.md
# tables host-threads, host-threads-sites, host-threads-reliability).  The threads are pinned to CPUs 0
# and 1: the tests need two cores.
#
# HT_NOT_OBSERVED: store-load sites whose dropping was never seen to fail on
# this machine; they run and are reported, but are not required to fail.
# fs_select_write (the four-slot Export's store-load fence): 0 violations in
# 180 M Imports over payloads of 2, 4, 8 words and 1 or 3 channels, and in
# every soak; fs_complete's full fence does its work on x86-64
# (docs/protocol.md, "The driver on host threads").

HT_DIR          := $(BUILD)/host_threads
HT_SRC          := tb/host_threads/host_threads.c
HT_DEPS         := $(HT_SRC) c-driver/albatross.c $(wildcard c-driver/*.h) c-driver/port/mmio/alb_port_impl.h \
                   tb/host_threads/port/alb_port_impl.h
HT_CFLAGS        = $(DRV_CFLAGS) -O2 -pthread -Ic-driver
HT_SITES        := $(shell grep -n 'alb_fence();' c-driver/albatross.c | cut -d: -f1)
HT_NOT_OBSERVED := fs_select_write
HT_RUN           = $(PYTHON) tools/host_threads.py
# HT_PAIR: the not-observed site dropped together with the fence that covers
# it on x86-64 (fs_complete's full fence, between the Slot store and the
# Actual store), which must fail; its lines, the first fence of each function.
HT_PAIR         := fs_select_write,fs_complete
HT_LP           := (
HT_RP           := )
ht_first_fence   = $(shell awk '/^(static |ALB_NOINLINE )*(int|void) [*]*$(1)[$(HT_LP)]/ {f = 1} f && /alb_fence[$(HT_LP)][$(HT_RP)];/ {print NR; exit}' c-driver/albatross.c)
HT_PAIR_LINES   := $(call ht_first_fence,$(word 1,$(subst $(comma), ,$(HT_PAIR))))_$(call ht_first_fence,$(word 2,$(subst $(comma), ,$(HT_PAIR))))

TESTS += host-threads host-threads-nofence-negative host-threads-sites
.PHONY: test-host-threads test-host-threads-nofence-negative test-host-threads-sites soak-host

# The real driver with the unchanged mmio port.
$(HT_DIR)/ht_mmio: $(HT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(HT_CFLAGS) -Ic-driver/port/mmio -o $@ $(HT_SRC) c-driver/albatross.c

# No fence anywhere (HT_DROP_LINE=0), or none at line N of albatross.c only.
$(HT_DIR)/ht_nofence: $(HT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(HT_CFLAGS) -Itb/host_threads/port -DHT_DROP_LINE=0 -DHT_VARIANT='"no-fence"' \
	    -o $@ $(HT_SRC) c-driver/albatross.c
$(HT_DIR)/ht_drop%: $(HT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(HT_CFLAGS) -Itb/host_threads/port -DHT_DROP_LINE=$* -DHT_VARIANT='"drop-line-$*"' \
	    -o $@ $(HT_SRC) c-driver/albatross.c

# Two fences dropped together, lines N and M: $(HT_DIR)/ht_pair_N_M.
$(HT_DIR)/ht_pair_%: $(HT_DEPS)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(HT_CFLAGS) -Itb/host_threads/port -DHT_DROP_LINE=$(word 1,$(subst _, ,$*)) \
	    -DHT_DROP_LINE2=$(word 2,$(subst _, ,$*)) -DHT_VARIANT='"drop-lines-$*"' -o $@ $(HT_SRC) c-driver/albatross.c

test-host-threads: $(HT_DIR)/ht_mmio
	@tools/run_test.sh host-threads $(HT_RUN) check $(HT_DIR) --imports 15000000 --min-overtaken 50000 \
	    --words 2,8

test-host-threads-nofence-negative: $(HT_DIR)/ht_mmio $(HT_DIR)/ht_nofence
	@tools/run_test.sh host-threads-nofence-negative $(HT_RUN) negative $(HT_DIR) \
	    --imports 60000000 --min-overtaken 300000 --words 2,8 --stop-after 1000

test-host-threads-sites: $(foreach L,$(HT_SITES),$(HT_DIR)/ht_drop$(L)) $(HT_DIR)/ht_pair_$(HT_PAIR_LINES)
	@tools/run_test.sh host-threads-sites $(HT_RUN) sites $(HT_DIR) --imports 20000000 --fail-imports 100000000 \
	    --min-overtaken 100000 --words 8 --stop-after 50 --not-observed $(HT_NOT_OBSERVED) --pair $(HT_PAIR)

soak-host: $(HT_DIR)/ht_mmio $(HT_DIR)/ht_nofence $(foreach L,$(HT_SITES),$(HT_DIR)/ht_drop$(L)) \
           $(HT_DIR)/ht_pair_$(HT_PAIR_LINES) ## host threads: 300 M checked Imports, and how reliably the fence-less builds fail
	$(HT_RUN) soak $(HT_DIR) --imports 75000000 --min-overtaken 150000 --words 2,8 \
	    --negative-imports 30000000 --repeat 10 --stop-after 1000 --pair $(HT_PAIR)
