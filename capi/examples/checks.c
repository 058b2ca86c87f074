/* bandnoise from C: recomputes the crate's checksums of every runtime description it checks
 * (checks.h) through the C interface, in 16.16 fixed point and in float, and reports each
 * difference. The same source runs on the host and, under QEMU, on Cortex-M0 and Cortex-M4F
 * (capi/README.md); equal checksums mean the same bits as the Rust crate's. Its exit status
 * is 0 when none differs.
 *
 * Each checksum folds the raw bits of 64 samples at pseudo-random points of
 * (-range, range)^dims, multiples of 2^-16, into FNV-1a (checks/src/lib.rs). */

#include "bandnoise.h"
#include "checks.h"
#include "say.h"

#define POINTS 64u

/* Which number types to check: 1 fixed point, 2 float, 3 both. A Cortex-M0's 256 KiB of
 * flash hold the noises of one type at a time (capi/README.md), so its programs are built
 * with -DTYPES=1 and -DTYPES=2. */
#ifndef TYPES
#define TYPES 3
#endif

/* Which dimensions to check: bit d - 1 for d dimensions, all by default. The Cortex-M0's
 * programs check 1D and 2D (-DDIMS=3) with a library built with its features dim1 and dim2,
 * and 3D and 4D (-DDIMS=12) with one built with dim3 and dim4. */
#ifndef DIMS
#define DIMS 15
#endif

static uint32_t fnv_add(uint32_t h, uint32_t word) {
    for (int i = 0; i < 4; i++) {
        h ^= (word >> (8 * i)) & 0xFFu;
        h *= 0x01000193u;
    }
    return h;
}

/* Coordinate `axis` of point `i`, in 16.16. */
static int32_t coordinate(uint32_t i, uint32_t axis, int32_t range) {
    uint32_t h = (i * 0x9E3779B9u) ^ (axis * 0x85EBCA6Bu);
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return (int32_t)(h % ((2u * (uint32_t)range) << 16)) - (range << 16);
}

/* The two checksums of one description; 0 on success. */
static int checksums(const struct bn_check *c, bn_noise *noise, uint32_t out[2]) {
    bn_error error;
    if (bn_noise_init(noise, c->text, c->dims, &error) != BN_OK) {
        say(c->text);
        say(": ");
        say(error.message);
        say("\n");
        return 1;
    }
    uint32_t fixed = 0x811C9DC5u, f32 = 0x811C9DC5u;
    for (uint32_t i = 0; i < POINTS; i++) {
        int32_t q[4];
        float p[4];
        for (uint32_t a = 0; a < c->dims; a++) {
            q[a] = coordinate(i, a, c->range);
            p[a] = (float)q[a] / 65536.0f;
        }
        int32_t w = 0;
        float v = 0.0f;
        if (((TYPES & 1) && bn_sample_fixed(noise, q, &w) != BN_OK) ||
            ((TYPES & 2) && bn_sample_f32(noise, p, &v) != BN_OK)) {
            say(c->text);
            say(": sampling failed\n");
            return 1;
        }
        union { float f; uint32_t u; } bits = {v};
        fixed = fnv_add(fixed, (uint32_t)w);
        f32 = fnv_add(f32, bits.u);
    }
    out[0] = fixed;
    out[1] = f32;
    return 0;
}

int main(void) {
    static bn_noise noise; /* 1.4 KB: static, for a microcontroller's small stack */
    unsigned differ = 0, checked = 0;
    for (unsigned k = 0; k < BN_CHECKS; k++) {
        const struct bn_check *c = &bn_checks[k];
        if (!(DIMS & (1u << (c->dims - 1)))) {
            continue;
        }
        checked++;
        uint32_t got[2];
        if (checksums(c, &noise, got) != 0) {
            differ += 2;
            continue;
        }
        const uint32_t expected[2] = {c->fixed, c->f32};
        for (int t = 0; t < 2; t++) {
            if (TYPES & (1 << t) && got[t] != expected[t]) {
                say(t == 0 ? "differs: I16F16 " : "differs: f32 ");
                say_uint(c->dims);
                say("D ");
                say(c->text);
                say(": ");
                say_hex(got[t]);
                say(", expected ");
                say_hex(expected[t]);
                say("\n");
                differ++;
            }
        }
    }
    say_uint(((TYPES & 1) + (TYPES >> 1)) * checked);
    say(TYPES == 3 ? " checksums (I16F16 and f32) of " : TYPES == 1 ? " I16F16 checksums of " : " f32 checksums of ");
    say_uint(checked);
    say(" descriptions through the C interface, ");
    say_uint(differ);
    say(" differ\n");
    return differ == 0 && checked > 0 ? 0 : 1;
}
