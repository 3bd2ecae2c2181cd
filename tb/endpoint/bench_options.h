// bench_options.h -- the command line shared by the endpoint benches
// (tb/endpoint/export/test_export_pico.cpp, tb/endpoint/import/test_import_pico.cpp):
//   [--values N] [--max-cycles N] [--seed S] [--report FILE] [--label NAME]
//   [--expect-checker KIND]   (negative test: that protocol checker must fire)
// Arguments starting with '+' are Verilator plusargs and are left alone.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include "protocol_checker.h"

struct BenchOptions {
    uint64_t max_cycles = 20000000, seed = 1, values = 0;
    std::string report, label, expect;
    int expect_kind = -1;   // index of the checker --expect-checker names, or -1

    // Parses argv; on an unknown argument or checker prints why and returns false.
    bool parse(int argc, char **argv)
    {
        for (int i = 1; i < argc; ++i) {
            const bool more = i + 1 < argc;
            if (!std::strcmp(argv[i], "--max-cycles") && more) max_cycles = std::strtoull(argv[++i], 0, 0);
            else if (!std::strcmp(argv[i], "--seed") && more) seed = std::strtoull(argv[++i], 0, 0);
            else if (!std::strcmp(argv[i], "--values") && more) values = std::strtoull(argv[++i], 0, 0);
            else if (!std::strcmp(argv[i], "--report") && more) report = argv[++i];
            else if (!std::strcmp(argv[i], "--label") && more) label = argv[++i];
            else if (!std::strcmp(argv[i], "--expect-checker") && more) expect = argv[++i];
            else if (argv[i][0] != '+') { std::fprintf(stderr, "unknown argument %s\n", argv[i]); return false; }
        }
        if (!expect.empty()) {
            for (int k = 0; k < ProtocolChecker::KINDS; ++k)
                if (expect == ProtocolChecker::kind_name(k)) expect_kind = k;
            if (expect_kind < 0) { std::fprintf(stderr, "unknown checker %s\n", expect.c_str()); return false; }
        }
        return true;
    }
};
