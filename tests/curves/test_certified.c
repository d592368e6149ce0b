/* SPDX-License-Identifier: MIT */
/* The certified curve search: helices (tiny pitch, many turns, far translations, targets
 * centred on the curve so that narrow basins recur turn after turn), Bezier curves and arcs
 * against the long double dense scan with local refinement of brute.h, at a spread of
 * curve_samples settings from the minimum (8) up. A miss is an answer above the reference by
 * more than 1e-12 of the scale. Also the reported cases: a helix-circle basin two turns from
 * the sampled one (missed at 512 samples), and a 4000-turn coaxial coil whose turns are all
 * within rounding of the answer (scanned turn by turn: COST_LIMIT at 2^18 samples).
 * --short: a tenth of the random cases and no 4096-sample setting (the default suite). */
#include <stdlib.h>
#include <string.h>

#include "brute.h"

static cdist_query *q;
static double worst;
static long n_queries, n_ref_weaker;

static const int settings_full[] = {8, 9, 13, 64, 512, 4096};
static const int settings_short[] = {8, 13, 64, 512};
static const int *settings;
static int n_settings;

/* One query: a helix, Bezier curve or arc against circle or disk c. */
enum { HELIX, BEZIER, ARC };
typedef struct curve_case {
    int kind, disk;
    cdist_helix h;
    cdist_bezier3 b;
    cdist_arc a;
    cdist_circle c;
} curve_case;

static cdist_status run(const curve_case *x, cdist_result *r)
{
    switch (x->kind) {
    case HELIX: return (x->disk ? cdist_helix_disk : cdist_helix_circle)(q, &x->h, &x->c, r);
    case BEZIER: return (x->disk ? cdist_bezier3_disk : cdist_bezier3_circle)(q, &x->b, &x->c, r);
    default: return (x->disk ? cdist_arc_disk : cdist_arc_circle)(q, &x->a, &x->c, r);
    }
}

/* The library's answer at every setting against ref (long double), scale L. */
static void judge(const char *what, long id, const curve_case *obj, ld ref, double L)
{
    for (int k = 0; k < n_settings; k++) {
        CHECK(cdist_query_set_curve_samples(q, settings[k]) == CDIST_OK, "set samples %d", settings[k]);
        cdist_result r;
        cdist_status st = run(obj, &r);
        n_queries++;
        CHECK(st == CDIST_OK, "%s %ld at %d samples: %s", what, id, settings[k], cdist_query_last_error(q));
        if (st) continue;
        double over = (double)(((ld)r.distance - ref) / L);
        if (over > worst) worst = over;
        if (over < -1e-12) n_ref_weaker++;
        CHECK(over <= 1e-12, "%s %ld at %d samples: %.17g above the reference %.20Lg by %.3g of scale", what, id,
              settings[k], r.distance, ref, over);
    }
    cdist_query_set_curve_samples(q, 512);
}


static cdist_vec3 helix_point(const cdist_helix *h, double t)
{
    bf_helix b = bf_helix_of(h, &(cdist_circle){tv(0, 0, 0), tv(0, 0, 1), 1}, 0);
    lv p = lv_add(b.c, lv_add(lv_scale(b.r * cosl(t), b.u),
                              lv_add(lv_scale(b.r * sinl(t), b.v), lv_scale(b.rise * t, b.n))));
    return tv((double)p.x, (double)p.y, (double)p.z);
}

static void helix_check(long id, const curve_case *x)
{
    bf_helix b = bf_helix_of(&x->h, &x->c, x->disk);
    double turns = (x->h.t1 - x->h.t0) / (2 * M_PI);
    int ns = (int)(2048 * (1 + turns));
    ld ref = bf_min1d(bf_f_helix, &b, x->h.t0, x->h.t1, ns);
    double ext = fabs(x->h.pitch) * fmax(fabs(x->h.t0), fabs(x->h.t1)) / (2 * M_PI);
    double L = fmax(fmax(fmax(x->h.radius, x->c.radius), tdist(x->h.center, x->c.center) + ext), (double)ref);
    judge(x->disk ? "helix-disk" : "helix-circle", id, x, ref, L);
}

