"""Issue 39: the meshes `plot surface` exports, read back by an independent
reader, meshio (a helper, not a project dependency: pip install meshio).

The thesis cubic surface over its printed net (examples/surfaces/thesis-net.txt,
m = 1/2) and a C1 join of a second patch are exported as OBJ, PLY and STL with
N = 7 samples per direction. Checked:
  * OBJ and PLY read back with the same vertices (bit for bit) and the same
    triangles, N*N vertices and 2*(N-1)^2 triangles per patch;
  * every STL facet's corners are vertices of the OBJ (STL repeats them per
    facet), as many facets as triangles;
  * vertex (i, j) of the first patch is S(i/(N-1), j/(N-1)): within the
    certified error bound that `trig-audit eval --surface` prints for it.

Run from the repository root:  python3 examples/independent/issue39_meshio.py
"""

import os
import subprocess
import tempfile

import meshio
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
N = 7
NET = "examples/surfaces/thesis-net.txt"


def cli(args):
    binary = os.path.join(ROOT, "target", "debug", "trig-audit")
    cmd = [binary] if os.path.exists(binary) else ["cargo", "run", "-q", "-p", "trig-audit", "--"]
    return subprocess.run(cmd + args, cwd=ROOT, capture_output=True, text=True, check=True).stdout


def export(path, extra):
    cli(["plot", "surface", "--family", "thesis-cubic", "--param", "m=1/2", "--net", NET,
         "--samples", str(N), "--output", path] + extra)
    return meshio.read(path)


def triangles(mesh):
    return np.concatenate([c.data for c in mesh.cells if c.type == "triangle"])


with tempfile.TemporaryDirectory() as tmp:
    for label, extra, patches in [("one patch", [], 1), ("C1 join, two patches", ["--join", "c1"], 2)]:
        obj, ply, stl = (export(os.path.join(tmp, f"s.{ext}"), extra) for ext in ("obj", "ply", "stl"))
        nv, nt = patches * N * N, patches * 2 * (N - 1) ** 2
        assert obj.points.shape == (nv, 3) and ply.points.shape == (nv, 3), (obj.points.shape, ply.points.shape)
        assert np.array_equal(obj.points, ply.points)
        assert np.array_equal(triangles(obj), triangles(ply)) and len(triangles(obj)) == nt
        corners = stl.points[triangles(stl)].reshape(-1, 3)
        assert len(triangles(stl)) == nt
        # STL is single precision in meshio's reading: compare at that precision
        distance = np.min(np.linalg.norm(corners[:, None, :] - obj.points[None, :, :], axis=2), axis=1)
        assert distance.max() < 1e-5, distance.max()
        print(f"[ok] {label}: OBJ = PLY ({nv} vertices, {nt} triangles, bit for bit); "
              f"STL facets on OBJ vertices (max distance {distance.max():.1e})")
        if patches == 1:
            worst = 0.0
            for i, j in [(0, 0), (1, 2), (3, 3), (5, 1), (6, 6)]:
                out = cli(["eval", "thesis-cubic", "--surface", "--net", NET, "--param", "m=1/2",
                           "--at", f"{i}/{N - 1},{j}/{N - 1}"])
                for k, line in enumerate(out.splitlines()[1:4]):
                    value, _, bound = line.split(" = ")[1].partition(" ± ")
                    err = abs(obj.points[i * N + j][k] - float(value))
                    assert err <= float(bound or 0) + 4e-16, (i, j, k, err, bound)
                    worst = max(worst, err)
            print(f"[ok] vertices = certified eval --surface at (i/{N - 1}, j/{N - 1}) "
                  f"(largest difference {worst:.1e}, within the printed bounds)")
