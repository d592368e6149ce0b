/* SPDX-License-Identifier: MIT */
/* Time of impact (src/topology/toi.c) against a dense time scan:
 *   test_toi [MOTIONS] [STEPS]
 * Each random motion is sampled at STEPS + 1 times (default 10^4) with the public contact
 * queries. Every interval between samples whose Lipschitz lower bound (d_i + d_i+1 - V h) / 2
 * (V from the triangle inequality |C - c| + r, not the library's reach) reaches the target is
 * subdivided (30 halvings); the first sample found at or below the target is the scan's contact
 * (motions whose subdivision exceeds a budget are skipped and counted, at most 1%). The
 * time-of-impact answer must never be later than that first contact (no tunnelling). On a hit,
 * the distance at the reported time (recomputed here) must be within the tolerance of the
 * target. "No impact" must have no contact in the scan. Hand-made cases: a ring
 * threading another's hole (no hit), one clipping the rim (hit), linked rings turning
 * (no hit), the posing formula, errors and the batch. */
#include <math.h>
#include <string.h>

#include "check.h"

#define TARGET_TOL 1e-7

static cdist_vec3 add(cdist_vec3 a, double s, cdist_vec3 b) { return tv(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
static double norm(cdist_vec3 a) { return sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

static int rank(int type) { return type == CDIST_SHAPE_TORUS ? 0 : type == CDIST_SHAPE_CAPSULE ? 1 : type == CDIST_SHAPE_SPHERE ? 2 : 3; }

/* Signed distance of two posed shapes through the public contact queries (ordered so that the
 * query exists; the distance is symmetric). */
static double shape_distance(cdist_query *q, const cdist_shape *x, const cdist_shape *y)
{
    if (rank(x->type) > rank(y->type)) {
        const cdist_shape *t = x;
        x = y;
        y = t;
    }
    cdist_contact c;
    cdist_status st = CDIST_ERR_INTERNAL;
    switch (x->type * 4 + y->type) {
    case CDIST_SHAPE_TORUS * 4 + CDIST_SHAPE_TORUS: st = cdist_torus_torus(q, &x->u.torus, &y->u.torus, &c); break;
    case CDIST_SHAPE_TORUS * 4 + CDIST_SHAPE_CAPSULE: st = cdist_torus_capsule(q, &x->u.torus, &y->u.capsule, &c); break;
    case CDIST_SHAPE_TORUS * 4 + CDIST_SHAPE_SPHERE: st = cdist_torus_sphere(q, &x->u.torus, &y->u.sphere, &c); break;
    case CDIST_SHAPE_TORUS * 4 + CDIST_SHAPE_ROUNDED_DISK:
        st = cdist_torus_rounded_disk(q, &x->u.torus, &y->u.rounded_disk, &c);
        break;
    case CDIST_SHAPE_CAPSULE * 4 + CDIST_SHAPE_CAPSULE: st = cdist_capsule_capsule(q, &x->u.capsule, &y->u.capsule, &c); break;
    case CDIST_SHAPE_CAPSULE * 4 + CDIST_SHAPE_SPHERE: st = cdist_capsule_sphere(q, &x->u.capsule, &y->u.sphere, &c); break;
    case CDIST_SHAPE_CAPSULE * 4 + CDIST_SHAPE_ROUNDED_DISK:
        st = cdist_capsule_rounded_disk(q, &x->u.capsule, &y->u.rounded_disk, &c);
        break;
    case CDIST_SHAPE_SPHERE * 4 + CDIST_SHAPE_SPHERE: st = cdist_sphere_sphere(q, &x->u.sphere, &y->u.sphere, &c); break;
    case CDIST_SHAPE_SPHERE * 4 + CDIST_SHAPE_ROUNDED_DISK:
        st = cdist_sphere_rounded_disk(q, &x->u.sphere, &y->u.rounded_disk, &c);
        break;
    case CDIST_SHAPE_ROUNDED_DISK * 4 + CDIST_SHAPE_ROUNDED_DISK:
        st = cdist_rounded_disk_rounded_disk(q, &x->u.rounded_disk, &y->u.rounded_disk, &c);
        break;
    default: break;
    }
    return st == CDIST_OK ? c.distance : NAN;
}

typedef struct motion_case {
    cdist_shape a, b;
    cdist_motion ma, mb;
    double target;
} motion_case;

static double dist_at(cdist_query *q, const motion_case *m, double t)
{
    cdist_shape pa, pb;
    if (cdist_shape_at(&m->a, &m->ma, t, &pa) || cdist_shape_at(&m->b, &m->mb, t, &pb)) return NAN;
    return shape_distance(q, &pa, &pb);
}

/* A bound on a core's distance from c by the triangle inequality (independent of the library's). */
static double loose_reach(const cdist_shape *s, cdist_vec3 c)
{
    switch (s->type) {
    case CDIST_SHAPE_SPHERE: return tdist(s->u.sphere.center, c);
    case CDIST_SHAPE_CAPSULE: return fmax(tdist(s->u.capsule.segment.p0, c), tdist(s->u.capsule.segment.p1, c));
    case CDIST_SHAPE_TORUS: return tdist(s->u.torus.circle.center, c) + s->u.torus.circle.radius;
    default: return tdist(s->u.rounded_disk.disk.center, c) + s->u.rounded_disk.disk.radius;
    }
}

static double speed_bound(const motion_case *m)
{
    return norm(add(m->ma.translation, -1, m->mb.translation)) + norm(m->ma.rotation) * loose_reach(&m->a, m->ma.center) +
           norm(m->mb.rotation) * loose_reach(&m->b, m->mb.center);
}

/* Distance evaluations one scan may spend on subdivision before it gives up on a motion (a
 * long graze just above the target would otherwise split every interval to the limit). */
#define SCAN_BUDGET 400000L
static long scan_budget;

/* First time in [t0, t1] with d <= target, given d(t0), d(t1): 1 found (*hit), 0 none, -1 the
 * budget ran out. An interval whose lower bound still reaches the target at the subdivision
 * limit (2^-30 of a step: next to a contact, or a graze within V 1e-14) holds no sample at or
 * below the target and is passed over: the scan's contact time is then an upper bound of the
 * first contact, which is all the check needs (the impact must not come later). */
static int refine(cdist_query *q, const motion_case *m, double V, double t0, double d0, double t1, double d1, int depth,
                  double *hit)
{
    if (d0 <= m->target) {
        *hit = t0;
        return 1;
    }
    if (0.5 * (d0 + d1 - V * (t1 - t0)) > m->target || depth >= 30) return 0;
    if (--scan_budget < 0) return -1;
    double tm = 0.5 * (t0 + t1), dm = dist_at(q, m, tm);
    int r = refine(q, m, V, t0, d0, tm, dm, depth + 1, hit);
    if (r) return r;
    return refine(q, m, V, tm, dm, t1, d1, depth + 1, hit);
}

/* The scan's first contact time (1: *t_hit, 0: none in [0, 1]; -1: a distance failed or the
 * budget ran out). */
static int scan(cdist_query *q, const motion_case *m, int steps, double *t_hit)
{
    double V = speed_bound(m) * (1 + 1e-9) + 1e-12;
    double prev = dist_at(q, m, 0.0);
    scan_budget = SCAN_BUDGET;
    for (int i = 0; i < steps; i++) {
        double t0 = (double)i / steps, t1 = (double)(i + 1) / steps;
        double d1 = dist_at(q, m, t1);
        if (isnan(d1) || isnan(prev)) return -1;
        int r = refine(q, m, V, t0, prev, t1, d1, 0, t_hit);
        if (r) return r;
        prev = d1;
    }
    if (prev <= m->target) {
        *t_hit = 1.0;
        return 1;
    }
    return 0;
}

static cdist_shape random_shape(cdist_vec3 at)
{
    cdist_shape s;
    memset(&s, 0, sizeof s);
    s.type = (int)(urand() * 4);
    double swept = urand() < 0.2 ? 0.0 : 0.02 + 0.2 * urand();
    double size = 0.2 + 0.8 * urand();
    switch (s.type) {
    case CDIST_SHAPE_SPHERE: s.u.sphere.center = at; s.u.sphere.radius = swept + 0.2 * urand(); break;
    case CDIST_SHAPE_CAPSULE: {
        cdist_vec3 d = rand_unit();
        s.u.capsule.segment.p0 = add(at, -size, d);
        s.u.capsule.segment.p1 = add(at, size, d);
        s.u.capsule.radius = swept;
        break;
    }
    case CDIST_SHAPE_TORUS: s.u.torus.circle = (cdist_circle){at, rand_unit(), size}; s.u.torus.tube_radius = swept; break;
    default: s.u.rounded_disk.disk = (cdist_circle){at, rand_unit(), size}; s.u.rounded_disk.radius = swept; break;
    }
    return s;
}

static motion_case random_motion(void)
{
    motion_case m;
    memset(&m, 0, sizeof m);
    cdist_vec3 ca = tv(0.2 * srand1(), 0.2 * srand1(), 0.2 * srand1());
    cdist_vec3 dir = rand_unit();
    cdist_vec3 cb = add(ca, 2.0 + 1.5 * urand(), dir);
    m.a = random_shape(ca);
    m.b = random_shape(cb);
    m.ma.center = add(ca, 0.3 * urand(), rand_unit());
    m.mb.center = add(cb, 0.3 * urand(), rand_unit());
    m.ma.translation = add(tv(0, 0, 0), 0.5 * urand(), rand_unit());
    /* b heads towards a, with a miss distance up to 1.2 (about half hit). */
    m.mb.translation = add(add(tv(0, 0, 0), -(3.0 + 2.0 * urand()), dir), 1.2 * urand(), rand_unit());
    m.ma.rotation = add(tv(0, 0, 0), 4.0 * M_PI * urand() * (urand() < 0.3 ? 0 : 1), rand_unit());
    m.mb.rotation = add(tv(0, 0, 0), 4.0 * M_PI * urand(), rand_unit());
    m.target = urand() < 0.5 ? 0.0 : 0.05;
    return m;
}

static void check_random(cdist_query *q, int n, int steps)
{
    int hits = 0, none = 0, limit = 0, undecided = 0, late = 0, far = 0, missed = 0;
    long queries = 0;
    double worst_gap = 0.0;
    for (int i = 0; i < n; i++) {
        motion_case m = random_motion();
        cdist_toi_result r;
        cdist_status st = cdist_toi(q, &m.a, &m.ma, &m.b, &m.mb, m.target, TARGET_TOL, 100000, &r);
        if (st != CDIST_OK) {
            CHECK(0, "motion %d: status %d (%s)", i, (int)st, cdist_query_last_error(q));
            continue;
        }
        queries += r.iterations;
        double t_ref = NAN;
        int ref = scan(q, &m, steps, &t_ref);
        if (ref < 0) {
            undecided++;
            continue;
        }
        if (r.state == CDIST_TOI_ITERATION_LIMIT) {
            limit++;
            if (ref == 1 && t_ref < r.t) late++;
            continue;
        }
        if (r.state == CDIST_TOI_HIT) {
            hits++;
            if (ref == 1 && r.t > t_ref) {
                late++;
                fprintf(stderr, "motion %d: impact at %.17g after the scan's first contact %.17g\n", i, r.t, t_ref);
            }
            double d = dist_at(q, &m, r.t);
            if (!(d <= m.target + TARGET_TOL + 1e-12)) {
                far++;
                fprintf(stderr, "motion %d: distance %.17g at the impact time, target %g\n", i, d, m.target);
            }
            if (ref == 1 && t_ref - r.t > worst_gap) worst_gap = t_ref - r.t;
        } else {
            none++;
            if (ref == 1) {
                missed++;
                fprintf(stderr, "motion %d: no impact reported, the scan touches at %.17g\n", i, t_ref);
            }
        }
    }
    printf("toi: %d motions (%d steps each): %d hits, %d none, %d at the iteration limit, %d skipped (scan "
           "budget); mean distance queries per call %.1f; largest (scan contact - impact time) %.3g\n",
           n, steps, hits, none, limit, undecided, n ? (double)queries / n : 0.0, worst_gap);
    CHECK(late == 0, "%d impacts later than the first contact (tunnelling)", late);
    CHECK(far == 0, "%d impacts farther than the tolerance from the target", far);
    CHECK(missed == 0, "%d contacts missed", missed);
    CHECK(undecided <= n / 100, "%d motions the scan could not decide", undecided);
    CHECK(hits > n / 5 && none > n / 5, "unbalanced sample: %d hits, %d none", hits, none);
}

static cdist_shape torus_shape(cdist_vec3 c, cdist_vec3 n, double R, double tube)
{
    cdist_shape s;
    memset(&s, 0, sizeof s);
    s.type = CDIST_SHAPE_TORUS;
    s.u.torus.circle = (cdist_circle){c, n, R};
    s.u.torus.tube_radius = tube;
    return s;
}

static void check_threading(cdist_query *q)
{
    cdist_shape a = torus_shape(tv(0, 0, 0), tv(0, 0, 1), 2.0, 0.2);
    /* A small ring along a's axis through the hole, turning twice about a diameter: no hit
     * (its points stay within 0.6 of the axis, a's tube starts at 1.8). */
    motion_case m;
    memset(&m, 0, sizeof m);
    m.a = a;
    m.b = torus_shape(tv(0, 0, -3), tv(0, 0, 1), 0.5, 0.1);
    m.mb.center = tv(0, 0, -3);
    m.mb.translation = tv(0, 0, 6);
    m.mb.rotation = tv(4 * M_PI, 0, 0);
    cdist_toi_result r;
    CHECK(cdist_toi(q, &m.a, NULL, &m.b, &m.mb, 0.0, 1e-9, 100000, &r) == CDIST_OK && r.state == CDIST_TOI_NONE,
          "threading ring: state %d at t %g", r.state, r.t);
    double t_ref;
    CHECK(scan(q, &m, 10000, &t_ref) == 0, "threading: the scan finds no contact");
    /* The same 1.45 off the axis: its rim reaches 1.45 + 0.6 > 1.8, it clips a's tube. */
    m.b.u.torus.circle.center = tv(1.45, 0, -3);
    m.mb.center = tv(1.45, 0, -3);
    CHECK(cdist_toi(q, &m.a, NULL, &m.b, &m.mb, 0.0, 1e-9, 100000, &r) == CDIST_OK && r.state == CDIST_TOI_HIT,
          "rim clip: state %d", r.state);
    CHECK(scan(q, &m, 10000, &t_ref) == 1 && r.t <= t_ref && fabs(r.distance) <= 1e-9,
          "rim clip: impact %.17g, scan %.17g, distance %g", r.t, t_ref, r.distance);
    printf("threading: ring through the hole: none; rim clip at t = %.12f (scan %.12f), %d queries\n", r.t, t_ref,
           r.iterations);
    /* Linked rings: b (centre on a's core circle, normal along a's tangent) turns a full turn
     * about a's core tangent through its centre while sliding along it slightly: the wire of a
     * stays inside b's hole, no hit at target 0. */
    cdist_shape a1 = torus_shape(tv(0, 0, 0), tv(0, 0, 1), 1.0, 0.1);
    motion_case k;
    memset(&k, 0, sizeof k);
    k.a = a1;
    k.b = torus_shape(tv(1, 0, 0), tv(0, 1, 0), 0.6, 0.1);
    k.mb.center = tv(1, 0, 0);
    k.mb.rotation = tv(0, 2 * M_PI, 0);
    k.mb.translation = tv(0, 0.2, 0);
    CHECK(cdist_toi(q, &k.a, NULL, &k.b, &k.mb, 0.0, 1e-9, 100000, &r) == CDIST_OK && r.state == CDIST_TOI_NONE,
          "linked rings turning: state %d at %g", r.state, r.t);
    CHECK(scan(q, &k, 10000, &t_ref) == 0, "linked rings: the scan finds no contact");
    /* A fast thin ring (tube 0) spinning 20 turns while it passes a thin rod (radius 0), target
     * separation 1e-3 (two curves meet only at isolated instants, which a scan cannot sample):
     * never later than the scan. */
    cdist_shape rod;
    memset(&rod, 0, sizeof rod);
    rod.type = CDIST_SHAPE_CAPSULE;
    rod.u.capsule.segment = (cdist_segment){tv(0, 0, -1), tv(0, 0, 1)};
    motion_case f;
    memset(&f, 0, sizeof f);
    f.a = rod;
    f.b = torus_shape(tv(-3, 0.3, 0), tv(0, 0, 1), 0.5, 0.0);
    f.mb.center = tv(-3, 0.3, 0);
    f.mb.translation = tv(6, 0, 0);
    f.mb.rotation = tv(40 * M_PI, 0, 0);
    f.target = 1e-3;
    CHECK(cdist_toi(q, &f.a, NULL, &f.b, &f.mb, f.target, 1e-9, 1000000, &r) == CDIST_OK, "spinning ring");
    int ref = scan(q, &f, 10000, &t_ref);
    CHECK(ref >= 0 && (ref == 0 ? r.state == CDIST_TOI_NONE : (r.state == CDIST_TOI_HIT && r.t <= t_ref)),
          "spinning ring: state %d t %.17g, scan %d %.17g", r.state, r.t, ref, t_ref);
    printf("spinning ring past a rod: state %d at t = %.12f (scan %d, %.12f), %d queries\n", r.state, r.t, ref, t_ref,
           r.iterations);
}

static void check_pose_and_errors(cdist_query *q)
{
    /* A quarter turn about z through (1, 0, 0) plus a shift: (2, 0, 0) -> (1, 1, 0) + (0, 0, 1). */
    cdist_shape s;
    memset(&s, 0, sizeof s);
    s.type = CDIST_SHAPE_SPHERE;
    s.u.sphere.center = tv(2, 0, 0);
    cdist_motion m = {tv(1, 0, 0), tv(0, 0, 2), tv(0, 0, M_PI)};
    cdist_shape out;
    CHECK(cdist_shape_at(&s, &m, 0.5, &out) == CDIST_OK && tdist(out.u.sphere.center, tv(1, 1, 1)) < 1e-15,
          "pose: %g %g %g", out.u.sphere.center.x, out.u.sphere.center.y, out.u.sphere.center.z);
    cdist_shape tor = torus_shape(tv(0, 0, 0), tv(1, 0, 0), 1, 0);
    cdist_motion mr = {tv(0, 0, 0), tv(0, 0, 0), tv(0, 0, M_PI / 2)};
    CHECK(cdist_shape_at(&tor, &mr, 1.0, &out) == CDIST_OK && tdist(out.u.torus.circle.normal, tv(0, 1, 0)) < 1e-15,
          "normal turns");
    CHECK(cdist_shape_size() == sizeof(cdist_shape) && cdist_toi_result_size() == sizeof(cdist_toi_result), "sizes");

    cdist_toi_result r;
    CHECK(cdist_toi(q, &s, NULL, &tor, NULL, 0, 0, 10, &r) == CDIST_ERR_BAD_OPTION && isnan(r.t), "zero tolerance");
    CHECK(cdist_toi(q, &s, NULL, &tor, NULL, NAN, 1e-9, 10, &r) == CDIST_ERR_NOT_FINITE, "NaN target");
    CHECK(cdist_toi(q, &s, NULL, &tor, NULL, 0, 1e-9, 0, &r) == CDIST_ERR_BAD_OPTION, "zero cap");
    CHECK(cdist_toi(q, NULL, NULL, &tor, NULL, 0, 1e-9, 10, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL shape");
    cdist_motion bad = {tv(NAN, 0, 0), tv(0, 0, 0), tv(0, 0, 0)};
    CHECK(cdist_toi(q, &s, &bad, &tor, NULL, 0, 1e-9, 10, &r) == CDIST_ERR_NOT_FINITE, "NaN motion");
    cdist_shape badt = tor;
    badt.u.torus.circle.normal = tv(0, 0, 0);
    CHECK(cdist_toi(q, &s, NULL, &badt, NULL, 0, 1e-9, 10, &r) == CDIST_ERR_ZERO_VECTOR, "bad torus");
    badt.type = 9;
    CHECK(cdist_toi(q, &s, NULL, &badt, NULL, 0, 1e-9, 10, &r) == CDIST_ERR_BAD_OPTION, "bad type");
    /* Still objects apart: none after one query; already touching: hit at 0. */
    CHECK(cdist_toi(q, &s, NULL, &tor, NULL, 0, 1e-9, 10, &r) == CDIST_OK && r.state == CDIST_TOI_NONE &&
              r.iterations == 1,
          "still");
    s.u.sphere.center = tv(0, 1, 0);
    CHECK(cdist_toi(q, &s, NULL, &tor, NULL, 0, 1e-9, 10, &r) == CDIST_OK && r.state == CDIST_TOI_HIT && r.t == 0,
          "touching at 0");
    /* Iteration cap: a slow grazing approach with a cap of 3. */
    cdist_shape sp = s;
    sp.u.sphere.center = tv(0, 5, 0);
    cdist_motion slow = {tv(0, 5, 0), tv(0, -4, 0), tv(0, 0, 0)};
    cdist_motion spin = {tv(0, 0, 0), tv(0, 0, 0), tv(40, 0, 0)}; /* the ring turns in its plane */
    CHECK(cdist_toi(q, &sp, &slow, &tor, &spin, 0, 1e-12, 3, &r) == CDIST_OK &&
              r.state == CDIST_TOI_ITERATION_LIMIT && r.iterations == 3 && r.t > 0,
          "cap: state %d it %d", r.state, r.iterations);

    /* Batch: broadcast a, two b's, one bad. */
    cdist_shape bs[2] = {tor, badt};
    cdist_motion mb = {tv(0, 5, 0), tv(0, -5, 0), tv(0, 0, 0)};
    cdist_toi_result out2[2];
    cdist_status st2[2];
    CHECK(cdist_toi_batch(q, 2, &sp, 0, &mb, 0, bs, sizeof(cdist_shape), NULL, 0, 0.0, 1e-9, 1000, out2, st2) ==
                  CDIST_ERR_BAD_OPTION &&
              st2[0] == CDIST_OK && out2[0].state == CDIST_TOI_HIT && st2[1] == CDIST_ERR_BAD_OPTION,
          "batch");
    CHECK(strstr(cdist_query_last_error(q), "entry 1") != NULL, "batch message: %s", cdist_query_last_error(q));
    CHECK(fabs(out2[0].t - 0.8) < 1e-6, "batch impact time %g (a point meets the ring at y = 1)", out2[0].t);
}

/* Large swept radii: the signed distance core - 2R rounds at R's scale, above a slack taken from
 * the motion's coordinates alone. Sphere b (radius R) comes at a (radius R) along x; target
 * 1 - 2R is reached when the centres are 1 apart, at the exact time t* = (1 - x0) / T (long
 * double). A hit must come at or before t*. */
static void check_large_radii(cdist_query *q)
{
    int n = 0, late = 0;
    double worst = 0.0;
    for (int k = 0; k < 600; k++) {
        double R = pow(10.0, 1 + k % 7), x0 = 3 + 0.001 * k, T = -2.5 - 0.0007 * k;
        cdist_shape a, b;
        memset(&a, 0, sizeof a);
        a.type = CDIST_SHAPE_SPHERE;
        a.u.sphere.radius = R;
        b = a;
        b.u.sphere.center = tv(x0, 0, 0);
        cdist_motion m = {tv(x0, 0, 0), tv(T, 0, 0), tv(0, 0, 0)};
        cdist_toi_result r;
        CHECK(cdist_toi(q, &a, NULL, &b, &m, 1 - 2 * R, 1e-15, 100000, &r) == CDIST_OK, "large radii %d", k);
        long double t_exact = (1.0L - x0) / (long double)T;
        if (r.state != CDIST_TOI_HIT) continue;
        n++;
        if (r.t > t_exact) {
            late++;
            worst = fmax(worst, (double)(r.t - t_exact));
        }
    }
    CHECK(n > 100, "large radii: %d hits", n);
    CHECK(late == 0, "large radii: %d of %d impacts after the exact contact time (by up to %.3g)", late, n, worst);
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 200;
    int steps = argc > 2 ? atoi(argv[2]) : 10000;
    cdist_query *q = cdist_query_new();
    check_pose_and_errors(q);
    check_threading(q);
    check_large_radii(q);
    check_random(q, n, steps);
    cdist_query_free(q);
    return check_summary("toi");
}
