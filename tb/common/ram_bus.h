// ram_bus.h -- the RTL dual-ported RAM under test, clocked from C++, with two
// simulated CPUs on its ports and a byte-atomicity checker on every access.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include "ref_ram.h"
#include "sim_cpu.h"

class Vdut;

class AccessObserver {
public:
    virtual ~AccessObserver() {}
    virtual void on_access(const Access &a) = 0;
};

class RamBus {
public:
    static const int kAddrWidth = 10;             // matches the RTL build
    static const uint32_t kBytes = 4u << kAddrWidth;

    RamBus();
    ~RamBus();

    SimCpu cpu[2];                      // cpu[p] sits on port p
    AccessObserver *observer = nullptr;

    // Write a VCD wave of the first max_cycles cycles to path (needs a model
    // built with --trace; returns false otherwise).
    bool trace(const char *path, uint64_t max_cycles);

    // Reset the RAM's control state (a few cycles, ports idle).
    void reset();
    // Write bytes through port A before the CPUs run (a RAM image).
    void load(uint32_t addr, const uint8_t *bytes, uint32_t n);

    // Drive cpu[p]'s pending request onto port p (if it has one).
    void issue(int port);
    bool busy(int port) const { return busy_[port]; }
    // One clock cycle; completed accesses go to the observer and the CPU.
    // Returns a bit mask of the ports that completed an access.
    unsigned tick();
    uint64_t cycle() const { return cycle_; }
    // Slot phase: which port the RAM serves at the next edge (tracked from
    // reset; the RTL alternates A, B, A, ...).
    int next_slot() const { return static_cast<int>(cycle_ - reset_cycle_) & 1; }

    RefRam ref;                         // byte-atomicity checker of this RAM
    uint64_t accesses = 0;
    // Access-time checker: every access is acknowledged within kMaxLatency
    // cycles of its request, whatever the other port does.
    static const int kMaxLatency = 2;
    uint64_t worst_latency = 0, latency_violations = 0;
    std::string first_latency_violation;
    // The RAM's content as the reference model knows it.
    uint8_t ram_byte(uint32_t addr) const { return ref.byte(addr); }
    // Stall detector for a RAM that never answers.
    uint64_t issue_cycle(int port) const { return issue_cycle_[port]; }

private:
    void drive(int port, const BusRequest *r);

    void eval_traced();

    std::unique_ptr<Vdut> dut_;
    struct Tracer;
    std::unique_ptr<Tracer> tracer_;
    uint64_t cycle_ = 0, reset_cycle_ = 0;
    bool busy_[2] = {false, false};
    bool late_[2] = {false, false};     // the request under way already counted as late
    uint64_t issue_cycle_[2] = {0, 0};
};
