# tools/mk/host_threads.mk -- the real driver on two simulated CPUs with store
# buffers (a software model, deterministic) and on two host threads over
# ordinary shared memory (silicon: tb/host_threads/host_threads.c), judged by
# tools/host_threads.py; docs/protocol.md, "The driver on host threads".
#   make test-host-threads-model    the proof that the checker catches what a
#                                   missing fence does, the same on every
#                                   machine: tb/host_threads/sb_model.c runs the
#                                   driver on two coroutine CPUs with store
#                                   buffers (tso: in order; pso: stores to
#                                   different addresses reorder) under a seeded
#                                   scheduler.  The fenced driver must never
#                                   fail, the fence-less one must, and each
#                                   fence site dropped alone fails exactly where
#                                   the memory model says (about 6 s of CPU)
#   make test-host-threads          silicon: the unchanged mmio port, both kinds,
#                                   payloads of 2 and 8 words, 5 M checked
#                                   Imports each; every one must check out
#   make test-host-threads-silicon  silicon, observed: each fence-less build
#                                   (no fence; each store-load site alone;
#                                   HT_PAIR) once, 3 M Imports each; how often
#                                   each tore is counted per CPU model in the
#                                   report; required only: a clean end, and no
#                                   fence instruction in the fence-less builds
#   make soak-host                  300 M checked Imports, then each fence-less
#                                   build 10 times (several minutes)
# Silicon runs go on past their Imports until the producer has overtaken (an
# Export completed during the Import) --min-overtaken of them, up to 40 s;
# less overlap (a busy machine) is reported as LIMITED, not failed.  The
# threads are pinned to CPUs 0 and 1.  Each command writes its section of
# build/reports/host_threads.json.
#
# HT_COVERED: store-load sites whose work a later full fence does (the
# model's expectation: they pass alone, in tso and pso): fs_select_write,
# covered by fs_complete's fence (docs/protocol.md explains why).
# HT_PAIR: that site dropped together with the fence that covers it, which
# must fail.

HT_DIR          := $(BUILD)/host_threads
HT_SRC          := tb/host_threads/host_threads.c
HT_DEPS         := $(HT_SRC) tb/host_threads/ht_check.h c-driver/albatross.c $(wildcard c-driver/*.h) c-driver/port/mmio/alb_port_impl.h \
                   tb/host_threads/port/alb_port_impl.h
HT_CFLAGS        = $(DRV_CFLAGS) -O2 -pthread -Ic-driver
# The store-load fence sites (their comment reads "... before loading ..."):
# the ones a store buffer can make fail alone, observed on silicon.
HT_SITES        := $(shell grep -n 'alb_fence();.*before loading' c-driver/albatross.c | cut -d: -f1)
HT_COVERED      := fs_select_write
# The model's seed (its scheduler): the same seed gives the same run.
HT_SEED         ?= 1
HT_RUN           = $(PYTHON) tools/host_threads.py
# HT_PAIR: the not-observed site dropped together with the fence that covers
# it on x86-64 (fs_complete's full fence, between the Slot store and the
# Actual store), which must fail; its lines, the first fence of each function.
HT_PAIR         := fs_select_write,fs_complete
HT_LP           := (
HT_RP           := )
ht_first_fence   = $(shell awk '/^(static |ALB_NOINLINE )*(int|void) [*]*$(1)[$(HT_LP)]/ {f = 1} f && /alb_fence[$(HT_LP)][$(HT_RP)];/ {print NR; exit}' c-driver/albatross.c)
HT_PAIR_LINES   := $(call ht_first_fence,$(word 1,$(subst $(comma), ,$(HT_PAIR))))_$(call ht_first_fence,$(word 2,$(subst $(comma), ,$(HT_PAIR))))

TESTS += host-threads-model host-threads host-threads-silicon
.PHONY: test-host-threads-model test-host-threads test-host-threads-silicon soak-host

# The store-buffer model: the driver with the port of tb/host_threads/sbport/
# (every access a scheduling point; the fences to drop chosen at run time).
# -U_FORTIFY_SOURCE: the coroutines switch stacks (docs: TOOLCHAIN).
$(HT_DIR)/sb_model: tb/host_threads/sb_model.c tb/host_threads/ht_check.h tb/host_threads/sbport/alb_port_impl.h \
                    c-driver/albatross.c $(wildcard c-driver/*.h)
	@mkdir -p $(@D)
	$(DRV_HOST_CC) $(DRV_CFLAGS) -O2 -U_FORTIFY_SOURCE -Ic-driver -Itb/host_threads/sbport -Itb/host_threads \
	    -o $@ tb/host_threads/sb_model.c c-driver/albatross.c

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

test-host-threads-model: $(HT_DIR)/sb_model
	@tools/run_test.sh host-threads-model $(HT_RUN) model $(HT_DIR) --seed $(HT_SEED) --imports 100000 \
	    --fail-imports 400000 --stop-after 5 --words 2,8 --covered $(HT_COVERED) --pair $(HT_PAIR)

test-host-threads: $(HT_DIR)/ht_mmio
	@tools/run_test.sh host-threads $(HT_RUN) check $(HT_DIR) --imports 5000000 --min-overtaken 50000 \
	    --words 2,8

test-host-threads-silicon: $(HT_DIR)/ht_mmio $(HT_DIR)/ht_nofence $(foreach L,$(HT_SITES),$(HT_DIR)/ht_drop$(L)) \
                           $(HT_DIR)/ht_pair_$(HT_PAIR_LINES)
	@tools/run_test.sh host-threads-silicon $(HT_RUN) observe $(HT_DIR) --imports 3000000 --min-overtaken 20000 \
	    --soft-seconds 10 --words 8 --stop-after 50 --pair $(HT_PAIR)

soak-host: $(HT_DIR)/ht_mmio $(HT_DIR)/ht_nofence $(foreach L,$(HT_SITES),$(HT_DIR)/ht_drop$(L)) \
           $(HT_DIR)/ht_pair_$(HT_PAIR_LINES) ## host threads: 300 M checked Imports, and how reliably the fence-less builds fail
	$(HT_RUN) soak $(HT_DIR) --imports 75000000 --min-overtaken 150000 --words 2,8 \
	    --negative-imports 30000000 --repeat 10 --stop-after 1000 --pair $(HT_PAIR)
