#!/usr/bin/env python3
"""fault_rates.py -- measured ages against the compiler's probabilistic
bounds (docs/verification.md "Faults at their true rate").

  fault_rates.py check --plan DIR --samples FILE.csv [--skip-clocks N]
                 [--optimistic F] [--expect-caught TEXT] [--label NAME] [--json FILE]
  fault_rates.py bench --out build/reports/fault_rates.json --svg FILE.svg
                 --tb-system BIN --desc sim/mobot3.toml [--clocks N] [--seed S]
  fault_rates.py svg REPORT.json FILE.svg

The bounds (docs/compiler.md "Fault hypothesis").  For a channel with n slots
per cycle of C clocks at starts s_0..s_{n-1}, and one consumer with slot
delivery probability q (report.json per consumer faults), m slots in a row
all miss with probability at most (1 - q)^m whatever happened before; a
delivery then follows every slot start within
    period_m = max_i (s_{i+m} - s_i)      (cyclic: s_{i+n} = s_i + C)
so an age (copy: a value's latency from its producer's publication; time,
status: how old the destination's value had grown when replaced) exceeds
    B_m = period_m + pub_offset,  pub_offset = at_target - period_at_target
with probability at most p_m = (1 - q)^m.  The family is taken for m = 1, 2,
... until p_m <= the hypothesis' miss probability (the compiler's target);
B_{slots_needed_at_target} is the compiler's age_bound.at_target (checked:
a mismatch is an error).  On the robot (mobot_sim --age-samples) an age is the
consumer's, at its Import; a copy channel's bound adds its producer's longest
gap between Actual stores so far (the robot's own age check does the same);
that gap is known from the producer's second Actual store on, so a copy
channel's earlier samples are its warm-up: counted (warmup_samples), not judged.

The check, per channel, consumer and bound: k of the N measured ages exceed
B_m.  Ages are not independent trials (all values published between two
slots share their fate), so the trials are the slots: N_eff = min(N, slots
of that consumer in the measured span) and k_eff = ceil(k * N_eff / N).  The
check fails when k_eff is improbable for a binomial(N_eff, p_m):
P(X >= k_eff) < ALPHA (one-sided, ALPHA = 1e-4: a false alarm in about one
of 10,000 checks).  With p_m = 1e-9 and a few thousand slots that means: no
age above the bound.  The per-cycle delivery probability is the same at
m = n (one cycle's slots): measured = 1 - k/N of the ages above B_n,
predicted = cycle_delivery_probability.  Every channel and consumer must
have ages (delivered).

The slot delivery itself (tb_system, whose rows are publications): each
publication is a slot that delivered, after #{m: age > B_m} slots in a row
that missed (copy channels: the oldest value the publication reaches, so a
slot without a new value is no trial); missed slots against a
binomial(trials, 1 - q), one-sided, the same ALPHA.

--optimistic F multiplies every predicted miss probability by F (< 1: a
prediction too optimistic; the negative test).  --expect-caught TEXT inverts
the verdict: the check passes only if it fails and a failure names TEXT.
Standard library only.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ALPHA = 1e-4


def binom_tail(n, k, p):
    """P(X >= k) for X ~ binomial(n, p)."""
    if k <= 0:
        return 1.0
    if p <= 0:
        return 0.0
    if p >= 1:
        return 1.0
    if k > n:
        return 0.0
    lp, lq = math.log(p), math.log1p(-p)
    total = 0.0
    for j in range(k, n + 1):
        t = math.lgamma(n + 1) - math.lgamma(j + 1) - math.lgamma(n - j + 1) + j * lp + (n - j) * lq
        term = math.exp(t)
        total += term
        if j > n * p and term < 1e-300:
            break
    return min(1.0, total)


def k_allowed(n, p):
    """The most exceedances of n trials with P(X >= k) >= ALPHA."""
    k = 0
    while k < n and binom_tail(n, k + 1, p) >= ALPHA:
        k += 1
    return k


def consumer_bounds(report, chan, cons):
    """[(m, B_m clocks, p_m)] for one consumer of one channel (report.json)."""
    C = report["cycle"]["clocks"]
    if report.get("planner") == "multi-rate":
        # the channel's runs over the cluster (its entries in the minor cycles they are due in)
        cluster = report["cluster"]["minor_cycles"]
        mine = [e for e in report["entries_list"] if e["channel"] == chan["name"]]
        starts = sorted(k * C + e["start"] for e in mine for k in range(cluster) if k % e["repetition"] == e["base"])
        C = C * cluster
    else:
        starts = sorted(s["start"] for s in chan["slots"])
    n = len(starts)
    f = cons["faults"]
    q = f["slot_delivery_probability"]
    eps = report["fault_hypothesis"]["miss_probability"] if report.get("fault_hypothesis") else 1e-9
    off = f["age_bound"]["at_target"]["clocks"] - f["period_at_target"]["clocks"]
    out = []
    m = 1
    while True:
        period = max(starts[(i + m) % n] + C * ((i + m) // n) - starts[i] for i in range(n))
        p = (1.0 - q) ** m
        out.append((m, period + off, p))
        if m == f["slots_needed_at_target"] and period + off != f["age_bound"]["at_target"]["clocks"]:
            raise SystemExit("fault_rates: %s to %s: B_%d = %d, the compiler's at_target is %d: the bound family "
                             "does not match docs/compiler.md" % (chan["name"], cons["board"], m, period + off,
                                                                  f["age_bound"]["at_target"]["clocks"]))
        if (p <= eps and m >= f["slots_needed_at_target"] and m >= n) or m >= 64:
            break
        m += 1
    return out


def load_samples(path, skip):
    """{(channel, board): [(age, producer_gap, cycle)]} of the samples at or
    after cycle skip.  tb_system's rows (no producer_gap column) are
    publications at the destination (cycle: of the publication); the robot's
    are Imports."""
    ages = {}
    with open(path) as fh:
        for row in csv.DictReader(fh):
            if int(row["cycle"]) < skip:
                continue
            key = (row["channel"], int(row["board"]))
            ages.setdefault(key, []).append((int(row["age"]), int(row.get("producer_gap") or 0),
                                             int(row["cycle"]) if "producer_gap" not in row else None))
    return ages


def slot_delivery(samples, bounds):
    """Measured slot delivery from publications (tb_system): each publication
    is one slot that delivered, after missed = #{m: age > B_m} slots in a row
    that had the value and missed it (a copy channel: the oldest value the
    publication reaches, so slots without a new value are not counted).
    Returns (missed slots, slot trials) or None (no publication cycles)."""
    if not samples or samples[0][2] is None:
        return None
    worst = {}
    for a, _, c in samples:
        worst[c] = max(worst.get(c, 0), a)
    missed = sum(sum(1 for _, B, _ in bounds if a > B) for a in worst.values())
    return missed, missed + len(worst)


def check(report, ages, span_cycles, optimistic=1.0):
    """Per channel and consumer: measured against predicted.  Returns
    (results, failures); failures name the channel, expected and got."""
    C = report["cycle"]["clocks"]
    results, failures = [], []
    for chan in report["channels"]:
        n_slots = len(chan["slots"])
        for cons in chan["consumers"]:
            key = (chan["name"], cons["board_index"])
            name = "%s to board %d (%s)" % (chan["name"], cons["board_index"], cons["board"])
            samples = ages.get(key, [])
            # The robot's copy ages are judged against B + the producer's gap so far, which is
            # known only from its second Actual store on: earlier samples are its warm-up.
            def warm(s):
                return s[2] is None and chan["kind"] == "copy" and s[1] == 0
            warmup = sum(1 for s in samples if warm(s))
            samples = [s for s in samples if not warm(s)]
            f = cons["faults"]
            res = {"channel": chan["name"], "size": chan["size"], "board": cons["board"],
                   "board_index": cons["board_index"], "samples": len(samples),
                   "warmup_samples": warmup,
                   "predicted_slot_delivery": f["slot_delivery_probability"],
                   "predicted_cycle_delivery": 1 - (1 - f["cycle_delivery_probability"]) * optimistic,
                   "age_bound_fault_free": f["age_bound"]["fault_free"]["clocks"],
                   "age_bound_at_target": f["age_bound"]["at_target"]["clocks"], "bounds": []}
            results.append(res)
            if not samples:
                failures.append("%s: expected values delivered, got no age measured (never delivered)" % name)
                continue
            res["worst_age"] = max(a for a, _, _ in samples)
            res["worst_age_minus_gap"] = max(a - g for a, g, _ in samples)
            res["worst_producer_gap"] = max(g for _, g, _ in samples)
            N = len(samples)
            bounds = consumer_bounds(report, chan, cons)
            sd = slot_delivery(samples, bounds)
            if sd:
                # The slot delivery itself, one-sided: missed slots against a binomial(trials, 1 - q).
                miss, trials = sd
                pq = (1 - f["slot_delivery_probability"]) * optimistic
                kmax = k_allowed(trials, min(pq, 1.0))
                res.update(measured_slot_delivery=1 - miss / trials, slot_trials=trials, slots_missed=miss,
                           slots_missed_allowed=kmax)
                if miss > kmax:
                    failures.append("%s: slot delivery: expected at least %.6g (at most %d of %d slots missed, "
                                    "binomial tolerance), got %.6g (%d of %d slots missed)"
                                    % (name, 1 - pq, kmax, trials, 1 - miss / trials, miss, trials))
            for m, B, p in bounds:
                p *= optimistic
                k = sum(1 for a, g, _ in samples if a > B + g)
                n_eff = min(N, max(1, span_cycles * n_slots))
                k_eff = math.ceil(k * n_eff / N) if k else 0
                kmax = k_allowed(n_eff, min(p, 1.0))
                ok = k_eff <= kmax
                res["bounds"].append({"slots_missed": m, "bound_clocks": B, "predicted_fraction_above": p,
                                      "measured_above": k, "measured_fraction_above": k / N, "trials": n_eff,
                                      "allowed_above": kmax, "ok": ok})
                if m == n_slots:
                    res["measured_cycle_delivery"] = 1 - k / N
                if not ok:
                    failures.append("%s: ages above %d clocks (%d slot%s missed in a row): expected a fraction of "
                                    "at most %.3g (%d of %d slot trials, binomial tolerance), got %d of %d ages = %.3g"
                                    % (name, B, m, "" if m == 1 else "s", p, kmax, n_eff, k, N, k / N))
    return results, failures


def cmd_check(a):
    report = json.load(open(os.path.join(a.plan, "report.json")))
    ages = load_samples(a.samples, a.skip_clocks)
    lo, hi = None, None
    with open(a.samples) as fh:
        for row in csv.DictReader(fh):
            c = int(row["cycle"])
            if c < a.skip_clocks:
                continue
            lo = c if lo is None else min(lo, c)
            hi = c if hi is None else max(hi, c)
    span = max(1, (hi - lo) // report["cycle"]["clocks"]) if lo is not None else 0
    results, failures = check(report, ages, span, a.optimistic)
    print("%s: measured ages against the compiler's bounds (plan %s, %d cycles measured%s)"
          % (a.label, a.plan, span, ", predictions x %g" % a.optimistic if a.optimistic != 1 else ""))
    print("  %-10s %-5s %7s %10s %10s %10s %14s %9s %9s" % (
        "channel", "board", "ages", "cycle pred", "cycle meas", "slot pred", "slot meas", "worst clk", "at-target"))
    for r in results:
        print("  %-10s %-5d %7d %10.6f %10s %10.6f %14s %9s %9d" % (
            r["channel"], r["board_index"], r["samples"], r["predicted_cycle_delivery"],
            "%.6f" % r["measured_cycle_delivery"] if "measured_cycle_delivery" in r else "-",
            r["predicted_slot_delivery"],
            "%.6f (%d/%d)" % (r["measured_slot_delivery"], r["slots_missed"], r["slot_trials"])
            if "measured_slot_delivery" in r else "-",
            r.get("worst_age", "-"), r["age_bound_at_target"]))
    for f in failures:
        print("  FAIL " + f)
    if a.json:
        os.makedirs(os.path.dirname(a.json) or ".", exist_ok=True)
        json.dump({"label": a.label, "plan": a.plan, "cycles_measured": span, "alpha": ALPHA,
                   "optimistic": a.optimistic, "consumers": results, "failures": failures},
                  open(a.json, "w"), indent=1)
    if a.expect_caught:
        if failures and any(a.expect_caught in f for f in failures):
            print("%s: negative test: the check caught it (%s), as expected" % (a.label, a.expect_caught))
            return 0
        print("%s: negative test FAILED: expected the check to fail naming %s, got %s"
              % (a.label, a.expect_caught, "; ".join(failures) if failures else "no failure"))
        return 1
    print("%s: %s" % (a.label, "FAILED" if failures else "PASSED"))
    return 1 if failures else 0


# ---- the sweep (make bench-fault-rates) ----

RATES = (0.0, 0.05, 0.10, 0.20, 0.30, 0.40, 0.50)
BURST_RATES = (0.05, 0.10, 0.20, 0.30, 0.40)     # with mean burst BURST
from fault_rates_svg import BURST, svg  # the picture (and its mean burst)
# Targets tried in turn until the compiler plans (docs/compiler.md: at 40 and
# 50 % the robot's 50 us channels cannot promise 1 - 1e-9).
TARGETS = (1 - 1e-9, 1 - 1e-6, 1 - 1e-3, 0.99, 0.9)


def plan_for(desc, rate, burst, out_root):
    """Plan desc for the hypothesis; (dir, target) or (None, reason)."""
    last = ""
    for t in TARGETS:
        tag = "f%g%s" % (rate * 100, "b%d" % burst if burst else "")
        d = os.path.join(out_root, "%s-t%d" % (tag, round(-math.log10(1 - t))))
        spec = "%r,%s,%r" % (rate, burst or "", t)
        r = subprocess.run(["albatross-schedule", desc, "-o", d, "-q", "--faults", spec],
                           capture_output=True, text=True)
        if r.returncode != 0:
            last = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "rejected"
            continue
        subprocess.run([sys.executable, "tb/common/plan_for_tb.py", os.path.join(d, "report.json"),
                        os.path.join(d, "tb_plan.txt")], check=True, capture_output=True)
        return d, t
    return None, last


def per_channel(results):
    """Per channel: the worst consumer's figures."""
    out = {}
    for r in results:
        c = out.setdefault(r["channel"], {"channel": r["channel"], "size": r["size"], "consumers": 0,
                                          "predicted_cycle_delivery": 1.0, "measured_cycle_delivery": 1.0,
                                          "predicted_slot_delivery": 1.0, "measured_slot_delivery": 1.0,
                                          "worst_age": 0, "age_bound_at_target": 0, "age_bound_fault_free": 0})
        c["consumers"] += 1
        c["predicted_cycle_delivery"] = min(c["predicted_cycle_delivery"], r["predicted_cycle_delivery"])
        c["measured_cycle_delivery"] = min(c["measured_cycle_delivery"], r.get("measured_cycle_delivery", 0.0))
        c["predicted_slot_delivery"] = min(c["predicted_slot_delivery"], r["predicted_slot_delivery"])
        c["measured_slot_delivery"] = min(c["measured_slot_delivery"], r.get("measured_slot_delivery", 1.0))
        c["worst_age"] = max(c["worst_age"], r.get("worst_age", 0))
        c["age_bound_at_target"] = max(c["age_bound_at_target"], r["age_bound_at_target"])
        c["age_bound_fault_free"] = max(c["age_bound_fault_free"], r["age_bound_fault_free"])
    return list(out.values())


