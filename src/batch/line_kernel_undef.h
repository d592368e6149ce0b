/* SPDX-License-Identifier: MIT */
/* Undefines the lane macros a variant of line_kernel.c defines for line_kernel_body.h (every
 * name any variant uses: #undef of a name a variant left undefined is harmless). No include
 * guard: included once after each variant's body. */
#undef W
#undef LK_CHAINS
#undef V
#undef M
#undef KN
#undef vadd
#undef vsub
#undef vmul
#undef vdiv
#undef vneg
#undef vsqrt
#undef vfma
#undef vabs
#undef vmax
#undef vmin
#undef vlt
#undef vle
#undef vgt
#undef vge
#undef veq
#undef vne
#undef vsel
#undef mand
#undef mor
#undef mandn
#undef mnot
#undef mtrue
#undef mfalse
#undef many
#undef mbits
#undef vcmp_mask
#undef vload_objects
#undef vfrexp_m
#undef vfrexp_e
#undef vtrunc
#undef vscale2
#undef vset
#undef vld
#undef vst
#undef vexpbits
#undef vrecip2
