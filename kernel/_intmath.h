/* Integer helpers shared by the compiled kernels (kernel/_bba.c, kernel/_f4lift.c, kernel/_fglm_proof.c). */
#ifndef MECH_INTMATH_H
#define MECH_INTMATH_H
#include <stdint.h>

typedef unsigned __int128 u128;
typedef __int128 i128;

/* gcd(|a|, |b|) */
static inline int64_t gcd_i64(int64_t a, int64_t b)
{
    if (a < 0)
        a = -a;
    if (b < 0)
        b = -b;
    while (b) {
        int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}
#endif