def run_point(a, rate, burst, root):
    d, t = plan_for(a.desc, rate, burst, os.path.join(root, "plans"))
    point = {"rate": rate, "mean_burst": burst, "independent": burst is None}
    if d is None:
        point.update(planned=False, rejection=t)
        print("  rate %.2f%s: the compiler cannot plan it: %s" % (rate, " burst %d" % burst if burst else "", t[:160]))
        return point
    report = json.load(open(os.path.join(d, "report.json")))
    point.update(planned=True, probability=t, drop_run=report["drop_run"], plan=d)
    tag = os.path.basename(d)
    samples = os.path.join(root, tag + ".csv")
    cmd = [a.tb_system, "--plan", d, "--seed", str(a.seed), "--cycles", str(a.clocks), "--fault-rate", repr(rate),
           "--label", "fault-rates-" + tag, "--report", os.path.join(root, tag + ".json"), "--ages", samples]
    if burst:
        cmd += ["--burst", str(burst)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    run = json.load(open(os.path.join(root, tag + ".json")))
    span = max(1, (a.clocks - int(run["measured_from"])) // report["cycle"]["clocks"])
    results, failures = check(report, load_samples(samples, 0), span)
    point.update(tb_system_passed=r.returncode == 0, fault_rate_measured=run["fault_rate_measured"],
                 cycles_measured=span, check_failures=failures, consumers=results, channels=per_channel(results))
    print("  rate %.2f%s, planned for %.9g (K = %d): measured rate %.4f, tb_system %s, check %s" % (
        rate, " burst %d" % burst if burst else "", t, report["drop_run"], run["fault_rate_measured"],
        "passed" if r.returncode == 0 else "FAILED", "passed" if not failures else "FAILED: " + failures[0]))
    for c in point["channels"]:
        print("    %-10s %4d B  delivery per cycle predicted %.6f measured %.6f  worst age %6d clk (at target %6d)"
              % (c["channel"], c["size"], c["predicted_cycle_delivery"], c["measured_cycle_delivery"],
                 c["worst_age"], c["age_bound_at_target"]))
    return point


def robot_point(a, rate, root):
    """The robot (PicoRV32 boards) at rate on the plan for it, if --robot."""
    d, t = plan_for(a.desc, rate, None, os.path.join(root, "plans"))
    if d is None:
        return None
    tag = os.path.basename(d)
    # The plan under build/schedule/ for make's firmware rules (tools/mk/pico_boards.mk).
    sched = os.path.join("build", "schedule", "fr-" + tag)
    subprocess.run(["rm", "-rf", sched], check=True)
    subprocess.run(["cp", "-r", d, sched], check=True)
    fw = os.path.join("build", "pico_boards", "fr-" + tag, "fw")
    subprocess.run(["make", "-s", "--no-print-directory"] + [os.path.join(fw, b + ".hex") for b in BOARDS],
                   check=True, capture_output=True)
    samples = os.path.join(root, "robot-" + tag + ".csv")
    cmd = [a.robot] + ["+fw%d=%s" % (i, os.path.join(fw, b + ".hex")) for i, b in enumerate(BOARDS)] + \
          ["+ram%d=%s" % (i, os.path.join(sched, b + "_ram.hex")) for i, b in enumerate(BOARDS)] + \
          ["+rom=" + os.path.join(sched, "rom.hex"), "--plan", os.path.join(sched, "tb_plan.txt"),
           "--cycles", "1500000", "--seed", str(a.seed), "--fault-rate", repr(rate), "--progress", "0",
           "--label", "robot-" + tag, "--age-samples", samples]
    r = subprocess.run(cmd, capture_output=True, text=True)
    report = json.load(open(os.path.join(sched, "report.json")))
    lo = min(int(x["cycle"]) for x in csv.DictReader(open(samples)) if int(x["cycle"]) >= ROBOT_SKIP)
    hi = max(int(x["cycle"]) for x in csv.DictReader(open(samples)))
    results, failures = check(report, load_samples(samples, ROBOT_SKIP), max(1, (hi - lo) // report["cycle"]["clocks"]))
    print("  robot at rate %.2f: mobot_sim %s, check %s" % (rate, "passed" if r.returncode == 0 else "FAILED",
                                                           "passed" if not failures else "FAILED: " + failures[0]))
    return {"rate": rate, "probability": t, "mobot_sim_passed": r.returncode == 0, "check_failures": failures,
            "consumers": results, "channels": per_channel(results)}


BOARDS = ("radar", "odometry", "navigation", "motor")
ROBOT_SKIP = 20000      # the robot's start (attach, the controller's ROM scan)


def cmd_bench(a):
    root = os.path.join("build", "fault_rates")
    os.makedirs(root, exist_ok=True)
    print("bench-fault-rates: %s planned for each hypothesis, tb_system %d clocks per point, seed %d"
          % (a.desc, a.clocks, a.seed))
    points = [run_point(a, r, None, root) for r in RATES]
    points += [run_point(a, r, BURST, root) for r in BURST_RATES]
    robot = [p for p in (robot_point(a, r, root) for r in ROBOT_RATES) if p] if a.robot else []
    out = {"description": a.desc, "clocks": a.clocks, "seed": a.seed, "alpha": ALPHA, "burst": BURST,
           "points": points, "robot": robot,
           "definition": "per channel the worst consumer: predicted = the compiler's cycle_delivery_probability, "
                         "measured = the fraction of ages within one cycle's slots' bound B_n; worst age in clocks"}
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    json.dump(out, open(a.out, "w"), indent=1)
    svg(out, a.svg)
    print("bench-fault-rates: %s, %s" % (a.out, a.svg))
    return 0


ROBOT_RATES = (0.05, 0.20, 0.30, 0.50)


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("check")
    c.add_argument("--plan", required=True)
    c.add_argument("--samples", required=True)
    c.add_argument("--skip-clocks", type=int, default=0)
    c.add_argument("--optimistic", type=float, default=1.0)
    c.add_argument("--expect-caught", default="")
    c.add_argument("--label", default="fault-rates")
    c.add_argument("--json", default="")
    b = sub.add_parser("bench")
    b.add_argument("--desc", default="sim/mobot3.toml")
    b.add_argument("--tb-system", required=True)
    b.add_argument("--robot", default="", help="Vpico_boards: also the robot at 5/20/30/50 %%")
    b.add_argument("--clocks", type=int, default=4000000)
    b.add_argument("--seed", type=int, default=1)
    b.add_argument("--out", required=True)
    b.add_argument("--svg", required=True)
    v = sub.add_parser("svg")
    v.add_argument("report")
    v.add_argument("out")
    a = ap.parse_args()
    if a.cmd == "check":
        return cmd_check(a)
    if a.cmd == "bench":
        return cmd_bench(a)
    if a.cmd == "svg":
        svg(json.load(open(a.report)), a.out)
        return 0
    return 2


if __name__ == "__main__":
    sys.exit(main())
