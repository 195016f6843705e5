#!/usr/bin/env python3
"""Independent transcription of phyllo-export(5)'s planar model, used to
write the expected CSV of the golden tests.  Usage: gen-planar.py N ALPHA
SCALE|- OUTER|- INNER EXPONENT DOME OBJECT"""
import math, sys

n_, alpha, scale, outer, inner, e, dome, obj = sys.argv[1:]
N, alpha, inner, e, dome = int(n_), float(alpha), float(inner), float(e), float(dome)
if outer != '-':
    c = (float(outer) - inner) / (N - 1) ** e
else:
    c = float(scale)
R = lambda n: inner + c * n ** e
dR = lambda n: c * e * n ** (e - 1)
rim = R(N - 1)
print("n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,scale,radius")
for n in range(N):
    phi = math.radians(n * alpha % 360)
    rho = R(n)
    z = dome * (1 - (rho / rim) ** 2)
    s = -2 * dome * rho / rim ** 2          # dz/drho
    k = 1 / math.sqrt(1 + s * s)
    cs, sn = math.cos(phi), math.sin(phi)
    u = (cs * k, sn * k, s * k)
    w = (-s * cs * k, -s * sn * k, k)
    v = (-sn, cs, 0.0)
    m = max(n, 1)
    # hexagonal packing with the area per organ d(pi R^2)/dn
    r = math.sqrt(2 * math.pi * R(m) * dR(m) / (2 * math.sqrt(3)))
    vals = [rho * cs, rho * sn, z, *u, *v, *w, r, r]
    print(f"{n},{obj}," + ",".join(f"{x:.12g}" for x in vals))
