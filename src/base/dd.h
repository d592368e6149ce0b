/* SPDX-License-Identifier: MIT */
/* Double-double arithmetic over a lane type (src/base/lanes/lanes_def.h): included after
 * lanes_def.h, once per instruction set; scalar code uses the 1-lane instance (names ending _1).
 * A double-double is hi + lo with |lo| small against |hi|, not renormalised: every sum below is of
 * a few terms whose low parts stay far below an ulp of the high part. Needs a correctly rounded
 * fma (vfma). No include guard. */

/* a + b = s + *lo exactly (Knuth's TwoSum; no condition on |a|, |b|) */
CD_INLINE V KN(dd_two_sum)(V a, V b, V *lo)
{
    V s = vadd(a, b), bb = vsub(s, a);
    *lo = vadd(vsub(a, vsub(s, bb)), vsub(b, bb));
    return s;
}

/* a b = p + *lo exactly */
CD_INLINE V KN(dd_two_prod)(V a, V b, V *lo)
{
    V p = vmul(a, b);
    *lo = vfma(a, b, vneg(p));
    return p;
}

/* a c + b sn + g: the products exact, the two sums error-free, their errors in *lo */
CD_INLINE V KN(dd_trig)(V a, V b, V g, V c, V sn, V *lo)
{
    V e1, e2, e3, e4;
    V p = KN(dd_two_prod)(a, c, &e1), q = KN(dd_two_prod)(b, sn, &e2);
    V s1 = KN(dd_two_sum)(p, q, &e3), s2 = KN(dd_two_sum)(s1, g, &e4);
    *lo = vadd(vadd(e1, e2), vadd(e3, e4));
    return s2;
}

/* (xh + xl)^2 + (ah + al), the square's low part to first order */
CD_INLINE V KN(dd_sqr_add)(V xh, V xl, V ah, V al, V *lo)
{
    V e1, e2, p = KN(dd_two_prod)(xh, xh, &e1);
    V s = KN(dd_two_sum)(ah, p, &e2);
    *lo = vadd(vadd(vadd(al, e2), e1), vmul(vadd(xh, xh), xl));
    return s;
}
