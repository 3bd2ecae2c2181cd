// ram_bus.cpp -- clocking the Verilated RAM; every completed access goes
// through the byte-atomicity checker (ref_ram.h).
#include "ram_bus.h"
#include <cstdio>
#include "Vdut.h"
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif

struct RamBus::Tracer {
#if VM_TRACE
    VerilatedVcdC vcd;
#endif
    uint64_t max_cycles = 0;
    uint64_t time = 0;
};

bool RamBus::trace(const char *path, uint64_t max_cycles)
{
#if VM_TRACE
    Verilated::traceEverOn(true);
    tracer_.reset(new Tracer);
    tracer_->max_cycles = cycle_ + max_cycles;
    dut_->trace(&tracer_->vcd, 99);
    tracer_->vcd.open(path);
    return tracer_->vcd.isOpen();
#else
    (void)path;
    (void)max_cycles;
    return false;
#endif
}

// One eval, dumped to the wave while tracing (10 time units per half cycle).
void RamBus::eval_traced()
{
    dut_->eval();
#if VM_TRACE
    if (tracer_) {
        tracer_->vcd.dump(tracer_->time);
        tracer_->time += 5;
        if (cycle_ >= tracer_->max_cycles) {
            tracer_->vcd.close();
            tracer_.reset();
        }
    }
#endif
}

RamBus::RamBus() : ref(kBytes), dut_(new Vdut)
{
    cpu[0].id = 0;
    cpu[1].id = 1;
    dut_->clk_i = 0;
    dut_->rst_i = 0;
    dut_->eval();           // every clock low before the first edge
    reset();
}

RamBus::~RamBus()
{
#if VM_TRACE
    if (tracer_) tracer_->vcd.close();
#endif
    dut_->final();
}

void RamBus::reset()
{
    drive(0, nullptr);
    drive(1, nullptr);
    busy_[0] = busy_[1] = false;
    dut_->rst_i = 1;
    tick();
    tick();
    dut_->rst_i = 0;
    reset_cycle_ = cycle_;
}

void RamBus::drive(int port, const BusRequest *r)
{
    const uint32_t mask = (1u << kAddrWidth) - 1u;   // ports are not masked
    uint8_t on = r != nullptr;
    uint32_t adr = r ? (r->addr >> 2) & mask : 0u;
    uint8_t sel = r ? (r->sel & 0xFu) : 0u;
    uint8_t we = r ? r->we : 0u;
    uint32_t dat = r ? r->wdata : 0u;
    if (port == 0) {
        dut_->a_cyc_i = on; dut_->a_stb_i = on; dut_->a_we_i = we;
        dut_->a_adr_i = adr; dut_->a_sel_i = sel; dut_->a_dat_i = dat;
    } else {
        dut_->b_cyc_i = on; dut_->b_stb_i = on; dut_->b_we_i = we;
        dut_->b_adr_i = adr; dut_->b_sel_i = sel; dut_->b_dat_i = dat;
    }
}

void RamBus::issue(int port)
{
    if (busy_[port] || !cpu[port].has_request) return;
    drive(port, &cpu[port].request);
    busy_[port] = true;
    late_[port] = false;
    issue_cycle_[port] = cycle_;
}

void RamBus::load(uint32_t addr, const uint8_t *bytes, uint32_t n)
{
    for (uint32_t i = 0; i < n;) {
        uint32_t a = addr + i, lane = a & 3u, word = 0;
        uint8_t sel = 0;
        for (; lane < 4 && i < n; ++lane, ++i) {
            word |= static_cast<uint32_t>(bytes[i]) << (8 * lane);
            sel |= static_cast<uint8_t>(1u << lane);
            ref.preload((a & ~3u) + lane, bytes[i]);
        }
        BusRequest r{a & ~3u, word, sel, true};
        drive(0, &r);
        // Bounded: a RAM that never acknowledges fails the access-time check.
        uint64_t from = cycle_;
        while (!(tick() & 1u)) {
            if (cycle_ - from > 64) {
                if (latency_violations++ == 0) {
                    char msg[160];
                    std::snprintf(msg, sizeof msg, "access time: loading the RAM image, port A had no acknowledge "
                                  "for address 0x%x after 64 cycles, expected one within %d", a & ~3u, kMaxLatency);
                    first_latency_violation = msg;
                }
                break;
            }
        }
        drive(0, nullptr);
    }
}

unsigned RamBus::tick()
{
    dut_->clk_i = 1;
    eval_traced();
    dut_->clk_i = 0;
    eval_traced();
    ++cycle_;
    Access done[2];
    int n = 0;
    unsigned mask = 0;
    bool ack[2] = {dut_->a_ack_o != 0, dut_->b_ack_o != 0};
    uint32_t dat[2] = {dut_->a_dat_o, dut_->b_dat_o};
    for (int p = 0; p < 2; ++p) {
        if (!ack[p]) {
            // Not yet acknowledged: a violation as soon as it is late (a RAM
            // that never answers is caught without waiting for an ack).
            if (busy_[p] && !late_[p] && cycle_ - issue_cycle_[p] > kMaxLatency) {
                late_[p] = true;
                if (latency_violations++ == 0) {
                    char msg[160];
                    std::snprintf(msg, sizeof msg, "access time: port %c issued at cycle %llu had no acknowledge "
                                  "after %llu cycles, expected one within %d", 'A' + p,
                                  static_cast<unsigned long long>(issue_cycle_[p]),
                                  static_cast<unsigned long long>(cycle_ - issue_cycle_[p]), kMaxLatency);
                    first_latency_violation = msg;
                }
            }
            continue;
        }
        mask |= 1u << p;
        if (busy_[p]) {
            uint64_t latency = cycle_ - issue_cycle_[p];
            if (latency > worst_latency) worst_latency = latency;
            if (latency > kMaxLatency && !late_[p] && latency_violations++ == 0) {
                char msg[120];
                std::snprintf(msg, sizeof msg, "access time: port %c acknowledged after %llu cycles, expected at most %d",
                              'A' + p, static_cast<unsigned long long>(latency), kMaxLatency);
                first_latency_violation = msg;
            }
            done[n++] = Access{p, cpu[p].request, dat[p], issue_cycle_[p], cycle_};
            busy_[p] = false;
            drive(p, nullptr);
        }
    }
    if (n) ref.check_and_apply(done, n);
    for (int i = 0; i < n; ++i) {
        SimCpu &c = cpu[done[i].port];
        c.rdata = done[i].rdata;
        c.has_request = false;
        ++c.accesses;
        if (observer) observer->on_access(done[i]);
    }
    accesses += n;
    return mask;
}
