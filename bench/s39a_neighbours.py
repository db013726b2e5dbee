#!/usr/bin/env python3
"""spec/stuffing.md S39a, case s >= 32h: for a point p outside a cube Y of
side 1 (center 0) with |p| <= 1 + eps, eps = 0.375 h / s, the largest
distance from p to the nearest center of a cube of side 1/2 that shares a
face or an edge with Y and lies in the box of Y and the side-1 grid cube
holding p; against S3's threshold for that cube, sqrt(3)/4 + 4h/s.
A random search over directions, then a local refinement of the worst.
Usage: python3 bench/s39a_neighbours.py   (about a minute)
"""
import math, itertools, random
k=math.sqrt(3)/2
C=[c for c in itertools.product([-0.75,-0.25,0.25,0.75],repeat=3) if sum(abs(x)==0.75 for x in c) in (1,2)]
def score(p):
    cell=[math.floor(x+0.5) for x in p]
    lo=[min(-0.5,c-0.5) for c in cell]; hi=[max(0.5,c+0.5) for c in cell]
    return min(math.dist(p,c) for c in C if all(c[i]-0.25>=lo[i]-1e-12 and c[i]+0.25<=hi[i]+1e-12 for i in range(3)))
def worst(rmax):
    best=0;bp=None
    random.seed(2)
    for it in range(60000):
        d=[random.gauss(0,1) for _ in range(3)]; n=math.sqrt(sum(x*x for x in d)); d=[x/n for x in d]
        p=[x*rmax for x in d]
        sc=score(p)
        if sc>best: best,bp=sc,p
    # local refine
    step=0.01
    for it in range(20000):
        q=[x+random.gauss(0,step) for x in bp]; n=math.sqrt(sum(x*x for x in q)); q=[x/n*rmax for x in q]
        sc=score(q)
        if sc>best: best,bp=sc,q
        if it%5000==4999: step/=3
    return best,bp
for j in (5,6,7,8,10,20):
    rmax=1+0.375/2**j
    w,p=worst(rmax)
    print(j, "worst %.5f"%w, "threshold %.5f"%(k/2+4/2**j), [round(x,4) for x in p])
