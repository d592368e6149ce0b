// SPDX-License-Identifier: MIT
// Our scene against Bullet's btDbvt on the same sphere and capsule scenes (10^4 and 10^5
// objects), same run: all pairs within delta (leaf boxes inflated by delta / 2, collideTT of the
// tree with itself, Bullet's GJK distance on each candidate pair). Bullet has no closest-pair
// query. Debian's Bullet is single precision (btScalar = float), so its pair count may differ
// from ours at the boundary.
#include <btBulletCollisionCommon.h>
#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "peer_scene.h"

namespace {

struct Within : btDbvt::ICollide {
    std::vector<std::unique_ptr<btConvexShape>> *shape;
    std::vector<btTransform> *pose;
    double delta = 0.0;
    size_t pairs = 0;
    void Process(const btDbvtNode *a, const btDbvtNode *b) override
    {
        size_t i = reinterpret_cast<size_t>(a->data), j = reinterpret_cast<size_t>(b->data);
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver epa;
        btGjkPairDetector gjk((*shape)[i].get(), (*shape)[j].get(), &simplex, &epa);
        btGjkPairDetector::ClosestPointInput in;
        in.m_transformA = (*pose)[i];
        in.m_transformB = (*pose)[j];
        btPointCollector out;
        gjk.getClosestPoints(in, out, nullptr);
        if (out.m_hasResult && out.m_distance <= delta) pairs++;
    }
};

}  // namespace

int main(int argc, char **argv)
{
    const double delta = 1.5;
    int reps = argc > 1 ? atoi(argv[1]) : 1;
    for (size_t n : {size_t(10000), size_t(100000)}) {
        for (int capsules = 0; capsules < 2; capsules++) {
            std::vector<peer_obj> o(n);
            peer_generate(o.data(), n, capsules);
            double tw = INFINITY, tc, bw = INFINITY, best;
            size_t pairs = 0, bpairs = 0;
            for (int r = 0; r < reps; r++) {
                double a;
                peer_ours(o.data(), n, delta, &a, &pairs, &tc, &best);
                tw = fmin(tw, a);
                double t0 = peer_now();
                std::vector<std::unique_ptr<btConvexShape>> shape;
                std::vector<btTransform> pose;
                btDbvt tree;
                for (size_t k = 0; k < n; k++) {
                    btVector3 p0(o[k].p0.x, o[k].p0.y, o[k].p0.z), p1(o[k].p1.x, o[k].p1.y, o[k].p1.z);
                    btTransform t;
                    t.setIdentity();
                    t.setOrigin(0.5 * (p0 + p1));
                    if (o[k].capsule) {
                        btVector3 d = p1 - p0;
                        shape.emplace_back(new btCapsuleShapeZ(o[k].r, d.length()));
                        t.setRotation(shortestArcQuat(btVector3(0, 0, 1), d.normalized()));
                    } else {
                        shape.emplace_back(new btSphereShape(o[k].r));
                    }
                    pose.push_back(t);
                    btVector3 lo, hi;
                    shape.back()->getAabb(t, lo, hi);
                    btVector3 g(0.5 * delta, 0.5 * delta, 0.5 * delta);
                    tree.insert(btDbvtVolume::FromMM(lo - g, hi + g), reinterpret_cast<void *>(k));
                }
                // no optimisation pass: inserts only (optimizeTopDown took longer than it saved)
                Within w;
                w.shape = &shape;
                w.pose = &pose;
                w.delta = delta;
                tree.collideTT(tree.m_root, tree.m_root, w);
                bw = fmin(bw, peer_now() - t0);
                bpairs = w.pairs;
            }
            printf("%-8s n=%-6zu within %.1f: ours %.4f s (%zu pairs)  Bullet btDbvt %.4f s (%zu pairs)  %.1fx\n",
                   capsules ? "capsules" : "spheres", n, delta, tw, pairs, bw, bpairs, bw / tw);
        }
    }
    return 0;
}
