# tools/mk/docs.mk -- the pictures committed for the manual (README.md) are
# generated files, so a test checks that the committed copies are current:
#   docs/img/timeline.svg  one schedule cycle of sim/mobot3.toml, drawn by the
#                          schedule compiler (make schedule)
#   docs/img/ages.svg      the data ages of make sim with its defaults (the
#                          robot with its modes and slow channels, 11,000,000
#                          clocks, seed 1, no faults, no crash, no stalls)
#   docs/img/timeline_cluster.svg  the cluster of minor cycles of that
#                          description (build/schedule/mobot3-slow/), drawn by
#                          the schedule compiler
#   make test-docs-pictures            regenerates both (the sim run into
#                                      build/docs/, not build/sim/) and fails if a
#                                      committed copy differs from the fresh one
#   make test-docs-pictures-negative   the check must catch a stale picture
#   make docs-pictures                 refreshes the committed copies
#   docs/img/fault_rates.svg  delivery and worst age against the true fault
#                          rate (make bench-fault-rates, seed 1; deterministic,
#                          refreshed by make docs-pictures, compared by its own
#                          test-docs-pictures-fault-rates in make test-slow:
#                          tools/mk/system_fault_rates.mk)
# The simulation is deterministic for a given seed: the same tree gives the
# same pictures bit for bit.  A change that moves any timing of the robot
# (RTL, firmware, schedule) changes ages.svg, and this test asks for a refresh.

DOCS_DIR      := $(BUILD)/docs
DOCS_PICTURES := docs/img/timeline.svg $(BUILD)/schedule/mobot3/timeline.svg \
                 docs/img/timeline_cluster.svg $(BUILD)/schedule/mobot3-slow/timeline.svg \
                 docs/img/ages.svg $(DOCS_DIR)/sim/ages.svg
# make sim pinned to its defaults, whatever the caller's SEED, FAULT_RATE, ...
DOCS_SIM_ARGS := SIM_DESC=$(BUILD)/schedule/mobot3-slow/mobot3-slow.toml SIM_CYCLES=11000000 FAULT_RATE=0 BURST= CRASH= STALL=0 SEED=1 TRACE=0 \
                 SIM_DIR=$(DOCS_DIR)/sim REPORTS=$(DOCS_DIR)/sim

.PHONY: docs-pictures-build docs-pictures test-docs-pictures test-docs-pictures-negative
# Regenerate both pictures; the simulation's output goes to build/docs/sim.log.
docs-pictures-build:
	@mkdir -p $(DOCS_DIR)/sim
	@rm -f $(DOCS_DIR)/sim/ages.svg
	@$(MAKE) -s --no-print-directory $(BUILD)/schedule/mobot3/rom.hex $(BUILD)/schedule/mobot3-slow/rom.hex
	@echo "docs-pictures: make sim (defaults, seed 1) into $(DOCS_DIR)/sim/ (log $(DOCS_DIR)/sim.log)"
	@$(MAKE) --no-print-directory sim $(DOCS_SIM_ARGS) > $(DOCS_DIR)/sim.log 2>&1 || \
	    { tail -n 20 $(DOCS_DIR)/sim.log; echo "docs-pictures: make sim failed"; exit 1; }

docs-pictures: docs-pictures-build docs-pictures-fault-rates ## refresh the committed pictures of the manual (docs/img/) from make schedule and make sim
	cp $(BUILD)/schedule/mobot3/timeline.svg docs/img/timeline.svg
	cp $(BUILD)/schedule/mobot3-slow/timeline.svg docs/img/timeline_cluster.svg
	cp $(DOCS_DIR)/sim/ages.svg docs/img/ages.svg

TESTS += docs-pictures docs-pictures-negative
test-docs-pictures:
	@tools/run_test.sh docs-pictures bash -c '$(MAKE) -s --no-print-directory docs-pictures-build && \
	    tools/docs_pictures.sh $(DOCS_PICTURES) && $(PYTHON) tools/doc_facts.py --sim-log $(DOCS_DIR)/sim.log'
