// Generated from rtl/albatross_contract.toml by make contract (compiler/albatross_schedule/contract_gen.py); do not edit.
// The ALBATROSS contract for the C++ testbenches: schedule ROM fields (word index
// in the header or entry, lsb, width), constants, the CRC, and the channel
// layout.  See docs/contract.md.
#pragma once
#include <cstdint>

namespace alb_contract {

struct Field {
    unsigned word, lsb, width;  // word: index within the header, an entry or a mode descriptor
    constexpr uint32_t max() const { return width >= 32 ? 0xFFFFFFFFu : (1u << width) - 1u; }
    constexpr uint32_t put(uint32_t v) const { return (v & max()) << lsb; }
    constexpr uint32_t get(uint32_t w) const { return (w >> lsb) & max(); }
};

constexpr unsigned ROM_HEADER_WORDS = 4, ROM_ENTRY_WORDS = 8;
constexpr unsigned ROM_MAX_ENTRIES = 255, ROM_MAX_DESTS = 4;
constexpr uint32_t ROM_MAGIC = 0xA1BAu;
constexpr uint32_t ROM_CRC_POLY = 0x000000AFu, ROM_CRC_SEED = 0xFFFFFFFFu;
constexpr unsigned ROM_CRC_WORD = 3, ROM_TIME_BITS = 16;

constexpr Field H0_MAGIC{0, 16, 16};
constexpr Field H0_NE{0, 8, 8};
constexpr Field H0_FLAGS{0, 0, 8};
constexpr Field H1_CYCLE{1, 0, 16};
constexpr Field H1_NEXT{1, 16, 16};
constexpr Field H2_DROP_RUN{2, 0, 8};
constexpr Field H2_TABLE{2, 8, 8};
constexpr Field H2_MODES{2, 16, 4};
constexpr Field H2_CLUSTER{2, 20, 4};
constexpr Field H2_START_END{2, 24, 8};
constexpr Field H3_CRC{3, 0, 32};
constexpr Field E0_KIND{0, 28, 4};
constexpr Field E0_FLAGS{0, 24, 4};
constexpr Field E0_ID{0, 16, 8};
constexpr Field E0_ND{0, 12, 4};
constexpr Field E0_W{0, 0, 12};
constexpr Field E1_START{1, 0, 16};
constexpr Field E2_LENGTH{2, 0, 16};
constexpr Field E3_SRC{3, 0, 16};
constexpr Field E3_SRC_BOARD{3, 12, 4};
constexpr Field E3_SRC_BASE{3, 0, 12};
constexpr Field E4_DST0{4, 0, 16};
constexpr Field E4_DST0_BOARD{4, 12, 4};
constexpr Field E4_DST0_BASE{4, 0, 12};
constexpr Field E4_DST1{4, 16, 16};
constexpr Field E4_DST1_BOARD{4, 28, 4};
constexpr Field E4_DST1_BASE{4, 16, 12};
constexpr Field E5_DST2{5, 0, 16};
constexpr Field E5_DST2_BOARD{5, 12, 4};
constexpr Field E5_DST2_BASE{5, 0, 12};
constexpr Field E5_DST3{5, 16, 16};
constexpr Field E5_DST3_BOARD{5, 28, 4};
constexpr Field E5_DST3_BASE{5, 16, 12};
constexpr Field E6_BASE{6, 0, 15};
constexpr Field E6_REP{6, 16, 4};
constexpr Field E7_FRAG{7, 0, 12};
constexpr Field D0_CYCLE{0, 0, 16};
constexpr Field D0_FIRST{0, 16, 8};
constexpr Field D0_END{0, 24, 8};
constexpr Field D1_DROP_RUN{1, 0, 8};
constexpr Field D1_NEXT{1, 16, 16};
constexpr Field D2_CLUSTER{2, 20, 4};
constexpr Field PLACE_BOARD{0, 12, 4};
constexpr Field PLACE_BASE{0, 0, 12};
// destination places of an entry, in order
constexpr Field DST[] = {E4_DST0, E4_DST1, E5_DST2, E5_DST3};

constexpr unsigned KIND_IDLE = 0;
constexpr unsigned KIND_COPY = 1;
constexpr unsigned KIND_TIME = 2;
constexpr unsigned KIND_STATUS = 3;
constexpr unsigned HFLAG_SYNC_MODE = 1u << 0;  // in H0.flags
constexpr unsigned EFLAG_SYNC = 1u << 0;  // in E0.flags
constexpr unsigned EFLAG_FOUR_SLOT = 1u << 1;  // in E0.flags
constexpr unsigned EFLAG_REQUEST = 1u << 2;  // in E0.flags
constexpr unsigned EFLAG_MODE = 1u << 3;  // in E0.flags

// CRC of n ROM words (the check word ROM_CRC_WORD too): 0 for a valid image.
inline uint32_t rom_crc(const uint32_t *w, int n) {
    uint32_t c = ROM_CRC_SEED;
    for (int i = 0; i < n; ++i) {
        for (int b = 0; b < 32; ++b) c = (c << 1) ^ ((c >> 31) ? ROM_CRC_POLY : 0u);
        c ^= w[i];
    }
    return c;
}
// The check word of an image of n words: the word ROM_CRC_WORD that makes its
// CRC 0 (the word it holds plus the CRC times x^-(32 (n - 1 - ROM_CRC_WORD)) mod P).
inline uint32_t rom_check_word(const uint32_t *w, int n) {
    uint32_t c = rom_crc(w, n);
    for (int b = 0; b < 32 * (n - 1 - (int)ROM_CRC_WORD); ++b)
        c = (c & 1u) ? ((c ^ ROM_CRC_POLY) >> 1) | 0x80000000u : c >> 1;
    return w[ROM_CRC_WORD] ^ c;
}
constexpr uint32_t place(uint32_t board, uint32_t base_word) {
    return PLACE_BOARD.put(board) | PLACE_BASE.put(base_word);
}

// channel layout: byte offsets from the channel base
constexpr uint32_t OFF_ACTUAL = 0, OFF_READLOCKED = 1, OFF_BUFFERS = 4;
constexpr uint32_t WORD_BYTES = 4, BUFFERS = 3, BUFFER1 = 1, INITIAL_INDEX = 1;
constexpr uint32_t TAKEN_AT_WORDS = 1;
// four-slot kind: slot bytes, four buffers; buffer b is pair (b-1)>>1, slot (b-1)&1
constexpr uint32_t OFF_SLOT0 = 2, OFF_SLOT1 = 3;
constexpr uint32_t FS_BUFFERS = 4, FS_INITIAL_SLOT = 0;
// Bytes of a destination payload: the value's words, then taken_at.
constexpr uint32_t dest_bytes(uint32_t words) { return WORD_BYTES * (words + TAKEN_AT_WORDS); }
// Byte offset of taken_at in a destination payload.
constexpr uint32_t taken_at_offset(uint32_t words) { return WORD_BYTES * words; }

}  // namespace alb_contract
