// ref_ram.h -- a reference model of one RAM, byte by byte, and the
// byte-atomicity checker built on it.
//
// Every write updates the model at the edge that performs it.  A read
// performed at edge e must return, for every byte it selects, the byte's value
// before e or (if another port writes that byte at the same edge) the value
// written at e: anything else is a torn or invented byte.  Bytes never
// written are unknown and accept any value.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "sim_cpu.h"

// One completed transaction, as seen at the port.
struct Access {
    int        port;         // 0 = A, 1 = B
    BusRequest req;
    uint32_t   rdata;
    uint64_t   issue_cycle;  // cycle its request was first driven
    uint64_t   serve_cycle;  // the edge that performed it (= ack seen)
};

class RefRam {
public:
    explicit RefRam(uint32_t bytes) : mask_(bytes - 1u), ref_(bytes, 0), known_(bytes, 0) {}

    // The accesses performed at one edge (at most one per port): check the
    // reads, then apply the writes.
    void check_and_apply(const Access *done, int n);
    // A write that bypasses the ports (a RAM image).
    void preload(uint32_t addr, uint8_t v) { ref_[addr & mask_] = v; known_[addr & mask_] = 1; }
    uint8_t byte(uint32_t addr) const { return ref_[addr & mask_]; }

    uint64_t violations = 0;
    std::string first_violation;
    uint64_t same_edge_collisions = 0;  // a read and a write of one byte at one edge

private:
    uint32_t mask_;
    std::vector<uint8_t> ref_;
    std::vector<uint8_t> known_;   // 0: unknown (never written, or two writers at one edge)
};
