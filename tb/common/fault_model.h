// fault_model.h -- the bus fault process of the system and robot tests, and
// the statistical check of the rate it produced (docs/verification.md,
// "Fault injection").
//
// The process runs over ACCESSES, not clocks: the harness draws one kind per
// new controller request to a live board (bus_fault_injector's fi_new_o and
// fi_dead_o) and holds it on fi_kind_i until the next such request, so the
// share of accesses faulted is the nominal rate whatever the controller's
// timing.  State of access k: bad (faulted, kind 1, 2 or 3 with equal
// probability) or good (kind 0), a two-state Markov chain (Gilbert):
//   P(good -> bad) = a,  P(bad -> good) = b,
//   stationary P(bad) = a / (a + b) = p        (the nominal rate),
//   mean length of a run of faulted accesses = 1 / b = L  (the burst).
// So b = 1 / L and a = p / (L (1 - p)); a <= 1 needs L >= p / (1 - p).
// Without a burst the accesses are independent: L = 1 / (1 - p), a = p,
// b = 1 - p.  The first access's state is drawn from the stationary law,
// so every access is faulted with probability p exactly.
//
// The check.  With S faulted of n accesses, E[S] = n p and, with
// lambda = 1 - a - b the chain's correlation from one access to the next
// (corr(k) = lambda^k),
//   Var S = n p (1 - p) [(1 + lambda) / (1 - lambda)
//                        - 2 lambda (1 - lambda^n) / (n (1 - lambda)^2)].
// The bracket's second term is negative for lambda >= 0 and, for
// -1 <= lambda < 0, at most p (1 - p) in absolute value once multiplied
// out, so  Var S <= n p (1 - p) (1 + lambda) / (1 - lambda) + p (1 - p).
// The run fails when |S - n p| > Z sigma + 1 (Z = 6; the + 1 is one access
// of discreteness), i.e. |measured - p| > (Z sigma + 1) / n.  Under a normal
// approximation a correct injector fails it with probability about 2e-9.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

struct FaultModel {
    static constexpr double kSigmas = 6.0;
    double rate = 0, burst = 0;      // burst 0: independent accesses
    double enter = 0, leave = 1;     // a, b
    bool bad = false, started = false;
    std::mt19937_64 rng;

    FaultModel(double r, double l, uint64_t seed) : rate(r), burst(l), rng(seed)
    {
        if (rate <= 0) return;
        if (burst <= 0) { enter = rate; leave = 1 - rate; }
        else { leave = 1 / burst; enter = rate / (burst * (1 - rate)); }
    }
    // "" or why (rate, burst) is no valid chain.
    static std::string invalid(double rate, double burst)
    {
        if (!(rate >= 0 && rate < 1)) return "the fault rate must be in [0, 1)";
        if (burst == 0) return "";
        if (burst < 1) return "a burst (mean faulted accesses in a row) is at least 1";
        if (rate > 0 && rate / (burst * (1 - rate)) > 1 + 1e-12)
            return "a burst of " + std::to_string(burst) + " accesses is too short for rate " + std::to_string(rate) +
                   ": at least p / (1 - p) = " + std::to_string(rate / (1 - rate));
        return "";
    }
    // The mean burst, 1 / b (independent accesses: 1 / (1 - p)).
    double mean_burst() const { return rate > 0 ? 1 / leave : 0; }
    double lambda() const { return 1 - enter - leave; }
    // The kind of the next access: 0, or 1..3 in a faulted one.
    unsigned next()
    {
        if (rate <= 0) return 0;
        std::uniform_real_distribution<double> u(0, 1);
        if (!started) { bad = u(rng) < rate; started = true; }
        else if (bad) { if (u(rng) < leave) bad = false; }
        else if (u(rng) < enter) bad = true;
        return bad ? 1 + static_cast<unsigned>(rng() % 3) : 0;
    }
    // The allowed |measured - nominal| over n accesses.
    double tolerance(uint64_t n) const
    {
        if (n == 0) return 1;
        const double p = rate, l = lambda(), dn = static_cast<double>(n);
        const double var = dn * p * (1 - p) * (1 + l) / (1 - l) + p * (1 - p);
        return (kSigmas * std::sqrt(std::max(0.0, var)) + 1) / dn;
    }
};
