#!/usr/bin/python3
"""Writes vessel.stl: the round column of this case (radius 25 mm, 0 to 150 mm, 64 sides) as a closed ASCII STL
with outward normals, the kind of file a CAD program exports. Run from this folder; the file is shipped, so this
only shows how it was made (and how to make another)."""
import math


def write(path, tris, name):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for a, b, c in tris:
            ux, uy, uz = (b[i] - a[i] for i in range(3)); vx, vy, vz = (c[i] - a[i] for i in range(3))
            n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx); l = math.sqrt(sum(x * x for x in n))
            f.write(f"  facet normal {n[0]/l:.9e} {n[1]/l:.9e} {n[2]/l:.9e}\n    outer loop\n")
            for p in (a, b, c): f.write(f"      vertex {p[0]:.9e} {p[1]:.9e} {p[2]:.9e}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")
def cylinder(axis_origin, radius, z0, z1, n, axis="z"):
    """A closed prism of n sides along axis from z0 to z1, outward normals (the seam shares its corners)."""
    cx, cy = axis_origin
    def pt(t, z):
        u, v = cx + radius * math.cos(t), cy + radius * math.sin(t)
        return (u, v, z) if axis == "z" else (z, u, v) if axis == "x" else (u, z, v)
    tris = []
    for k in range(n):
        t0, t1 = 2 * math.pi * k / n, 2 * math.pi * ((k + 1) % n) / n
        a, b, c, d = pt(t0, z0), pt(t1, z0), pt(t1, z1), pt(t0, z1)
        tris += [(a, b, c), (a, c, d)]
        lo, hi = pt(0, z0), pt(0, z1)
        clo = (cx, cy, z0) if axis == "z" else (z0, cx, cy) if axis == "x" else (cx, z0, cy)
        chi = (cx, cy, z1) if axis == "z" else (z1, cx, cy) if axis == "x" else (cx, z1, cy)
        tris += [(clo, b, a), (chi, d, c)]
    return tris


if __name__ == "__main__":
    write("vessel.stl", cylinder((0.0, 0.0), 0.025, 0.0, 0.15, 64), "vessel")