static void random_helices(int count)
{
    for (long id = 0; id < count; id++) {
        curve_case x = {.kind = HELIX};
        int turns = 1 + (int)(12 * urand());
        double pitch = pow(10.0, -9 + 8.5 * urand()) * (id % 3 == 0 ? -1 : 1);
        cdist_vec3 far = id % 4 == 0 ? tv(1e3 * srand1(), 1e3 * srand1(), 1e3 * srand1()) : tv(0, 0, 0);
        x.h = (cdist_helix){far, rand_unit(), rand_unit(), 0.2 + urand(), pitch, -3 * urand(), 0};
        x.h.t1 = x.h.t0 + 2 * M_PI * turns * (0.8 + 0.2 * urand());
        x.disk = (int)(id % 2);
        double tc = x.h.t0 + (x.h.t1 - x.h.t0) * urand();
        switch (id % 4) {
        case 0: /* a small circle centred near a helix point: a narrow basin on every turn */
        case 1: {
            cdist_vec3 p = helix_point(&x.h, tc), o = rand_unit();
            double off = 0.05 * urand() * x.h.radius;
            x.c = (cdist_circle){tv(p.x + off * o.x, p.y + off * o.y, p.z + off * o.z), rand_unit(),
                                 x.h.radius * (0.01 + 0.2 * urand())};
            break;
        }
        case 2: { /* near the axis, tilted */
            double z = x.h.pitch * tc / (2 * M_PI);
            cdist_vec3 n = x.h.axis;
            x.c = (cdist_circle){tv(far.x + z * n.x + 0.3 * srand1(), far.y + z * n.y + 0.3 * srand1(),
                                    far.z + z * n.z + 0.3 * srand1()),
                                 rand_unit(), x.h.radius * (0.3 + 1.5 * urand())};
            break;
        }
        default: /* to the side */
            x.c = (cdist_circle){tv(far.x + 2 * srand1(), far.y + 2 * srand1(), far.z + 2 * srand1()), rand_unit(),
                                 urand()};
        }
        helix_check(id, &x);
    }
}


static void random_beziers(int count)
{
    for (long id = 0; id < count; id++) {
        curve_case x = {.kind = BEZIER};
        cdist_vec3 far = id % 4 == 0 ? tv(1e3 * srand1(), 1e3 * srand1(), 1e3 * srand1()) : tv(0, 0, 0);
        for (int i = 0; i < 4; i++) x.b.p[i] = tv(far.x + 2 * srand1(), far.y + 2 * srand1(), far.z + 2 * srand1());
        x.disk = (int)(id % 2);
        bf_bez b;
        for (int i = 0; i < 4; i++) b.p[i] = lv_of(x.b.p[i]);
        if (id % 3 == 0) { /* a small circle centred near a curve point */
            lv p = bf_bez_point(&b, urand());
            cdist_vec3 o = tv((double)p.x + 0.02 * srand1(), (double)p.y + 0.02 * srand1(), (double)p.z + 0.02 * srand1());
            x.c = (cdist_circle){o, rand_unit(), 0.01 + 0.3 * urand()};
        } else if (id % 3 == 1 && x.disk) { /* lying flat over the disk: constant distance */
            for (int i = 0; i < 4; i++) x.b.p[i].z = far.z + 0.25;
            for (int i = 0; i < 4; i++) b.p[i] = lv_of(x.b.p[i]);
            x.c = (cdist_circle){tv(far.x, far.y, far.z), tv(0, 0, 1), 1 + 3 * urand()};
        } else {
            x.c = (cdist_circle){tv(far.x + srand1(), far.y + srand1(), far.z + srand1()), rand_unit(),
                                 0.1 + 1.5 * urand()};
        }
        b.k = bf_circ(x.c);
        b.disk = x.disk;
        ld ref = bf_min1d(bf_f_bez, &b, 0, 1, 16384);
        double L = fmax(x.c.radius, (double)ref);
        for (int i = 0; i < 4; i++) L = fmax(L, tdist(x.b.p[i], x.c.center));
        judge(x.disk ? "bezier-disk" : "bezier-circle", id, &x, ref, L);
    }
}


typedef struct bf_arc_t {
    bf_arc a;
    bf_circle k;
    int disk;
} bf_arc_t;

static ld f_arc(const void *p, ld t)
{
    const bf_arc_t *x = p;
    lv pt = bf_arc_point(&x->a, t);
    return x->disk ? bf_point_disk(pt, &x->k) : bf_point_circle(pt, &x->k);
}

