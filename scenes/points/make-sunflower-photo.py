#!/usr/bin/env python3
# make-sunflower-photo.py - writes sunflower-photo.csv: the florets of a
# sunflower head as clicking their centres on a photograph would give
# them.  SYNTHETIC: no photograph whose licence allowed it was at hand,
# so the head is made, with what a photograph and a hand add to one:
#   - 1400 florets on Vogel's spiral, a little larger towards the rim
#     (radius ~ n^0.53, as a real head's florets grow outward);
#   - each click off by 8% of the spacing (a steady hand, a sharp photo);
#   - 2% of the florets missed;
#   - the camera 20 degrees off the axis: the head squashed by
#     cos 20 = 0.94 across one direction;
#   - the photograph's frame cutting off the head's right edge;
#   - pixel coordinates, y growing down the picture, the centre unknown;
#   - the rows in the order of no particular walk over the head.
# Python's standard library only; the same file every run (seeded).
import math
import random

random.seed(20250101)
N, EXPONENT, PX = 1400, 0.53, 17.0          # florets, growth, pixels
ALPHA = math.radians(137.50776405003785)
CX, CY = 812.0, 598.0                         # the head's centre, pixels
SQUASH, SQUASH_AT = math.cos(math.radians(20)), math.radians(35)
FRAME_RIGHT = 1420.0                          # the photograph's edge

rows = []
for n in range(1, N + 1):
    r = PX * n ** EXPONENT
    a = n * ALPHA
    x, y = r * math.cos(a), r * math.sin(a)
    # The spacing of a hexagonal cell of the area a floret takes there.
    spacing = PX * n ** (EXPONENT - 0.5) * math.sqrt(4 * math.pi * EXPONENT / math.sqrt(3))
    x += random.gauss(0, 0.08 * spacing / math.sqrt(2))
    y += random.gauss(0, 0.08 * spacing / math.sqrt(2))
    if random.random() < 0.02:
        continue
    # The view: squashed along SQUASH_AT, then into the picture, y down.
    u = x * math.cos(SQUASH_AT) + y * math.sin(SQUASH_AT)
    v = -x * math.sin(SQUASH_AT) + y * math.cos(SQUASH_AT)
    u *= SQUASH
    x = u * math.cos(SQUASH_AT) - v * math.sin(SQUASH_AT)
    y = u * math.sin(SQUASH_AT) + v * math.cos(SQUASH_AT)
    px, py = CX + x, CY - y
    if px > FRAME_RIGHT:
        continue
    rows.append((px, py))
random.shuffle(rows)

with open("sunflower-photo.csv", "w") as f:
    f.write("# Florets of a sunflower head clicked on a photograph, in pixels\n")
    f.write("# (y down).  SYNTHETIC: made by make-sunflower-photo.py, which\n")
    f.write("# says how; no real photograph's licence allowed its use here.\n")
    f.write("x,y\n")
    for px, py in rows:
        f.write("%.1f,%.1f\n" % (px, py))