# A stale picture (one figure changed), a missing committed copy and a missing
# fresh one must each fail the check; the current picture must pass it.
test-docs-pictures-negative:
	@tools/run_test.sh docs-pictures-negative bash -c 'set -u; d=$(DOCS_DIR)/negative; rm -rf $$d; mkdir -p $$d; \
	    sed "0,/<text/s/<text\([^>]*\)>[^<]*</<text\1>stale</" docs/img/timeline.svg > $$d/timeline.svg; \
	    cmp -s $$d/timeline.svg docs/img/timeline.svg && { echo "the stale copy equals the real one"; exit 1; }; \
	    for c in "$$d/timeline.svg docs/img/timeline.svg" "$$d/absent.svg docs/img/timeline.svg" \
	             "docs/img/timeline.svg $$d/absent.svg"; do \
	        if tools/docs_pictures.sh $$c > $$d/out.txt; then \
	            echo "expected tools/docs_pictures.sh $$c to fail, it passed"; exit 1; fi; \
	        grep -q "FAIL" $$d/out.txt || { echo "no FAIL line for $$c"; exit 1; }; \
	        echo "caught: $$(head -n 1 $$d/out.txt)"; done; \
	    tools/docs_pictures.sh docs/img/timeline.svg docs/img/timeline.svg > /dev/null || \
	        { echo "an identical copy failed the check"; exit 1; }; \
	    echo "a stale, a missing committed and a missing fresh picture are each caught"'

# The docs speak to a stranger (tools/doc_words.py): no internal issue numbers
# and no "seed" for the paper in README.md, docs/*.md, compiler/README.md, the
# contract's doc strings, the C driver and tools/mk.
#   make test-docs-words            the check
#   make test-docs-words-negative   each kind of bad phrase must be caught
TESTS += docs-words docs-words-negative
.PHONY: test-docs-words test-docs-words-negative
test-docs-words:
	@tools/run_test.sh docs-words $(PYTHON) tools/doc_words.py
test-docs-words-negative:
	@tools/run_test.sh docs-words-negative $(PYTHON) tools/doc_words.py --self-test

# Figures typed in the prose, checked against the thing (tools/doc_facts.py):
# the timeline caption's ROM entries and cycle (the compiler's report), the
# FuseSoC lint-target count (the core files); test-docs-pictures also checks
# that make sim's last line is `sim: pass`, as the README says, and that every
# line of the README's make sim excerpt (copied by make figures from
# build/docs/sim.log) is printed by the fresh run, in that order.
#   make test-docs-facts            the check
#   make test-docs-facts-negative   each figure changed by one must be caught
TESTS += docs-facts docs-facts-negative
.PHONY: test-docs-facts test-docs-facts-negative
test-docs-facts: $(BUILD)/schedule/mobot3/rom.hex
	@tools/run_test.sh docs-facts $(PYTHON) tools/doc_facts.py
test-docs-facts-negative: $(BUILD)/schedule/mobot3/rom.hex
	@tools/run_test.sh docs-facts-negative $(PYTHON) tools/doc_facts.py --self-test

# make help lists every target the docs name (tools/make_help.py --check-docs):
# each `make X` in a code span or block of README.md, docs/*.md and
# compiler/README.md is in make help, or, for make test-NAME, is a rule.
#   make test-help-docs            the check
#   make test-help-docs-negative   a scratch doc naming a target that does not
#                                  exist and a test that does not exist: both caught
HELP_DOCS     := README.md $(wildcard docs/*.md) compiler/README.md
HELP_TARGETS  := $(BUILD)/help/targets.txt
TESTS += help-docs help-docs-negative
.PHONY: test-help-docs test-help-docs-negative $(HELP_TARGETS)
$(HELP_TARGETS):
	@mkdir -p $(@D)
	@$(MAKE) -pRrq -f $(firstword $(MAKEFILE_LIST)) : 2>/dev/null | grep -oE '^[a-zA-Z0-9_.-]+:' | tr -d : | sort -u > $@
test-help-docs: $(HELP_TARGETS)
	@tools/run_test.sh help-docs python3 tools/make_help.py --check-docs $(MAKEFILE_LIST) --targets $< $(HELP_DOCS)
test-help-docs-negative: $(HELP_TARGETS)
	@tools/run_test.sh help-docs-negative bash -c 'd=$(BUILD)/help; \
	    printf "Run \`make no-such-target\`, then:\n\n\`\`\`sh\nmake test-no-such-test\nmake help\n\`\`\`\n" > $$d/neg.md; \
	    if python3 tools/make_help.py --check-docs $(MAKEFILE_LIST) --targets $< $$d/neg.md > $$d/neg.out; then \
	        echo "expected the check to fail on $$d/neg.md, it passed"; exit 1; fi; \
	    cat $$d/neg.out; \
	    grep -q "make no-such-target: expected it in make help" $$d/neg.out && \
	    grep -q "make test-no-such-test: expected it in make help" $$d/neg.out && \
	    ! grep -q "make help:" $$d/neg.out || { echo "expected exactly the two missing targets named"; exit 1; }; \
	    echo "help-docs-negative: a target and a test that do not exist are both caught"'