static void random_arcs(int count)
{
    for (long id = 0; id < count; id++) {
        curve_case x = {.kind = ARC};
        cdist_vec3 far = id % 4 == 0 ? tv(1e3 * srand1(), 1e3 * srand1(), 1e3 * srand1()) : tv(0, 0, 0);
        double s0 = 4 * srand1();
        x.a = (cdist_arc){{far, rand_unit(), 0.2 + urand()}, rand_unit(), s0, s0 + 2 * M_PI * urand()};
        x.disk = (int)(id % 2);
        if (id % 3 == 0) /* parallel to the disk or coaxial with the circle: the sampled fallback */
            x.c = (cdist_circle){tv(far.x + 0.5 * srand1() * x.disk, far.y, far.z), x.a.circle.normal, 0.1 + urand()};
        else
            x.c = (cdist_circle){tv(far.x + srand1(), far.y + srand1(), far.z + srand1()), rand_unit(), 0.1 + urand()};
        if (id % 3 == 0) {
            cdist_vec3 n = x.a.circle.normal;
            double z = 0.3 * srand1();
            x.c.center = tv(x.c.center.x + z * n.x, x.c.center.y + z * n.y, x.c.center.z + z * n.z);
        }
        bf_arc_t b = {bf_arc_of(&x.a), bf_circ(x.c), x.disk};
        ld ref = bf_min1d(f_arc, &b, x.a.start, x.a.end, 8192);
        double L = fmax(fmax(x.a.circle.radius, x.c.radius), fmax(tdist(x.a.circle.center, x.c.center), (double)ref));
        judge(x.disk ? "arc-disk" : "arc-circle", id, &x, ref, L);
    }
}

static void reported_cases(void)
{
    /* The basin at t = 37.704 (distance 0.060175777123367480, closed to the digits by the
     * long double scan below) was stepped over at 512 samples: 0.060181571180885587 at
     * t = 31.421 came back with status OK. */
    curve_case x = {.kind = HELIX,
                    .h = {tv(0, 0, 0), tv(0.12713528112406569, 0.72235514668474465, 0.67973499420845329),
                          tv(0.88764416518506173, 0.22295885816590461, -0.4029605235978716), 1,
                          8.1110380473151297e-06, -2.6739032527197715, 38.002800815063324},
                    .c = {tv(0.88764416518461076, 0.22295885816674854, -0.40296052359735768),
                          tv(-0.39536083285874024, 0.62633915544033258, -0.67185495027091557), 0.060415434432673422}};
    helix_check(-1, &x);
    /* 4000 turns of pitch 1e-9 around a coaxial circle: every turn is within rounding of the
     * answer 0.5 (closed form: the helix radius 1 minus the circle's 0.5 at height 0). Turns
     * scanned until the bound of the rest exceeded best * (1 + 1e-9): all of them, refused at
     * 2^18 samples (more than 8 turns); the certified skip needs one. */
    cdist_helix h = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1, 1e-9, 0, 25000};
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 1), 0.5};
    cdist_result r;
    CHECK(cdist_query_set_curve_samples(q, 1 << 18) == CDIST_OK, "set samples");
    cdist_status st = cdist_helix_circle(q, &h, &c, &r);
    CHECK(st == CDIST_OK && fabs(r.distance - 0.5) <= 1e-15, "coaxial 4000 turns at 2^18 samples: %s, %.17g",
          cdist_status_name(st), r.distance);
    cdist_query_set_curve_samples(q, 512);
}

int main(int argc, char **argv)
{
    int full = !(argc > 1 && strcmp(argv[1], "--short") == 0);
    settings = full ? settings_full : settings_short;
    n_settings = full ? (int)(sizeof settings_full / sizeof settings_full[0])
                      : (int)(sizeof settings_short / sizeof settings_short[0]);
    q = cdist_query_new();
    reported_cases();
    int k = full ? 10 : 1;
    random_helices(150 * k);
    random_beziers(150 * k);
    random_arcs(60 * k);
    printf("certified curves: %ld queries, largest excess over the reference %.3g of scale, %ld where the reference "
           "was weaker\n",
           n_queries, worst, n_ref_weaker);
    cdist_query_free(q);
    return check_summary("certified-curves");
}
