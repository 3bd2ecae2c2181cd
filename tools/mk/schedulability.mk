# tools/mk/schedulability.mk -- the schedulability benchmark (tools/schedulability_bench.py,
# docs/compiler.md "Schedulability"): generated systems at bus demands of 5 to 90 %,
# each planned by the single-rate plan alone and by the compiler as it is (its
# multi-rate planner when the single-rate plan fails; both --no-redundancy), and by
# the exact search on the plain power-of-two grid (compiler/albatross_schedule/exact.py,
# OR-Tools CP-SAT, which make deps installs):
#   make bench-schedulability [SCHED_SYSTEMS=N]  build/reports/schedulability.json and .svg
#                                                (N systems per demand level, default 100:
#                                                about a minute on 2 cores today)
#   make test-schedulability-smoke               the hand-made systems, the generator's
#                                                targets, a run of two systems
#   tools/schedulability_bench.py --case SEED    one system's description (seeds: the report)
# The exact search's own tests are compiler/tests/test_exact.py (make test-compiler-exact).
SCHED_SYSTEMS ?= 100

BENCHES += bench-schedulability
TESTS   += schedulability-smoke
.PHONY: bench-schedulability test-schedulability-smoke

bench-schedulability: ## acceptance per bus demand: the single-rate plan, the multi-rate planner, the exact search on the power-of-two grid
	$(PYTHON) tools/schedulability_bench.py run --systems $(SCHED_SYSTEMS) \
	    --out $(REPORTS)/schedulability.json --svg $(REPORTS)/schedulability.svg

test-schedulability-smoke:
	@tools/run_test.sh schedulability-smoke $(PYTHON) tools/schedulability_bench.py --smoke
