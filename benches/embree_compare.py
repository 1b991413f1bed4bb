#!/usr/bin/env python3
"""Embree 4 on the rays of `grader bench-rays`: the same mesh, the same camera.

Usage (the arguments of `grader bench-rays`):

    python3 benches/embree_compare.py MESH.obj --size 1000x1000 \
        --eye -0.0168,0.110,0.30 --at -0.0168,0.110,-0.0015 --up 0,1,0 --fovy 40
    python3 benches/embree_compare.py --generated 80000 --eye 0,-2.6,2.6 --up 0,0,1

On first use it creates a virtualenv in <workspace>/target/embree-venv, installs
`embreex numpy` there and re-runs itself inside it.

The rays follow the book's conventions (§0), computed here independently of the Rust
code: pixel centres, sx = 2(x+0.5)/w - 1, sy = 1 - 2(y+0.5)/h; look-at frame
w = normalize(eye - at), u = normalize(up x w), v = w x u; direction
normalize(u*sx*aspect*tan(fovy/2) + v*sy*tan(fovy/2) - w), in float64, then
rounded to float32 for Embree. The rays are made before the clock starts; the
clock (time.process_time: CPU time of the whole process, so any helper thread
would count too) covers only `scene.run(origins, directions, output=1)`, which
shoots them one by one (rtcIntersect1) on one thread. Median of --repeat runs.

Output, one line per kernel:
    embree robust: Mrays/s: F hits: N build_ms: B
    embree fast:   Mrays/s: F hits: N build_ms: B
"""

import argparse
import math
import os
import subprocess
import sys
import time
import venv

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VENV = os.path.join(ROOT, "target", "embree-venv")


def ensure_embree():
    """Imports embreex and numpy, creating the virtualenv and re-running inside it if needed."""
    try:
        import embreex.mesh_construction  # noqa: F401
        import embreex.rtcore_scene  # noqa: F401
        import numpy  # noqa: F401

        return
    except ImportError:
        pass
    python = os.path.join(VENV, "bin", "python")
    if os.path.realpath(sys.prefix) == os.path.realpath(VENV):
        sys.exit("error: embreex or numpy is missing from " + VENV + "; delete that folder and run again")
    if not os.path.exists(python):
        print("creating " + VENV + " (pip install embreex numpy) ...", file=sys.stderr)
        venv.create(VENV, with_pip=True)
        subprocess.run([python, "-m", "pip", "install", "--quiet", "embreex", "numpy"], check=True)
    os.execv(python, [python, os.path.abspath(__file__)] + sys.argv[1:])


def parse_size(s):
    try:
        w, h = s.lower().split("x")
        w, h = int(w), int(h)
    except ValueError:
        raise argparse.ArgumentTypeError("expected WxH, e.g. 1000x1000, found %r" % s)
    if not (1 <= w <= 16384 and 1 <= h <= 16384):
        raise argparse.ArgumentTypeError("expected sizes from 1 to 16384, found %r" % s)
    return w, h


def parse_vec3(s):
    parts = s.split(",")
    try:
        v = [float(p) for p in parts]
    except ValueError:
        v = []
    if len(v) != 3 or not all(math.isfinite(x) for x in v):
        raise argparse.ArgumentTypeError("expected three finite numbers X,Y,Z, found %r" % s)
    return v


def load_obj(path):
    """Positions (float32, n x 3) and triangles (int32, m x 3) of an OBJ file;
    polygons are split into fans from their first corner, as tobj does."""
    import numpy as np

    positions, triangles = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                positions.append([float(x) for x in fields[1:4]])
            elif fields[0] == "f":
                n = len(positions)
                corners = []
                for c in fields[1:]:
                    i = int(c.split("/")[0])
                    corners.append(i - 1 if i > 0 else n + i)
                for k in range(1, len(corners) - 1):
                    triangles.append([corners[0], corners[k], corners[k + 1]])
    if not triangles:
        sys.exit("error: %s holds no faces" % path)
    return np.array(positions, dtype=np.float32), np.array(triangles, dtype=np.int32)


def torus_segments(n):
    """The (major, minor) segment counts of `grader bench-rays --generated n`."""
    minor = max(3, int(round(math.sqrt(n / 4.0))))
    major = max(3, int(round(n / (2.0 * minor))))
    return major, minor


def torus(major_r, minor_r, m, n):
    """The kit's Mesh::torus, in float32 as the default (f32) build computes it:
    p(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), two
    triangles (a, b, c), (a, c, d) per grid cell, wrapping at the seams."""
    import numpy as np

    f = np.float32
    tau = f(2.0 * math.pi)
    i = np.repeat(np.arange(m), n).astype(f)
    j = np.tile(np.arange(n), m).astype(f)
    u = tau * i / f(m)
    v = tau * j / f(n)
    normal = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=1)
    ring = np.stack([f(major_r) * np.cos(u), f(major_r) * np.sin(u), np.zeros_like(u)], axis=1)
    positions = (ring + f(minor_r) * normal).astype(f)
    ii, jj = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    ii, jj = ii.ravel(), jj.ravel()

    def index(a, b):
        return (a % m) * n + b % n

    a, b, c, d = index(ii, jj), index(ii + 1, jj), index(ii + 1, jj + 1), index(ii, jj + 1)
    tris = np.empty((2 * m * n, 3), dtype=np.int32)
    tris[0::2] = np.stack([a, b, c], axis=1)
    tris[1::2] = np.stack([a, c, d], axis=1)
    return positions, tris


