#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Reference distances of the tilted "far tiny" lines and rays of tests/lines/test_lines.c (far_tiny):
# independent of the library. Input lines "lc|rc O(3) D(3) C(3) N(3) r" (the doubles as written);
# prints the minimum over the circle angle of the point-line (point-ray) distance: 2000 samples,
# golden-section refinement of the 6 best, 60 digits, in coordinates relative to the centre
# (taken exactly at 800 digits). The inputs: `far_tiny_ref.py --gen` (random.seed(7); x = 1e10, the
# rest at scale 1e-300; the test takes lines 1, 3, 7, 8). Usage: far_tiny_ref.py --gen | far_tiny_ref.py
import sys, random
from mpmath import mp, mpf, sqrt, cos, sin, pi
mp.dps = 60
def v(a): return [mpf(x) for x in a]
def dot(a,b): return sum(x*y for x,y in zip(a,b))
def sub(a,b): return [x-y for x,y in zip(a,b)]
def norm(a): return sqrt(dot(a,a))
def basis(n):
    n=[x/norm(n) for x in n]
    e=[mpf(1),0,0] if abs(n[0])<0.9 else [0,mpf(1),0]
    u=sub(e,[dot(e,n)*x for x in n]); u=[x/norm(u) for x in u]
    w=[n[1]*u[2]-n[2]*u[1], n[2]*u[0]-n[0]*u[2], n[0]*u[1]-n[1]*u[0]]
    return n,u,w
def dist(kind,O,D,C,N,r):
    O,D,C,N=v(O),v(D),v(C),v(N); r=mpf(r)
    mp.dps=800; O=sub(O,C); C=[mpf(0)]*3; mp.dps=60  # relative to the centre, exactly
    D=[x/norm(D) for x in D]
    n,u,w=basis(N)
    def f(th):
        P=[C[i]+r*(cos(th)*u[i]+sin(th)*w[i]) for i in range(3)]
        q=sub(P,O); t=dot(q,D)
        if kind=='r' and t<0: t=mpf(0)
        X=[O[i]+t*D[i] for i in range(3)]
        return norm(sub(P,X))
    K=2000
    vals=[(f(2*pi*k/K),k) for k in range(K)]
    best=min(vals)[0]
    for _,k in sorted(vals)[:6]:
        a,b=2*pi*(k-1)/K,2*pi*(k+1)/K
        g=(sqrt(5)-1)/2
        for _ in range(200):
            c=b-g*(b-a); d=a+g*(b-a)
            if f(c)<f(d): b=d
            else: a=c
        best=min(best,f((a+b)/2))
    return best
def gen():
    import math
    random.seed(7)
    for i in range(8):
        s=1e-300
        def uv():
            a=[random.gauss(0,1) for _ in range(3)]; n=math.sqrt(sum(x*x for x in a)); return [x/n for x in a]
        D=uv(); N=uv()
        kind=random.choice(['lc','rc'])
        O=[1e10, random.uniform(-2,2)*s, random.uniform(-2,2)*s]
        C=[1e10, random.uniform(-2,2)*s, random.uniform(-2,2)*s]
        r=random.uniform(0.1,2)*s
        print(kind,*('%.17g'%x for x in O+D+C+N+[r]))
if __name__=='__main__' and sys.argv[1:]==['--gen']:
    gen()
elif __name__=='__main__':
    for line in sys.stdin:
        p=line.split(); k=p[0]; x=[float(t) for t in p[1:]]
        print(mp.nstr(dist(k[0],x[0:3],x[3:6],x[6:9],x[9:12],x[12]),20))
