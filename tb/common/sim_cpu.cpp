// sim_cpu.cpp -- coroutine hand-off between the driver's port layer and the
// clock loop.
#include "sim_cpu.h"
#include <cstdio>
#include "port/alb_port_impl.h"

static SimCpu *g_current = nullptr;

void SimCpu::resume()
{
    if (faulted) return;
    SimCpu *outer = g_current;
    g_current = this;
    coro_.resume();
    g_current = outer;
}

uint32_t SimCpu::access(uint32_t addr, uint32_t wdata, unsigned sel, bool we)
{
    uint32_t word = addr & ~3u;
    uint32_t first = 4, last = 0;
    for (uint32_t lane = 0; lane < 4; ++lane)
        if (sel & (1u << lane)) { if (first == 4) first = lane; last = lane; }
    bool word_access = sel == 0xFu;
    if (sel == 0 || (word_access && (addr & 3u) != 0) ||
        word + first < window_lo || word + last >= window_hi) {
        char msg[160];
        std::snprintf(msg, sizeof msg,
                      "cpu %d: %s of address 0x%x (lanes 0x%x) outside its channel [0x%x, 0x%x)",
                      id, we ? "write" : "read", addr, sel, window_lo, window_hi);
        fault = msg;
        faulted = true;
        has_request = false;
        coro_.yield();   // never resumed again
        return 0;
    }
    request = BusRequest{word, wdata, static_cast<uint8_t>(sel), we};
    has_request = true;
    coro_.yield();       // the clock loop completes it and resumes us
    return rdata;
}

extern "C" uint32_t tb_bus_access(uintptr_t addr, uint32_t wdata, unsigned sel, int we)
{
    // Addresses beyond 32 bits (a wrapped buffer index) are outside anything.
    uint32_t a = addr > 0xFFFFFFFFu ? 0xFFFFFFFCu : static_cast<uint32_t>(addr);
    return g_current->access(a, wdata, sel, we != 0);
}
