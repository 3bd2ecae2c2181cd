// sim_cpu.cpp -- coroutine hand-off between the driver's port layer and the
// clock loop.
#include "sim_cpu.h"
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/time.h>
#include <unistd.h>
#include "port/alb_port_impl.h"

static SimCpu *volatile g_current = nullptr;
// Hand-off watchdog state: resumes begun so far, as the timer last saw them.
static std::atomic<unsigned> g_handoffs{0};
static unsigned g_handoff_limit = 0, g_handoff_seen = 0, g_handoff_stuck = 0;

static void on_handoff_alarm(int)
{
    SimCpu *c = g_current;
    const unsigned n = g_handoffs.load(std::memory_order_relaxed);
    if (c == nullptr || n != g_handoff_seen) {
        g_handoff_seen = n;
        g_handoff_stuck = 0;
        return;
    }
    if (++g_handoff_stuck < g_handoff_limit) return;
    // Async-signal-safe: no stdio, only write and _exit.
    char msg[300] = "tb: watchdog: simulated CPU ";
    size_t len = std::strlen(msg);
    auto put_uint = [&](unsigned v) {
        char d[12];
        int k = 0;
        do { d[k++] = static_cast<char>('0' + v % 10); v /= 10; } while (v && k < 11);
        while (k) msg[len++] = d[--k];
    };
    auto put = [&](const char *t) { while (*t && len < sizeof msg - 1) msg[len++] = *t++; };
    put_uint(static_cast<unsigned>(c->id));
    put(" has not handed control back to the clock loop for ");
    put_uint(g_handoff_stuck);
    put(" s of CPU time: its C code loops without a RAM access (expected a hand-off at every access)\n");
    ssize_t w = write(2, msg, len);
    (void)w;
    _exit(3);
}

void SimCpu::arm_handoff_watchdog(unsigned seconds)
{
    g_handoff_limit = seconds ? seconds : 1;
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_handoff_alarm;
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    // CPU time (ITIMER_PROF: user + system), not wall time: a C loop without
    // a hand-off spins and uses CPU time, while a busy machine that lends the
    // simulation little CPU does not make a healthy run look stuck.
    sigaction(SIGPROF, &sa, nullptr);
    struct itimerval t;
    t.it_interval.tv_sec = 1;
    t.it_interval.tv_usec = 0;
    t.it_value = t.it_interval;
    setitimer(ITIMER_PROF, &t, nullptr);
}

void SimCpu::resume()
{
    if (faulted) return;
    g_handoffs.store(g_handoffs.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
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
    if (stall_hook)
        for (unsigned n = stall_hook(*this, word, we); n > 0; --n) idle();
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
