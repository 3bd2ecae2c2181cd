// system_sim.cpp -- see system_sim.h.
#include "system_sim.h"
#include <cstdio>
#include "Vsys.h"
#include "verilated.h"

namespace {

// Flattened vector ports: board b's field of width w at bits [b*w +: w].
template <typename T>
void put(T &port, int lsb, int width, uint64_t v)
{
    const T mask = static_cast<T>(((width >= 64 ? ~0ull : (1ull << width) - 1ull)) << lsb);
    port = static_cast<T>((port & ~mask) | ((static_cast<T>(v) << lsb) & mask));
}

template <typename T>
uint64_t get(const T &port, int lsb, int width)
{
    return (static_cast<uint64_t>(port) >> lsb) & (width >= 64 ? ~0ull : (1ull << width) - 1ull);
}

}  // namespace

SystemSim::SystemSim(const std::string &rom_file, const std::vector<std::string> &extra_plusargs)
    : ref(kBoards, RefRam(kRamBytes)), dut_()
{
    static std::vector<std::string> args;
    args = {"tb_system", "+rom=" + rom_file};
    args.insert(args.end(), extra_plusargs.begin(), extra_plusargs.end());
    static std::vector<const char *> argv;
    argv.clear();
    for (const std::string &a : args) argv.push_back(a.c_str());
    Verilated::commandArgs(static_cast<int>(argv.size()), argv.data());
    dut_.reset(new Vsys);
    for (int b = 0; b < kBoards; ++b) cpu[b].id = b;
    dut_->clk_i = 0;
    dut_->rst_i = 1;
    dut_->eval();       // every clock low before the first edge
    reset();
}

SystemSim::~SystemSim() { dut_->final(); }

void SystemSim::reset()
{
    for (int b = 0; b < kBoards; ++b) { drive(b, nullptr); busy_[b] = false; }
    dut_->fi_kind_i = 0;
    fault_accesses = fault_injected = dead_accesses = 0;
    dut_->rst_i = 1;
    for (int i = 0; i < 4; ++i) tick();
    dut_->rst_i = 0;
}

void SystemSim::drive(int b, const BusRequest *r)
{
    const uint32_t amask = (1u << kAddrWidth) - 1u;   // ports are not masked by Verilator
    put(dut_->cpu_cyc_i, b, 1, r != nullptr);
    put(dut_->cpu_stb_i, b, 1, r != nullptr);
    put(dut_->cpu_we_i, b, 1, r ? r->we : 0);
    put(dut_->cpu_adr_i, b * kAddrWidth, kAddrWidth, r ? (r->addr >> 2) & amask : 0);
    put(dut_->cpu_sel_i, b * 4, 4, r ? r->sel & 0xFu : 0);
    dut_->cpu_dat_i[b] = r ? r->wdata : 0;
}

void SystemSim::issue(int b)
{
    if (busy_[b] || !cpu[b].has_request) return;
    drive(b, &cpu[b].request);
    busy_[b] = true;
    issue_cycle_[b] = cycle_;
}

void SystemSim::load(int b, uint32_t addr, const uint8_t *bytes, uint32_t n)
{
    for (uint32_t i = 0; i < n;) {
        uint32_t a = addr + i, word = 0;
        uint8_t sel = 0;
        uint32_t first = i;
        for (uint32_t lane = a & 3u; lane < 4 && i < n; ++lane, ++i) {
            word |= static_cast<uint32_t>(bytes[i]) << (8 * lane);
            sel |= static_cast<uint8_t>(1u << lane);
        }
        BusRequest r{a & ~3u, word, sel, true};
        loading_[b] = true;
        load_req_[b] = r;
        drive(b, &r);
        busy_[b] = true;
        issue_cycle_[b] = cycle_;
        for (int guard = 0; busy_[b] && guard < 16; ++guard) tick();
        loading_[b] = false;
        drive(b, nullptr);
        busy_[b] = false;
        // The reference learns the bytes once the RAM holds them: the
        // controller runs meanwhile, and a read of port B between the two
        // would otherwise be compared with bytes not yet written.
        for (uint32_t lane = a & 3u, k = first; lane < 4 && k < n; ++lane, ++k)
            ref[b].preload((a & ~3u) + lane, bytes[k]);
    }
}

void SystemSim::set_fault(unsigned kind) { drawn_kind_ = kind & 3u; if (!forced_) dut_->fi_kind_i = drawn_kind_; }
void SystemSim::force_fault(unsigned kind) { forced_ = true; dut_->fi_kind_i = kind & 3u; }
bool SystemSim::next_request(int &board, uint32_t &addr, bool &we, uint8_t &sel) const
{
    if (!dut_->fi_new_o || dut_->fi_dead_o || dut_->rst_i) return false;
    board = static_cast<int>(dut_->bus_adr_o >> kAddrWidth) & 0xF;
    addr = static_cast<uint32_t>(dut_->bus_adr_o & ((1u << kAddrWidth) - 1u)) << 2;
    we = dut_->bus_we_o != 0;
    sel = static_cast<uint8_t>(dut_->bus_sel_o & 0xFu);
    return true;
}
void SystemSim::set_dead(unsigned mask) { dut_->fi_dead_i = mask & ((1u << kBoards) - 1u); }
uint32_t SystemSim::time() const { return dut_->time_o; }
unsigned SystemSim::mode() const { return dut_->mode_o; }
bool SystemSim::cycle_start() const { return dut_->cycle_o != 0; }
bool SystemSim::bus_stb() const { return dut_->bus_stb_o != 0; }
bool SystemSim::error() const { return dut_->error_o != 0; }
unsigned SystemSim::rom_errors() const { return dut_->rom_errors_o; }

