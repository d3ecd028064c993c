# Hostile OpenVDB volumes for tests/bad/vdb.cases, made by OpenVDB's own
# Python module (python3-openvdb): a truncated file, one with garbage in its
# grid data, one whose only grid holds booleans, an empty float grid, and a
# float grid under a rotated transform.
/usr/bin/python3 - <<'PY'
import math
import pyopenvdb as vdb

def cube(name="density"):
    g = vdb.FloatGrid()
    g.name = name
    a = g.getAccessor()
    for k in range(4):
        for j in range(4):
            for i in range(4):
                a.setValueOn((i, j, k), 0.25 * i + j - k)
    return g

vdb.write("good.vdb", grids=[cube()])
data = open("good.vdb", "rb").read()
open("trunc.vdb", "wb").write(data[:len(data) // 2])
mid = len(data) // 2
open("garbage.vdb", "wb").write(data[:mid - 64] + bytes((37 * i + 11) % 256 for i in range(128)) + data[mid + 64:])
g = vdb.BoolGrid()
g.name = "labels"
g.getAccessor().setValueOn((1, 2, 3), True)
vdb.write("boolgrid.vdb", grids=[g])
e = vdb.FloatGrid()
e.name = "density"
vdb.write("emptygrid.vdb", grids=[e])
r = cube()
c, s = math.cos(0.3), math.sin(0.3)
r.transform = vdb.createLinearTransform([[c, s, 0, 0], [-s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
vdb.write("rotated.vdb", grids=[r])
PY
rm -f good.vdb
