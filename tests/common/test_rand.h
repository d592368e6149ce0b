/* SPDX-License-Identifier: MIT */
/* The tests' reproducible pseudo-random numbers (xorshift64; a test may reseed test_rng first),
 * random unit vectors and the ulp of a double. */
#ifndef CDIST_TEST_RAND_H
#define CDIST_TEST_RAND_H

#include <math.h>
#include <stdint.h>

#include "circledist.h"

static uint64_t test_rng = 0x2545F4914F6CDD1Dull;

static inline uint64_t next_rand(void)
{
    test_rng ^= test_rng << 13;
    test_rng ^= test_rng >> 7;
    test_rng ^= test_rng << 17;
    return test_rng;
}

/* uniform in [0, 1) */
static inline double rnd01(void) { return (double)(next_rand() >> 11) * 0x1p-53; }

/* a random unit vector (uniform direction: rejection from the cube) */
static inline cdist_vec3 rnd_unit_vec(void)
{
    for (;;) {
        double x = 2 * rnd01() - 1, y = 2 * rnd01() - 1, z = 2 * rnd01() - 1, l = sqrt(x * x + y * y + z * z);
        if (l > 0.1 && l < 1) return (cdist_vec3){x / l, y / l, z / l};
    }
}

static inline double ulp(double x) { return nextafter(fabs(x), INFINITY) - fabs(x); }

#endif
