# svgcheck.py - what --svg's parastichies must be, read back from the
# SVG itself: every path follows one family f through organ centres
# (each point a circle's centre, each step f organs on where the organs
# have an order), in chains of two steps at least (one only in a family
# that has no longer chain, a zone too short to hold two) that are
# spirals, not zig-zags -- along a chain the organs turn one way about
# the axis and move one way along the structure (up the unrolled page;
# out from the middle from above), in the model's own positions from
# --csv -- no path is empty, a colour stands for one family, the
# legend's families are exactly the families drawn, on a head whose
# first organs are its centre the smallest family's spirals start there
# (not in a ring of short arcs round it), the family counts drawn do not
# overlap, and the key names every organ object beside a disc of its
# colour.  Usage:
#   python3 svgcheck.py FILE.svg FILE.csv OBJECT...
# Prints what is wrong and exits 1, or prints nothing.
import csv
import math
import re
import sys
import xml.etree.ElementTree as E

NS = "{http://www.w3.org/2000/svg}"
path, csv_path, objects = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = list(csv.DictReader(open(csv_path)))
angle = [math.atan2(float(r["y"]), float(r["x"])) for r in rows]
root = E.parse(path).getroot()
wrong = []

circles = [(float(c.get("cx")), float(c.get("cy")), c.get("fill"))
           for c in root.iter(NS + "circle")]
texts = []
for t in root.iter(NS + "text"):
    m = re.match(r"translate\(([-\d.e+]+) ([-\d.e+]+)\) scale\(([-\d.e+]+)\)",
                 t.get("transform"))
    texts.append((float(m.group(1)), float(m.group(2)),
                  100 * float(m.group(3)), t.get("fill"), t.text or ""))

unrolled = any("unrolled" in words for x, y, size, fill, words in texts)
# Organs measured (model "measured") are numbered as the file's rows,
# not along the spiral: their steps are not f organs on.
ordered = not any("measured model" in words
                  for x, y, size, fill, words in texts)
# The organs: the circles drawn one per organ, before the key's.
legend_top = min(y for x, y, size, fill, words in texts)
organs = circles[:len(circles) - len(objects)]
where = {}
for i, (x, y, fill) in enumerate(organs):
    where[(round(x, 6), round(y, 6))] = i

# A colour stands for one family, named by the numbers in that colour.
family = {}
for x, y, size, fill, words in texts:
    if words.isdigit():
        if family.setdefault(fill, int(words)) != int(words):
            wrong.append("colour %s names families %d and %s"
                         % (fill, family[fill], words))

chains = {}     # family: its chains, as organ indices
for p in root.iter(NS + "path"):
    d, colour = p.get("d"), p.get("stroke")
    if not d or not d.strip():
        wrong.append("an empty path")
        continue
    if colour not in family:
        wrong.append("a path of colour %s, which no count names" % colour)
        continue
    f = family[colour]
    for sub in d.split("M")[1:]:
        # The points on the curve: the start, then each C's last.
        nums = [float(v) for v in re.findall(r"[-\d.e+]+", sub)]
        pts = [tuple(nums[0:2])] + [tuple(nums[k + 4:k + 6])
                                    for k in range(2, len(nums), 6)]
        ix = [where.get((round(x, 6), round(y, 6))) for x, y in pts]
        if None in ix:
            wrong.append("family %d: a point that is no organ's centre"
                         % f)
            continue
        chains.setdefault(f, []).append(ix)
        if len(ix) < 2:
            wrong.append("family %d: a chain of %d organs" % (f, len(ix)))
        if ordered and any(b - a != f for a, b in zip(ix, ix[1:])):
            wrong.append("family %d: steps %s" % (
                f, sorted({b - a for a, b in zip(ix, ix[1:])})))
        # Turning: each step's angle, within a half turn either way.
        turns = [math.remainder(angle[b] - angle[a], 2 * math.pi)
                 for a, b in zip(ix, ix[1:])]
        along = [b[1] - a[1] if unrolled else
                 math.hypot(*b) - math.hypot(*a)
                 for a, b in zip(pts, pts[1:])]
        for what, steps in (("turns", turns), ("moves", along)):
            if any(x > 0 for x in steps) and any(x < 0 for x in steps):
                wrong.append("family %d %s both ways along organs %s..."
                             % (f, what, ix[:4]))

for f, cs in chains.items():
    if any(len(c) < 3 for c in cs) and any(len(c) >= 3 for c in cs):
        wrong.append("family %d: a chain of 2 organs beside longer ones" % f)

# The legend's families: the numbers on its "families:" line.
line = [t for t in texts if t[4] == "families:"]
if line:
    y0 = line[0][1]
    keyed_families = {int(words) for x, y, size, fill, words in texts
                      if words.isdigit() and abs(y - y0) < 1e-9 * max(1, abs(y0))}
    for f in sorted(keyed_families - set(chains)):
        wrong.append("the legend lists family %d, which is not drawn" % f)
    for f in sorted(set(chains) - keyed_families):
        wrong.append("family %d is drawn but not in the legend" % f)
elif chains:
    wrong.append("families drawn but no families line in the legend")

# A head seen from above whose first organs are its middle: the
# smallest family's spirals run from there.
if ordered and chains and not unrolled and len(organs) > 1:
    mx = sum(x for x, y, fill in organs) / len(organs)
    my = sum(y for x, y, fill in organs) / len(organs)
    r0 = math.hypot(organs[0][0] - mx, organs[0][1] - my)
    rn = math.hypot(organs[-1][0] - mx, organs[-1][1] - my)
    f = min(chains)
    if r0 < rn and not any(c[0] < f for c in chains[f]):
        wrong.append("family %d: no spiral starts at the centre (organs "
                     "0 to %d): they start at %s" % (f, f - 1, sorted(
                         c[0] for c in chains[f])[:6]))

# The counts drawn (not the legend's key): their boxes apart.
labels = [(x, y - 0.7 * size, 0.56 * size * len(words), 0.7 * size)
          for x, y, size, fill, words in texts
          if words.isdigit() and y > legend_top + 7 * size]
for i, a in enumerate(labels):
    for b in labels[i + 1:]:
        if a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and \
                a[1] < b[1] + b[3] and b[1] < a[1] + a[3]:
            wrong.append("counts overlap at %.3g,%.3g" % a[:2])

# The key: each object's name, and its colour on a disc.
keyed = {words for x, y, size, fill, words in texts}
colours = {fill for x, y, fill in circles[len(circles) - len(objects):]}
for k, name in enumerate(objects):
    if name not in keyed:
        wrong.append("the key lacks %s" % name)
if len(colours) != len(objects):
    wrong.append("the key has %d colours for %d objects"
                 % (len(colours), len(objects)))

for w in sorted(set(wrong))[:12]:
    print(w)
sys.exit(1 if wrong else 0)
