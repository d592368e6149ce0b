/* TEMPORARY: placeholder bodies for query families not implemented yet. Removed family by
 * family as each lands; nothing may ship with it. */
#ifndef CDIST_STUB_H
#define CDIST_STUB_H
#include "internal.h"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define CD_STUB(name, ...)                                                                                  \
    cdist_status name(__VA_ARGS__)                                                                      \
    {                                                                                                   \
        return cd_fail(q, CDIST_ERR_INTERNAL, #name " is not implemented yet");                        \
    }
#endif