unsigned SystemSim::tick()
{
    // A new request samples fi_kind_i at this edge (the injector's fi_new_o,
    // settled: the controller's request comes from its registers).
    fault_drawn = false;
    const bool forced = forced_;
    if (dut_->fi_new_o && !dut_->rst_i) {
        if (dut_->fi_dead_o) ++dead_accesses;
        else if (forced) ++forced_faults;
        else {
            ++fault_accesses;
            if (dut_->fi_kind_i) ++fault_injected;
            fault_drawn = true;
        }
    }
    dut_->clk_i = 1;
    dut_->eval();
    dut_->clk_i = 0;
    dut_->eval();
    ++cycle_;
    if (forced) {                   // the drawn kind waits for the next request
        forced_ = false;
        dut_->fi_kind_i = drawn_kind_;
    }
    // The controller's bus, as it sees it: an access begins when stb rises
    // or stays high after the previous access ended; it ends at ack or err
    // (or when the controller gives up and drops stb).
    bus_event.done = false;
    bool stb = dut_->bus_stb_o != 0;
    if (stb && !bus_prev_stb_) bus_start_ = cycle_;   // raised at this edge
    if (dut_->bus_cyc_o) ++bus_busy_cycles;
    if (stb && (dut_->bus_ack_o || dut_->bus_err_o)) {
        bus_event.done = true;
        bus_event.ok = dut_->bus_ack_o != 0;
        bus_event.we = dut_->bus_we_o != 0;
        bus_event.board = static_cast<int>(dut_->bus_adr_o >> kAddrWidth) & 0xF;
        bus_event.addr = static_cast<uint32_t>(dut_->bus_adr_o & ((1u << kAddrWidth) - 1u)) << 2;
        bus_event.sel = static_cast<uint8_t>(dut_->bus_sel_o & 0xFu);
        bus_event.wdata = dut_->bus_wdat_o;
        bus_event.rdata = dut_->bus_rdat_o;
        bus_event.time = dut_->time_o;
        bus_event.start = bus_start_;
        bus_event.end = cycle_ + 1;    // the controller samples the answer at the next edge
        if (dut_->bus_ack_o) ++bus_accesses; else ++bus_failures;
        bus_start_ = cycle_ + 1;       // a request held on begins there
    }
    bus_prev_stb_ = stb && !(dut_->bus_ack_o || dut_->bus_err_o);
    unsigned mask = 0;
    for (int b = 0; b < kBoards; ++b) {
        Access done[2];
        int n = 0;
        if (get(dut_->cpu_ack_o, b, 1) && busy_[b]) {
            uint64_t latency = cycle_ - issue_cycle_[b];
            if (latency > worst_cpu_latency) worst_cpu_latency = latency;
            if (latency > static_cast<uint64_t>(kMaxLatency) && cpu_latency_violations++ == 0) {
                char m[120];
                std::snprintf(m, sizeof m, "access time: CPU %d acknowledged after %llu cycles, expected at most %d",
                              b, static_cast<unsigned long long>(latency), kMaxLatency);
                first_cpu_latency_violation = m;
            }
            done[n++] = Access{0, loading_[b] ? load_req_[b] : cpu[b].request, dut_->cpu_dat_o[b],
                               issue_cycle_[b], cycle_};
            busy_[b] = false;
            drive(b, nullptr);
            mask |= 1u << b;
        }
        if (get(dut_->mon_ack_o, b, 1)) {
            BusRequest r;
            r.addr = static_cast<uint32_t>(get(dut_->mon_adr_o, b * kAddrWidth, kAddrWidth)) << 2;
            r.sel = static_cast<uint8_t>(get(dut_->mon_sel_o, b * 4, 4));
            r.we = get(dut_->mon_we_o, b, 1) != 0;
            r.wdata = dut_->mon_wdat_o[b];
            done[n++] = Access{1, r, dut_->mon_rdat_o[b], cycle_, cycle_};
        }
        if (!n) continue;
        ref[b].check_and_apply(done, n);
        if (loading_[b]) continue;   // a RAM image, not a CPU access
        for (int i = 0; i < n; ++i) {
            if (done[i].port == 0) {
                SimCpu &c = cpu[b];
                c.rdata = done[i].rdata;
                c.has_request = false;
                ++c.accesses;
            }
            if (observer) observer->on_access(b, done[i]);
        }
    }
    return mask;
}
