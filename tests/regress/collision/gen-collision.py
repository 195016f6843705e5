#!/usr/bin/env python3
"""Independent transcription of phyllo-export(5)'s collision model on a
receptacle whose profile is one straight segment (the disk, cone and
cylinder presets), used to write the expected CSV of the golden tests.

Primordium n (radius R_p) sits at angle n*alpha and at the smallest arc
length s >= 0 from the base where its sphere overlaps no earlier one.
On a straight generator the overlap with each earlier sphere is one
interval of s, the roots of a quadratic, so the smallest free s is
found exactly: start at 0 and, while some earlier sphere overlaps, move
to the upper root of the furthest-reaching one.  Placement stops at the
first primordium that would pass the tip.

Usage: gen-collision.py COUNT ALPHA R_P RHO0 Z0 RHO1 Z1 OBJECT
(the segment from the base (RHO0, Z0) to the tip (RHO1, Z1))."""
import math, sys

n_, alpha, rp, r0, z0, r1, z1, obj = sys.argv[1:]
N, alpha, rp = int(n_), float(alpha), float(rp)
r0, z0, r1, z1 = float(r0), float(z0), float(r1), float(z1)
L = math.hypot(r1 - r0, z1 - z0)
dr, dz = (r1 - r0) / L, (z1 - z0) / L        # unit, towards the tip


def point(s, a):
    rho = r0 + s * dr
    return (rho * math.cos(a), rho * math.sin(a), z0 + s * dz)


def upper_root(s, a, q, d):
    """Largest s' with |point(s', a) - q| = d, the end of the overlap."""
    c, sn = math.cos(a), math.sin(a)
    # point(s) = p0 + s * e, with p0 at s = 0 and e the unit direction
    p0 = (r0 * c - q[0], r0 * sn - q[1], z0 - q[2])
    e = (dr * c, dr * sn, dz)
    B = sum(p0[i] * e[i] for i in range(3))
    C = sum(x * x for x in p0) - d * d
    disc = max(B * B - C, 0.0)
    return -B + math.sqrt(disc)


placed = []
for n in range(N):
    a = math.radians(n * alpha % 360)
    s = 0.0
    while True:
        p = point(s, a)
        far = None
        for q in placed:
            d2 = sum((p[i] - q[i]) ** 2 for i in range(3))
            if d2 < (2 * rp) ** 2 * (1 - 1e-12):
                end = upper_root(s, a, q, 2 * rp)
                far = end if far is None else max(far, end)
        if far is None:
            break
        s = far
    if s > L * (1 + 1e-12):
        break
    placed.append(point(s, a))

print("n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,scale,radius")
tr, tz = -dr, -dz                      # u: along the generator, away from the tip
for n, p in enumerate(placed):
    a = math.radians(n * alpha % 360)
    c, sn = math.cos(a), math.sin(a)
    u = (tr * c, tr * sn, tz)
    w = (-tz * c, -tz * sn, tr)        # the tangent turned towards the outside
    v = (w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2],
         w[0] * u[1] - w[1] * u[0])
    vals = [*p, *u, *v, *w, rp, rp]
    print(f"{n},{obj}," + ",".join(f"{x:.12g}" for x in vals))
