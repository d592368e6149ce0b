/* Point family cores (src/point/point.c). */
#ifndef CDIST_POINT_PRIV_H
#define CDIST_POINT_PRIV_H

#include "base/best.h"
#include "base/vec.h"

/* Point p (relative to the circle centre) to circle/disk c (c->c ignored, taken as origin). */
void cd_point_circle_core(vec3 p, const cd_circle *c, cd_best *b, int swap);
void cd_point_disk_core(vec3 p, const cd_circle *c, cd_best *b, int swap);

#endif
