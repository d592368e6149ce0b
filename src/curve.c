/* Parametric curves, arcs, helices and Bezier curves to circles and disks. */
#include "stub.h"
CD_STUB(cdist_curve_circle, cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_curve_disk, cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_arc_circle, cdist_query *q, const cdist_arc *a, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_arc_arc, cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r)
CD_STUB(cdist_segment_arc, cdist_query *q, const cdist_segment *s, const cdist_arc *a, cdist_result *r)
CD_STUB(cdist_arc_disk, cdist_query *q, const cdist_arc *a, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_helix_circle, cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_helix_disk, cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_bezier3_circle, cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_bezier3_disk, cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r)