def primary_rays(size, eye, at, up, fovy_degrees):
    """One ray per pixel, row-major, pixel (0, 0) at the top left."""
    import numpy as np

    w_px, h_px = size
    eye, at, up = (np.array(x, dtype=np.float64) for x in (eye, at, up))
    w = eye - at
    if np.linalg.norm(w) == 0.0:
        sys.exit("error: bad camera: eye and at are the same point")
    w /= np.linalg.norm(w)
    u = np.cross(up, w)
    if np.linalg.norm(u) == 0.0:
        sys.exit("error: bad camera: up is parallel to the view direction")
    u /= np.linalg.norm(u)
    v = np.cross(w, u)
    aspect = w_px / h_px
    half = math.tan(math.radians(fovy_degrees) / 2.0)
    x = np.arange(w_px, dtype=np.float64)
    y = np.arange(h_px, dtype=np.float64)
    sx = 2.0 * (x + 0.5) / w_px - 1.0
    sy = 1.0 - 2.0 * (y + 0.5) / h_px
    sx, sy = np.meshgrid(sx, sy)  # rows are y: row-major like the pixel loop
    d = (sx.ravel()[:, None] * aspect * half) * u + (sy.ravel()[:, None] * half) * v - w
    d /= np.linalg.norm(d, axis=1)[:, None]
    origins = np.broadcast_to(eye, d.shape)
    return np.ascontiguousarray(origins, dtype=np.float32), np.ascontiguousarray(d, dtype=np.float32)


def bench(positions, triangles, origins, directions, robust, repeat):
    import numpy as np
    from embreex import rtcore_scene
    from embreex.mesh_construction import TriangleMesh

    start = time.perf_counter()
    scene = rtcore_scene.EmbreeScene(robust=robust)
    TriangleMesh(scene, positions, triangles)
    # Embree builds on the first query: commit with one ray so the build is timed here.
    scene.run(origins[:1], directions[:1])
    build_ms = (time.perf_counter() - start) * 1e3
    rates, hits = [], None
    for _ in range(repeat):
        start = time.process_time()
        result = scene.run(origins, directions, output=1)
        seconds = time.process_time() - start
        found = int(np.count_nonzero(result["geomID"] != -1))
        if hits is not None and found != hits:
            sys.exit("error: Embree's hit count changed between runs: %d then %d" % (hits, found))
        hits = found
        rates.append(len(origins) / seconds / 1e6)
    rates.sort()
    median = rates[len(rates) // 2] if len(rates) % 2 else 0.5 * sum(rates[len(rates) // 2 - 1 :][:2])
    return median, hits, build_ms


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh", nargs="?", help="the OBJ mesh")
    parser.add_argument("--generated", type=int, help="the kit's torus with about N triangles instead")
    parser.add_argument("--size", type=parse_size, default=(1000, 1000))
    parser.add_argument("--eye", type=parse_vec3, default=[0.0, 0.0, 4.0])
    parser.add_argument("--at", type=parse_vec3, default=[0.0, 0.0, 0.0])
    parser.add_argument("--up", type=parse_vec3, default=[0.0, 1.0, 0.0])
    parser.add_argument("--fovy", type=float, default=40.0)
    parser.add_argument("--repeat", type=int, default=5)
    # "--eye -0.0168,0.11,0.3" would read as an unknown option: glue such values on with "=".
    argv, k = [], 0
    while k < len(sys.argv[1:]):
        a = sys.argv[1 + k]
        if a in ("--eye", "--at", "--up") and k + 1 < len(sys.argv[1:]):
            argv.append(a + "=" + sys.argv[2 + k])
            k += 2
        else:
            argv.append(a)
            k += 1
    args = parser.parse_args(argv)
    if (args.mesh is None) == (args.generated is None):
        parser.error("give a mesh file or --generated N (one of them)")
    if not 0.0 < args.fovy < 180.0:
        parser.error("--fovy must be between 0 and 180 degrees")
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    ensure_embree()

    if args.mesh is not None:
        if not os.path.isfile(args.mesh):
            sys.exit("error: cannot read %s: no such file" % args.mesh)
        positions, triangles = load_obj(args.mesh)
        name = args.mesh
    else:
        m, n = torus_segments(args.generated)
        positions, triangles = torus(1.0, 0.4, m, n)
        name = "torus %dx%d" % (m, n)
    origins, directions = primary_rays(args.size, args.eye, args.at, args.up, args.fovy)
    print(
        "%s: %d triangles, %d rays, one thread, median of %d run(s)"
        % (name, len(triangles), len(origins), args.repeat),
        file=sys.stderr,
        flush=True,
    )
    for label, robust in (("embree robust", True), ("embree fast  ", False)):
        rate, hits, build_ms = bench(positions, triangles, origins, directions, robust, args.repeat)
        print("%s: Mrays/s: %.3f hits: %d build_ms: %.1f" % (label, rate, hits, build_ms))


if __name__ == "__main__":
    main()
