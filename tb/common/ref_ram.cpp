// ref_ram.cpp -- see ref_ram.h.
#include "ref_ram.h"
#include <cstdio>

void RefRam::check_and_apply(const Access *done, int n)
{
    // Reads first, against the values before this edge and this edge's writes.
    for (int i = 0; i < n; ++i) {
        const Access &r = done[i];
        if (r.req.we) continue;
        for (uint32_t lane = 0; lane < 4; ++lane) {
            if (!(r.req.sel & (1u << lane))) continue;
            uint32_t a = (r.req.addr + lane) & mask_;
            uint8_t got = static_cast<uint8_t>(r.rdata >> (8 * lane));
            bool ok = !known_[a] || got == ref_[a];
            for (int j = 0; j < n; ++j) {
                const Access &w = done[j];
                if (j == i || !w.req.we || !(w.req.sel & (1u << lane)) ||
                    ((w.req.addr ^ r.req.addr) & (mask_ & ~3u)) != 0)
                    continue;
                ++same_edge_collisions;
                if (got == static_cast<uint8_t>(w.req.wdata >> (8 * lane))) ok = true;
            }
            if (!ok) {
                if (violations++ == 0) {
                    char msg[200];
                    std::snprintf(msg, sizeof msg,
                                  "byte atomicity: port %c read byte 0x%x at cycle %llu: expected 0x%02x "
                                  "(old) or a value written at that edge, got 0x%02x",
                                  'A' + r.port, a, static_cast<unsigned long long>(r.serve_cycle),
                                  ref_[a], got);
                    first_violation = msg;
                }
                ref_[a] = got;   // resynchronise
            }
        }
    }
    for (int i = 0; i < n; ++i) {
        const Access &w = done[i];
        if (!w.req.we) continue;
        for (uint32_t lane = 0; lane < 4; ++lane) {
            if (!(w.req.sel & (1u << lane))) continue;
            uint32_t a = (w.req.addr + lane) & mask_;
            bool both = false;
            for (int j = 0; j < n; ++j)
                if (j != i && done[j].req.we && (done[j].req.sel & (1u << lane)) &&
                    ((done[j].req.addr ^ w.req.addr) & (mask_ & ~3u)) == 0)
                    both = true;
            ref_[a] = static_cast<uint8_t>(w.req.wdata >> (8 * lane));
            known_[a] = both ? 0 : 1;   // two writers at one edge: either value
        }
    }
}
