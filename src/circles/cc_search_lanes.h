/* SPDX-License-Identifier: MIT */
/* The circle-circle search's lane bodies for every instruction set: for 1 lane, then (x86) 8
 * lanes (AVX-512) and 4 (AVX2), the lane operations, double-double, cc_search_body.h and the
 * includer's own body, named by CC_LANES_BODY (a header path), each variant compiled for its
 * instruction set. No include guard: included once per file that instantiates a body. */
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/dd.h"
#include "circles/cc_search_body.h"
#include CC_LANES_BODY
#include "base/lanes/lanes_undef.h"

#ifdef CD_X86_KERNELS
CD_LANES_TARGET_PUSH("avx512f,fma")
#define CD_LANES 8
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/dd.h"
#include "circles/cc_search_body.h"
#include CC_LANES_BODY
#include "base/lanes/lanes_undef.h"
CD_LANES_TARGET_POP

CD_LANES_TARGET_PUSH("avx2,fma")
#define CD_LANES 4
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/dd.h"
#include "circles/cc_search_body.h"
#include CC_LANES_BODY
#include "base/lanes/lanes_undef.h"
CD_LANES_TARGET_POP
#endif
#undef CC_LANES_BODY
