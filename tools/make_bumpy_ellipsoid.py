#!/usr/bin/env python3
"""Writes a bumpy ellipsoid, a stand-in for a raw scan (issue 40), as OBJ, binary STL or PLY.

A closed latitude-longitude grid: `rings` latitude bands × `segments` longitudes gives
2·segments·(rings − 1) triangles (780 × 1,560 → 2,430,480). Semi-axes 40 × 40 × 65 mm (an
8 × 13 cm ellipsoid, meters in the file); the radius is modulated by seeded bumps (±1.5 mm)
and a fine ripple (0.15 mm). Deterministic for a given seed. Python 3 standard library only.

    tools/make_bumpy_ellipsoid.py --rings 780 --segments 1560 --out /tmp/bumpy_2.4M.obj
    tools/make_bumpy_ellipsoid.py --triangles 1e5 --out /tmp/bumpy_1e5.ply
"""
import argparse
import math
import random
import struct
import sys

SEMI_AXES_M = (0.040, 0.040, 0.065)
BUMP_AMPLITUDE_M = 0.0015
RIPPLE_AMPLITUDE_M = 0.00015
BUMP_TERMS = 8


def grid_for_triangles(triangles):
    """Rings × segments with segments = 2·rings and about `triangles` triangles."""
    rings = max(3, round(math.sqrt(triangles / 4.0)))
    return rings, 2 * rings


def make_vertices(rings, segments, seed):
    """Flat [x, y, z, ...] in meters: north pole, rings − 1 latitude circles, south pole."""
    rng = random.Random(seed)
    terms = [(rng.randint(2, 9), rng.randint(1, 8), rng.uniform(0, 2 * math.pi),
              rng.uniform(0, 2 * math.pi), rng.uniform(-1.0, 1.0)) for _ in range(BUMP_TERMS)]
    norm = sum(abs(t[4]) for t in terms)
    terms = [(m, n, p, q, BUMP_AMPLITUDE_M * a / norm) for m, n, p, q, a in terms]
    ax, ay, az = SEMI_AXES_M
    phis = [2.0 * math.pi * j / segments for j in range(segments)]
    # Per-longitude factors of each term, computed once.
    cos_n = [[math.cos(n * phi + q) for phi in phis] for (_, n, _, q, _) in terms]
    ripple_phi = [math.sin(97.0 * phi) for phi in phis]
    cos_phi = [math.cos(phi) for phi in phis]
    sin_phi = [math.sin(phi) for phi in phis]
    out = [0.0, 0.0, az]
    for i in range(1, rings):
        theta = math.pi * i / rings
        st, ct = math.sin(theta), math.cos(theta)
        sin_m = [a * math.sin(m * theta + p) for (m, _, p, _, a) in terms]
        ripple_t = RIPPLE_AMPLITUDE_M * math.sin(61.0 * theta) * st
        base = [(ax * st, ay * st, az * ct)]
        bx, by, bz = base[0]
        # Offset along the sphere direction (st cos φ, st sin φ, ct).
        for j in range(segments):
            d = ripple_t * ripple_phi[j] * st
            for k, s in enumerate(sin_m):
                d += s * cos_n[k][j]
            d *= st  # bumps fade toward the poles: no spike at the grid's singular points
            cp, sp = cos_phi[j], sin_phi[j]
            out.extend((bx * cp + d * st * cp, by * sp + d * st * sp, bz + d * ct))
    out.extend((0.0, 0.0, -az))
    return out


def triangle_indices(rings, segments):
    """Yields (a, b, c) 0-based, counter-clockwise seen from outside."""
    south = 1 + (rings - 1) * segments
    for j in range(segments):
        yield 0, 1 + j, 1 + (j + 1) % segments
    for i in range(rings - 2):
        r0, r1 = 1 + i * segments, 1 + (i + 1) * segments
        for j in range(segments):
            j1 = (j + 1) % segments
            yield r0 + j, r1 + j, r1 + j1
            yield r0 + j, r1 + j1, r0 + j1
    r = 1 + (rings - 2) * segments
    for j in range(segments):
        yield r + j, south, r + (j + 1) % segments


def write_obj(path, v, rings, segments):
    with open(path, "w", buffering=1 << 20) as f:
        f.write("# bumpy ellipsoid %d x %d (tools/make_bumpy_ellipsoid.py)\n" % (rings, segments))
        f.write("".join("v %.7g %.7g %.7g\n" % (v[k], v[k + 1], v[k + 2])
                        for k in range(0, len(v), 3)))
        f.write("".join("f %d %d %d\n" % (a + 1, b + 1, c + 1)
                        for a, b, c in triangle_indices(rings, segments)))


def write_stl(path, v, rings, segments):
    tris = list(triangle_indices(rings, segments))
    with open(path, "wb") as f:
        f.write(b"bumpy ellipsoid (tools/make_bumpy_ellipsoid.py)".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        pack = struct.Struct("<12fH").pack
        chunk = []
        for a, b, c in tris:
            pa, pb, pc = v[3 * a:3 * a + 3], v[3 * b:3 * b + 3], v[3 * c:3 * c + 3]
            ux, uy, uz = pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]
            wx, wy, wz = pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]
            nx, ny, nz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
            ln = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
            chunk.append(pack(nx / ln, ny / ln, nz / ln, *pa, *pb, *pc, 0))
            if len(chunk) >= 65536:
                f.write(b"".join(chunk))
                chunk = []
        f.write(b"".join(chunk))


def write_ply(path, v, rings, segments):
    tris = list(triangle_indices(rings, segments))
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\n"
                 "comment bumpy ellipsoid (tools/make_bumpy_ellipsoid.py)\n"
                 "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(v) // 3, len(tris))).encode())
        f.write(struct.pack("<%df" % len(v), *v))
        pack = struct.Struct("<B3i").pack
        f.write(b"".join(pack(3, a, b, c) for a, b, c in tris))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rings", type=int, help="latitude bands (default from --triangles)")
    ap.add_argument("--segments", type=int, help="longitudes (default 2·rings)")
    ap.add_argument("--triangles", type=float, help="about this many triangles (rings = √(n/4))")
    ap.add_argument("--seed", type=int, default=40, help="bump seed")
    ap.add_argument("--out", required=True, help="output file: .obj, .stl (binary) or .ply")
    a = ap.parse_args()
    if a.rings is None:
        if a.triangles is None:
            ap.error("give --rings or --triangles")
        a.rings, a.segments = grid_for_triangles(a.triangles)
    if a.segments is None:
        a.segments = 2 * a.rings
    if a.rings < 3 or a.segments < 3:
        ap.error("need rings >= 3 and segments >= 3")
    writers = {"obj": write_obj, "stl": write_stl, "ply": write_ply}
    ext = a.out.rsplit(".", 1)[-1].lower()
    if ext not in writers:
        ap.error("output must end in .obj, .stl or .ply")
    v = make_vertices(a.rings, a.segments, a.seed)
    writers[ext](a.out, v, a.rings, a.segments)
    print("%s: %d x %d grid, %d vertices, %d triangles" %
          (a.out, a.rings, a.segments, len(v) // 3, 2 * a.segments * (a.rings - 1)),
          file=sys.stderr)


if __name__ == "__main__":
    main()
