// sim_cpu.h -- a simulated CPU: real C code on a coroutine whose every RAM
// access (tb_bus_access, called by the driver's port layer) becomes one
// Wishbone transaction on the RTL.
#pragma once
#include <cstdint>
#include <string>
#include "coro.h"

struct BusRequest {
    uint32_t addr;   // byte address of the word (lane bits cleared)
    uint32_t wdata;
    uint8_t  sel;    // byte lanes
    bool     we;
};

class SimCpu {
public:
    typedef void (*Program)(SimCpu &cpu);

    int         id = 0;          // also the RAM port: 0 = A, 1 = B
    uint32_t    window_lo = 0;   // the only bytes it may touch: [lo, hi)
    uint32_t    window_hi = 0;
    void       *context = nullptr;  // the program's own state
    bool        warmup = false;     // set by the program: not yet under test

    // Set by the CPU, consumed by the clock loop.
    bool        has_request = false;
    BusRequest  request{};
    uint32_t    rdata = 0;
    // Optional stall hook (a test stretching the C code between accesses):
    // called before every access the program makes, it returns how many
    // clocks the CPU idles before it posts that access.
    unsigned  (*stall_hook)(SimCpu &cpu, uint32_t addr, bool we) = nullptr;
    bool        faulted = false;    // it made an illegal access: stopped
    std::string fault;
    uint64_t    accesses = 0;

    void start(Program p) {
        program_ = p;
        has_request = false;
        coro_.start(&SimCpu::entry, this);
    }
    void resume();                  // run to its next access (or the end)
    // The hand-off watchdog, in CPU time: C code that loops without a
    // RAM access never hands control back, and no watchdog counting simulated
    // cycles can see that.  Once armed (by a bench's main), a timer checks
    // every second of CPU time that a resume() under way has returned within `seconds`;
    // if one has not, the process prints which CPU and exits with status 3.
    static void arm_handoff_watchdog(unsigned seconds);
    bool finished() const { return coro_.finished(); }
    uint32_t access(uint32_t addr, uint32_t wdata, unsigned sel, bool we);
    // Called by the program: spend a clock without a RAM access (a CPU
    // that has nothing to do yet must still let time pass).
    void idle() { has_request = false; coro_.yield(); }

private:
    static void entry(void *self) {
        SimCpu *c = static_cast<SimCpu *>(self);
        c->program_(*c);
    }
    Coro    coro_;
    Program program_ = nullptr;
};
