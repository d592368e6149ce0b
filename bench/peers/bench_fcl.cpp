// SPDX-License-Identifier: MIT
// Our scene against FCL 0.7's DynamicAABBTreeCollisionManager on the same sphere and capsule
// scenes (10^4 and 10^5 objects), same run: all pairs within delta (FCL has no such query: its
// broad phase over objects inflated by delta / 2, then fcl::distance on each candidate pair, as
// FCL users are told to do) and the closest pair (the manager's self distance query).
#include <fcl/fcl.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "peer_scene.h"

using fcl::CollisionObjectd;

namespace {

struct Ctx {
    std::vector<CollisionObjectd *> exact;
    double delta = 0.0;
    size_t pairs = 0;
    double best = INFINITY;
};

std::shared_ptr<fcl::CollisionGeometryd> geometry(const peer_obj &o, double grow)
{
    if (!o.capsule) return std::make_shared<fcl::Sphered>(o.r + grow);
    Eigen::Vector3d a(o.p0.x, o.p0.y, o.p0.z), b(o.p1.x, o.p1.y, o.p1.z);
    return std::make_shared<fcl::Capsuled>(o.r + grow, (b - a).norm());
}

fcl::Transform3d pose(const peer_obj &o)
{
    Eigen::Vector3d a(o.p0.x, o.p0.y, o.p0.z), b(o.p1.x, o.p1.y, o.p1.z);
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.translation() = 0.5 * (a + b);
    if (o.capsule) t.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), b - a).toRotationMatrix();
    return t;
}

bool within_cb(CollisionObjectd *a, CollisionObjectd *b, void *data)
{
    Ctx *c = static_cast<Ctx *>(data);
    size_t i = reinterpret_cast<size_t>(a->getUserData()), j = reinterpret_cast<size_t>(b->getUserData());
    fcl::DistanceRequestd req;
    fcl::DistanceResultd res;
    double d = fcl::distance(c->exact[i], c->exact[j], req, res);
    if (d <= c->delta) c->pairs++;
    return false;
}

bool distance_cb(CollisionObjectd *a, CollisionObjectd *b, void *data, double &dist)
{
    Ctx *c = static_cast<Ctx *>(data);
    fcl::DistanceRequestd req;
    fcl::DistanceResultd res;
    double d = fcl::distance(a, b, req, res);
    if (d < c->best) c->best = d;
    dist = c->best;
    return c->best <= 0.0;
}

std::vector<CollisionObjectd *> objects(const std::vector<peer_obj> &o, double grow)
{
    std::vector<CollisionObjectd *> v;
    for (size_t k = 0; k < o.size(); k++) {
        auto *x = new CollisionObjectd(geometry(o[k], grow), pose(o[k]));
        x->setUserData(reinterpret_cast<void *>(k));
        v.push_back(x);
    }
    return v;
}

}  // namespace

int main(int argc, char **argv)
{
    const double delta = 1.5;
    int reps = argc > 1 ? atoi(argv[1]) : 1;
    for (size_t n : {size_t(10000), size_t(100000)}) {
        for (int capsules = 0; capsules < 2; capsules++) {
            std::vector<peer_obj> o(n);
            peer_generate(o.data(), n, capsules);
            double tw = INFINITY, tc = INFINITY, fw = INFINITY, fc = INFINITY, best = NAN, fbest = NAN;
            size_t pairs = 0, fpairs = 0;
            for (int r = 0; r < reps; r++) {
                double a, b;
                peer_ours(o.data(), n, delta, &a, &pairs, &b, &best);
                tw = fmin(tw, a), tc = fmin(tc, b);
                Ctx c;
                c.delta = delta;
                double t0 = peer_now();
                c.exact = objects(o, 0.0);
                std::vector<CollisionObjectd *> fat = objects(o, 0.5 * delta);
                fcl::DynamicAABBTreeCollisionManagerd m;
                m.registerObjects(fat);
                m.setup();
                m.collide(&c, within_cb);
                fw = fmin(fw, peer_now() - t0);
                fpairs = c.pairs;
                for (auto *x : fat) delete x;
                t0 = peer_now();
                fcl::DynamicAABBTreeCollisionManagerd m2;
                m2.registerObjects(c.exact);
                m2.setup();
                m2.distance(&c, distance_cb);
                fc = fmin(fc, peer_now() - t0 + 0.0);
                fbest = c.best;
                for (auto *x : c.exact) delete x;
            }
            printf("%-8s n=%-6zu within %.1f: ours %.4f s (%zu pairs)  FCL %.4f s (%zu pairs)  %.1fx | "
                   "closest: ours %.4f s (%.6f)  FCL %.4f s (%.6f)  %.1fx\n",
                   capsules ? "capsules" : "spheres", n, delta, tw, pairs, fw, fpairs, fw / tw, tc, best, fc, fbest,
                   fc / tc);
        }
    }
    return 0;
}
