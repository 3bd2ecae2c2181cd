// tb/system/tb_system_verdict.cpp -- tb_system's final verdict: an expected
// failure, a negative test's expected catch, or PASSED/FAILED (its exit status).
#include <cstdio>
#include <string>
#include <vector>
#include "board_program.h"
#include "system_checker.h"

namespace tbsys {

int system_verdict(const Options &o, const std::vector<std::string> &failures, const SystemChecker &chk)
{
    if (!o.expect_failure.empty()) {
        // An expected failure (a known limit kept visible, or a negative
        // test of a scenario check): every TEXT is in some failure, every
        // failure contains some TEXT, and no checker found a violation.
        std::string missing, other;
        for (const std::string &t : o.expect_failure) {
            bool seen = false;
            for (const std::string &f : failures) seen = seen || f.find(t) != std::string::npos;
            if (!seen) missing += " \"" + t + "\"";
        }
        for (const std::string &f : failures) {
            bool known = false;
            for (const std::string &t : o.expect_failure) known = known || f.find(t) != std::string::npos;
            if (!known) other += " \"" + f + "\"";
        }
        if (missing.empty() && other.empty() && chk.total() == 0) {
            std::printf("%s: expected failure: it failed as expected, and no checker found a violation\n", o.label.c_str());
            return 0;
        }
        std::printf("%s: expected failure did NOT happen as expected: expected failures containing%s%s; got%s%s, "
                    "%llu checker violations\n", o.label.c_str(), missing.empty() ? " each text (seen)" : "",
                    missing.c_str(), other.empty() ? " no other failure" : " other failures", other.c_str(),
                    static_cast<unsigned long long>(chk.total()));
        return 1;
    }
    if (!o.expect_caught_by.empty()) {
        std::string missing;
        for (const std::string &k : o.expect_caught_by) {
            int i = 0;
            while (std::string(SystemChecker::kind_name(i)) != k) ++i;
            if (!chk.violations[i]) missing += " " + k;
        }
        if (missing.empty()) {
            std::printf("%s: negative test: the fault was caught, as expected\n", o.label.c_str());
            return 0;
        }
        std::printf("%s: negative test FAILED: expected the fault to be caught by%s, it was not\n",
                    o.label.c_str(), missing.c_str());
        return 1;
    }
    bool ok = chk.total() == 0 && failures.empty();
    std::printf("%s: %s\n", o.label.c_str(), ok ? "PASSED" : "FAILED");
    return ok ? 0 : 1;
}

}  // namespace tbsys
