#!/usr/bin/env python3
"""Draws points uniformly on the faces of a mesh (.off).

    python3 make_samples.py MESH.off NAME COUNT SEED

writes NAME.xyz (x y z) and NAME_truth.xyz (x y z nx ny nz, the normal of the
face each point lies on) next to this script. The bundled files come from
    python3 make_samples.py ../../../shared/data/meshes/fandisk.off fandisk_20k 20000 2012
    python3 make_samples.py ../../../shared/data/meshes/anchor_dense.off anchor_15k 15000 2013

    python3 make_samples.py --ply NAME

writes NAME_truth.xyz again as NAME.ply (binary PLY: the same points and
normals, as doubles); fandisk_20k.ply comes from `--ply fandisk_20k`.
"""
import bisect, math, os, random, struct, sys

def read_off(path):
    words = open(path).read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = [tuple(map(float, words[at + 3 * i: at + 3 * i + 3])) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append(tuple(int(w) for w in words[at + 1: at + 1 + k]))
        at += 1 + k
    return vertices, faces

def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

def write_ply(name):
    here = os.path.dirname(os.path.abspath(__file__))
    rows = [tuple(map(float, line.split())) for line in open(os.path.join(here, name + "_truth.xyz"))]
    header = ["ply", "format binary_little_endian 1.0", "element vertex %d" % len(rows)]
    header += ["property double %s" % p for p in ("x", "y", "z", "nx", "ny", "nz")] + ["end_header", ""]
    with open(os.path.join(here, name + ".ply"), "wb") as ply:
        ply.write("\n".join(header).encode("ascii"))
        for row in rows:
            ply.write(struct.pack("<6d", *row))

def main():
    if sys.argv[1] == "--ply":
        return write_ply(sys.argv[2])
    vertices, faces = read_off(sys.argv[1])
    triangles, cumulated, total = [], [], 0.0
    for f in faces:
        for i in range(1, len(f) - 1):  # fan triangulation
            p, q, r = vertices[f[0]], vertices[f[i]], vertices[f[i + 1]]
            n = cross(sub(q, p), sub(r, p))
            area = 0.5 * math.sqrt(sum(c * c for c in n))
            if area == 0:
                continue
            total += area
            triangles.append((p, q, r, tuple(c / (2 * area) for c in n)))
            cumulated.append(total)
    name, count, seed = sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    rng = random.Random(seed)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, name + ".xyz"), "w") as points, \
         open(os.path.join(here, name + "_truth.xyz"), "w") as truth:
        for _ in range(count):
            p, q, r, n = triangles[bisect.bisect_left(cumulated, rng.random() * total)]
            a, b = rng.random(), rng.random()
            if a + b > 1:
                a, b = 1 - a, 1 - b
            x = tuple(p[d] + a * (q[d] - p[d]) + b * (r[d] - p[d]) for d in range(3))
            points.write("%.6f %.6f %.6f\n" % x)
            truth.write("%.6f %.6f %.6f %.6f %.6f %.6f\n" % (x + n))

if __name__ == "__main__":
    main()
