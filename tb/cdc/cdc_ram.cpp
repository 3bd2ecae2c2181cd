// cdc_ram.cpp -- the RAM-side monitor of the albatross_wb_cdc bench: the ram
// checks on each bridge's RAM bus and the reference memory they feed
// (declarations in cdc_tb.h).
#include "cdc_tb.h"

void ram_access(Cpu &cpu, Mon &m, const MonSample &s, uint64_t t_go, uint64_t t,
                       bool in_reset) {
    if (in_reset) {  // registers may still hold power-up garbage
        m.prev = s;
        return;
    }
    ++g_checks[CHK_RAM];
    if (s.cyc != s.stb)
        fail(CHK_RAM, "bridge %c RAM bus at t=%" PRIu64 ": expected cyc == stb, came cyc=%d stb=%d",
             m.name, t, s.cyc, s.stb);
    if (s.ack && !s.stb)
        fail(CHK_RAM, "RAM port %c at t=%" PRIu64 ": expected no ack without stb, came ack",
             m.name, t);
    if (m.prev.stb && !m.prev.ack) {  // a cycle in progress must hold its request
        if (!s.stb || s.we != m.prev.we || s.adr != m.prev.adr || s.sel != m.prev.sel ||
            (s.we && s.wdat != m.prev.wdat))
            fail(CHK_RAM,
                 "bridge %c RAM bus at t=%" PRIu64 ": expected request held until ack (stb=1 we=%d"
                 " adr=0x%02x sel=0x%x), came stb=%d we=%d adr=0x%02x sel=0x%x",
                 m.name, t, m.prev.we, m.prev.adr, m.prev.sel, s.stb, s.we, s.adr, s.sel);
    }
    if (s.stb && s.ack) {
        RamTx x{s.we, s.adr, s.sel, s.wdat, s.rdat, t_go};
        ++m.n_tx;
        for (int b = 0; b < 4; ++b) {
            Hist &hb = g_ref[x.adr * 4 + b];
            if (x.we) {
                if (x.sel >> b & 1) hb.h.emplace_back(t_go, (uint16_t)((x.wdat >> (8 * b)) & 0xff));
            } else {
                const uint8_t got = (uint8_t)(x.rdat >> (8 * b));
                if (hb.h.back().second == UNKNOWN) {
                    hb.h.back().second = got;  // power-up value, now known
                } else if (hb.h.back().second != got) {
                    fail(CHK_RAM,
                         "RAM port %c read adr 0x%02x byte %d at t=%" PRIu64 ": expected 0x%02x,"
                         " came 0x%02x",
                         m.name, x.adr, b, t_go, hb.h.back().second, got);
                }
            }
        }
        cpu.ramq.push_back(x);
    }
    m.prev = s;
}
