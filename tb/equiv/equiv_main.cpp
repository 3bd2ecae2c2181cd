// equiv_main.cpp -- drives tb/equiv/tb_equiv.v (tools/ctrl_equiv.sh).
//
//   Vtb_equiv CLOCKS SEED FAIL RESET +rom=FILE [+rom_upset_word=N +rom_upset_at=T]
//
// The bus is random and shared: each access is acked after 0..2 clocks,
// answered with err (probability FAIL/2) or never answered (FAIL/2, a
// timeout); read data is random with each byte biased to the control values
// 0..3 (one word in four fully random); RESET > 0 pulses rst_i with
// probability 1/RESET per clock (0: only at the start).  Every clock the two
// controllers' outputs are compared (address, sel and we while cyc is high,
// data while a store is on the bus); the first difference ends the run with
// exit status 1.  Exit 0: cycle-equivalent for CLOCKS clocks.
#include "Vtb_equiv.h"
#include "verilated.h"
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>

int main(int argc, char** argv) {
    Verilated::commandArgs(argc, argv);
    if (argc < 5) {
        std::fprintf(stderr, "usage: Vtb_equiv CLOCKS SEED FAIL RESET +rom=FILE\n");
        return 2;
    }
    const uint64_t clocks = std::strtoull(argv[1], nullptr, 10);
    const unsigned seed = (unsigned)std::atoi(argv[2]);
    const double pfail = std::atof(argv[3]);
    const uint64_t reset_every = std::strtoull(argv[4], nullptr, 10);
    std::mt19937_64 r(seed);
    Vtb_equiv* t = new Vtb_equiv;
    t->clk_i = 0;
    t->rst_i = 1;
    t->m_ack_i = 0;
    t->m_err_i = 0;
    t->eval();
    int wait = -1;                       // clocks to the answer; -2 err now; -1 none pending
    uint64_t acks = 0, errs = 0, resets = 0;
    for (uint64_t c = 0; c < clocks; ++c) {
        t->rst_i = c < 3 || (reset_every && r() % reset_every == 0);
        resets += t->rst_i && c >= 3;
        t->m_ack_i = 0;
        t->m_err_i = 0;
        if (t->n_cyc_o && t->n_stb_o) {
            if (wait == -1) {
                double x = (double)(r() % 1000000) / 1e6;
                wait = x < pfail / 2 ? 1000 : x < pfail ? -2 : (int)(r() % 3);
            }
            if (wait == -2) { t->m_err_i = 1; wait = -1; ++errs; }
            else if (wait == 0) { t->m_ack_i = 1; wait = -1; ++acks; }
            else --wait;
        } else {
            wait = -1;
        }
        uint32_t d = 0;
        for (int b = 0; b < 4; ++b) {
            uint32_t x = (uint32_t)(r() % 8);
            uint32_t v = x < 3 ? x + 1 : x == 3 ? 0 : (uint32_t)(r() & 0xff);
            d |= v << (8 * b);
        }
        if (r() % 4 == 0) d = (uint32_t)r();
        t->m_dat_i = d;
        t->clk_i = 0;
        t->eval();
#define SAME(a, b)                                                                                   \
        if (t->a != t->b) {                                                                          \
            std::printf("DIFFER at clock %llu: %s = 0x%llx, reference %s = 0x%llx\n",              \
                        (unsigned long long)c, #a, (unsigned long long)t->a, #b, (unsigned long long)t->b); \
            delete t;                                                                                \
            return 1;                                                                                \
        }
        SAME(n_cyc_o, r_cyc_o) SAME(n_stb_o, r_stb_o) SAME(n_error_o, r_error_o) SAME(n_rerr_o, r_rerr_o)
        SAME(n_time_o, r_time_o)
        if (t->n_cyc_o) {
            SAME(n_we_o, r_we_o) SAME(n_adr_o, r_adr_o) SAME(n_sel_o, r_sel_o)
            if (t->n_we_o) SAME(n_dat_o, r_dat_o)
        }
        t->clk_i = 1;
        t->eval();
    }
    std::printf("equivalent for %llu clocks (seed %u, fail %.2f: %llu acks, %llu errs, %llu resets; "
                "rom_errors %u, error %u at the end)\n", (unsigned long long)clocks, seed, pfail,
                (unsigned long long)acks, (unsigned long long)errs, (unsigned long long)resets,
                (unsigned)t->n_rerr_o, (unsigned)t->n_error_o);
    delete t;
    return 0;
}
