// system_sim.h -- the Verilated multi-board system (tb/system/tb_system.v):
// one simulated CPU per board on its RAM's port A, the communication
// controller on every port B, the bus fault injector between them.
//
// Each clock: the CPUs' requests are driven, the system is clocked, and every
// access performed on a RAM -- by its CPU (port A, seen at the CPU's ack) or
// by the controller (port B, seen on the monitor outputs at that RAM's ack) --
// goes through that board's byte-atomicity checker and then to the observer.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include "ref_ram.h"
#include "sim_cpu.h"

class Vsys;

class SystemObserver {
public:
    virtual ~SystemObserver() {}
    // port 0: the board's CPU, port 1: the controller.
    virtual void on_access(int board, const Access &a) = 0;
};

class SystemSim {
public:
    static const int kBoards = 4;               // matches tb_system's NB
    static const int kAddrWidth = 10;
    static const uint32_t kRamBytes = 4u << kAddrWidth;
    static const int kMaxLatency = 2;           // CPU port access time, as for the RAM alone

    // extra_plusargs: more +name=value arguments for the model (e.g. the ROM upset).
    explicit SystemSim(const std::string &rom_file, const std::vector<std::string> &extra_plusargs = {});
    ~SystemSim();

    SimCpu cpu[kBoards];
    std::vector<RefRam> ref;
    SystemObserver *observer = nullptr;

    // Hold reset for a few clocks (CPU ports idle): the controller restarts.
    void reset();
    // Write bytes into board b's RAM through its CPU port (a RAM image).
    void load(int board, uint32_t addr, const uint8_t *bytes, uint32_t n);

    void issue(int board);                      // drive cpu[board]'s request
    bool busy(int board) const { return busy_[board]; }
    uint64_t issue_cycle(int board) const { return issue_cycle_[board]; }
    unsigned tick();                            // one clock; mask of CPU acks
    uint64_t cycle() const { return cycle_; }

    // Fault injection for the controller's accesses.
    void set_fault(unsigned kind);              // applied to the next access begun
    void set_dead(unsigned mask);               // permanently failed board links
    // The injector's count of new requests (fi_new_o), at the edge that
    // sampled their kind: to live boards (fault_accesses, of which
    // fault_injected had a kind other than 0) and to dead boards.
    // fault_drawn: the last tick started an access to a live board, so the
    // kind set by set_fault has been used (draw the next one).
    uint64_t fault_accesses = 0, fault_injected = 0, dead_accesses = 0;
    bool fault_drawn = false;
    // Targeted faults outside the random process (negative tests): if the
    // next edge starts a new request to a live board, next_request() gives
    // it; force_fault(k) gives that one request kind k instead of the drawn
    // kind, which stays for the next one.  Counted in forced_faults only.
    bool next_request(int &board, uint32_t &addr, bool &we, uint8_t &sel) const;
    void force_fault(unsigned kind);
    uint64_t forced_faults = 0;

    // The controller, as seen from outside.
    uint32_t time() const;                      // global time (clocks since reset)
    unsigned mode() const;                      // the controller's running schedule mode (a probe)
    bool cycle_start() const;                   // after tick(): a minor cycle starts in this clock (a probe)
    bool error() const;
    unsigned rom_errors() const;
    uint64_t bus_busy_cycles = 0, bus_accesses = 0, bus_failures = 0;
    // The controller's access completed at the last tick, if any.
    struct BusEvent {
        bool done = false, ok = false, we = false;
        int board = 0;
        uint32_t addr = 0;          // byte address in that board's RAM
        uint8_t sel = 0;            // byte lanes
        uint32_t wdata = 0, rdata = 0;  // store data; load data (valid with ok)
        uint32_t time = 0;          // the controller's time_o in the answer's clock
        uint64_t start = 0, end = 0;  // edges: request presented .. answer sampled
    } bus_event;
    bool bus_stb() const;

    uint64_t cpu_latency_violations = 0, worst_cpu_latency = 0;
    std::string first_cpu_latency_violation;

private:
    void drive(int board, const BusRequest *r);

    std::unique_ptr<Vsys> dut_;
    uint64_t cycle_ = 0;
    bool busy_[kBoards] = {};
    uint64_t issue_cycle_[kBoards] = {};
    bool bus_prev_stb_ = false;
    unsigned drawn_kind_ = 0;     // set_fault's kind
    bool forced_ = false;         // force_fault for the next edge
    uint64_t bus_start_ = 0;
    bool loading_[kBoards] = {};       // load() owns the CPU port
    BusRequest load_req_[kBoards] = {};
};
