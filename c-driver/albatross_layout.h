/*
 * albatross_layout.h -- memory layout of one ALBATROSS channel in a
 * dual-ported RAM (the paper, section 3.1, figure 2).  Shared by the C driver, the
 * testbenches and the hardware controller; byte offsets from the channel base.
 * Generated from rtl/albatross_contract.toml by make contract
 * (compiler/albatross_schedule/contract_gen.py); do not edit.
 *
 *   offset            size  contents                           written only by
 *   0                 1     Actual: 1, 2 or 3 (Buffer1..3)     the producer
 *   1                 1     ReadLocked: 1, 2 or 3              the consumer
 *   2                 2     reserved, 0                        -
 *   4                 S     Buffer1                            the producer
 *   4 + S             S     Buffer2                            the producer
 *   4 + 2S            S     Buffer3                            the producer
 *
 * S = payload size rounded up to a multiple of 4, so every buffer is
 * word-aligned when the channel base is.  Buffer indices are stored as
 * 1 = Buffer1, 2 = Buffer2, 3 = Buffer3; 0 means that the byte's writer has not set it yet
 * (a zeroed RAM: Actual = nothing published yet, ReadLocked = no buffer
 * locked); any other value is invalid and reported by the driver.  Channel bases must be
 * 4-byte aligned.  Multi-byte payload words are little-endian (byte lane 0 is
 * the lowest address).
 */
#ifndef ALBATROSS_LAYOUT_H
#define ALBATROSS_LAYOUT_H

#define ALB_OFF_ACTUAL      0u
#define ALB_OFF_READLOCKED  1u
#define ALB_OFF_BUFFERS     4u
#define ALB_BUFFER1         1u
#define ALB_BUFFER3         3u
/* A control byte its writer has not set yet (cold start on a zeroed RAM). */
#define ALB_NOT_STARTED     0u

/* Payload size rounded up to whole words: the stride between buffers. */
#define ALB_STRIDE(size)          (((size) + 3u) & ~3u)
/* Byte offset of buffer b (1..3) of a channel with the given payload size. */
#define ALB_OFF_BUFFER(b, size)   (ALB_OFF_BUFFERS + ((b) - ALB_BUFFER1) * ALB_STRIDE(size))
/* Bytes one channel occupies in the dual-ported RAM. */
#define ALB_CHANNEL_BYTES(size)   (ALB_OFF_BUFFERS + 3u * ALB_STRIDE(size))
/* A control byte value names a buffer. */
#define ALB_VALID_INDEX(v)        ((v) >= ALB_BUFFER1 && (v) <= ALB_BUFFER3)

/* The four-slot kind (docs/four_slot.md): the same control bytes, the two
 * reserved bytes as the producer's slot bytes (Slot0, Slot1: 0 or 1, the
 * slot of each pair completed last) and a fourth buffer.  Buffer b
 * (1..4) is pair (b - 1) >> 1, slot (b - 1) & 1. */
#define ALB_OFF_SLOT0       2u
#define ALB_OFF_SLOT1       3u
#define ALB_FS_BUFFERS      4u
#define ALB_BUFFER4         4u
#define ALB_FS_INITIAL_SLOT 0u
/* Bytes one four-slot channel occupies in the dual-ported RAM. */
#define ALB_FS_CHANNEL_BYTES(size) (ALB_OFF_BUFFERS + ALB_FS_BUFFERS * ALB_STRIDE(size))
/* A control byte value names a buffer of the four-slot kind. */
#define ALB_FS_VALID_INDEX(v)     ((v) >= ALB_BUFFER1 && (v) <= ALB_BUFFER4)
/* A slot byte value names a slot. */
#define ALB_FS_VALID_SLOT(v)      ((v) <= 1u)
/* Pair and slot of buffer b, and the buffer of pair p, slot s. */
#define ALB_FS_PAIR(b)            ((unsigned)((b) - ALB_BUFFER1) >> 1)
#define ALB_FS_SLOT(b)            ((unsigned)((b) - ALB_BUFFER1) & 1u)
#define ALB_FS_BUFFER(p, s)       (ALB_BUFFER1 + 2u * (p) + (s))
/* Byte offset of the slot byte of pair p (0 or 1). */
#define ALB_OFF_SLOT(p)           (ALB_OFF_SLOT0 + (p) * (ALB_OFF_SLOT1 - ALB_OFF_SLOT0))

#endif
