// rom_scenario.cpp -- see rom_scenario.h.
#include "rom_scenario.h"
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace tbsys {

namespace {
std::string g_tmp;
void remove_tmp() { if (!g_tmp.empty()) unlink(g_tmp.c_str()); }
}  // namespace

std::string flip_rom_bit(const std::string &rom, int word, int bit, std::string &err)
{
    std::ifstream in(rom);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    // $readmemh, one 32-bit word a line (schedule compiler output): no address marks.
    if (word < 0 || static_cast<size_t>(word) >= lines.size() || bit < 0 || bit > 31 ||
        lines[static_cast<size_t>(word)].find('@') != std::string::npos) {
        err = "--flip-rom-bit: " + rom + " has no word " + std::to_string(word) + " (or bit " +
              std::to_string(bit) + " is outside 0..31)";
        return "";
    }
    char *end = nullptr;
    const std::string &w = lines[static_cast<size_t>(word)];
    const unsigned long v = std::strtoul(w.c_str(), &end, 16);
    if (w.empty() || *end) {
        err = "--flip-rom-bit: word " + std::to_string(word) + " of " + rom + " is not one hex word: " + w;
        return "";
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "%08lx", (v ^ (1ul << bit)) & 0xFFFFFFFFul);
    lines[static_cast<size_t>(word)] = hex;
    char path[] = "/tmp/tb_system_rom_XXXXXX";
    const int fd = mkstemp(path);
    if (fd < 0) {
        err = "--flip-rom-bit: cannot create a temporary file";
        return "";
    }
    close(fd);
    std::ofstream out(path);
    for (const std::string &l : lines) out << l << "\n";
    if (!out) {
        err = std::string("--flip-rom-bit: cannot write ") + path;
        return "";
    }
    g_tmp = path;
    std::atexit(remove_tmp);
    return g_tmp;
}

void rom_refused_verdict(const Plan &plan, const SystemChecker &chk, SystemSim &sim, std::vector<std::string> &failures)
{
    std::vector<std::string> kept;
    for (const std::string &f : failures)
        if (f.find("no value was ever published") == std::string::npos &&
            f.find("STATUS: no transfer counted") == std::string::npos &&
            f != "the controller flagged its ROM header as invalid")
            kept.push_back(f);
    uint64_t pubs = 0;
    for (size_t i = 0; i < plan.channels.size(); ++i)
        for (const SystemChecker::DestStats &ds : chk.stats[i].dests) pubs += ds.publications;
    char m[300];
    std::printf("  flipped ROM bit: error_o %d, %llu controller bus accesses, %llu publications\n", sim.error() ? 1 : 0,
                static_cast<unsigned long long>(sim.bus_accesses), static_cast<unsigned long long>(pubs));
    if (!sim.error() || sim.bus_accesses || pubs) {
        std::snprintf(m, sizeof m, "flipped ROM bit: expected the start-up CRC check to refuse the image (error_o 1, "
                      "no bus access, nothing published), got error_o %d, %llu bus accesses, %llu publications",
                      sim.error() ? 1 : 0, static_cast<unsigned long long>(sim.bus_accesses),
                      static_cast<unsigned long long>(pubs));
        kept.push_back(m);
    }
    failures.swap(kept);
}

}  // namespace tbsys
