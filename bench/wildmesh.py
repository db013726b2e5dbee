"""Triangle files in the wild, read and measured independently of bccmis
(issue 27): readers for OFF, STL (ASCII and binary), PLY (ASCII) and OBJ,
simple topological flaws, the generalized winding number of a triangle soup
and the volume of the solid {q : w(q) >= 1/2} by sampling, and the
tetrahedra of a .vtu / TetGen .node/.ele with their volume, orientation and
dihedral angles. numpy only. Used by bench/stuff_wild.py and
tests/stuff/wild_files_test.py.

The generalized winding number (Jacobson, Kavan, Sorkine-Hornung 2013) of a
point q is w(q) = sum over triangles of Omega(q) / (4 pi), Omega the signed
solid angle of Van Oosterom and Strackee (1983): with a, b, c the corners
minus q, tan(Omega / 2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| +
(c.a)|b|). Every term is written through point-triangle inner products so
that a chunk of points against all triangles is a few matrix products.
"""
import math
import re
import struct

import numpy as np


class ReadError(Exception):
    pass


# ---- Readers: (points n x 3 float64, triangles m x 3 int64; polygons fanned) --

def _fan(polys):
    tris = []
    for p in polys:
        for k in range(1, len(p) - 1):
            tris.append((p[0], p[k], p[k + 1]))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)


def read_off(path):
    with open(path, "r", errors="replace") as f:
        tokens_lines = [l.split("#")[0].split() for l in f]
    lines = [l for l in tokens_lines if l]
    if not lines:
        raise ReadError("empty file")
    head = lines.pop(0)
    if "OFF" not in head[0]:
        raise ReadError("not an OFF file")
    counts = head[1:] if len(head) > 1 else lines.pop(0)
    nv, nf = int(counts[0]), int(counts[1])
    if len(lines) < nv + nf:
        raise ReadError("truncated")
    pts = np.array([[float(x) for x in l[:3]] for l in lines[:nv]], dtype=np.float64).reshape(-1, 3)
    polys = []
    for l in lines[nv:nv + nf]:
        n = int(l[0])
        polys.append([int(x) for x in l[1:1 + n]])
    tris = _fan(polys)
    if tris.size and (tris.min() < 0 or tris.max() >= nv):
        raise ReadError("face index out of range")
    return pts, tris


def read_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            rec = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                                count=n, offset=84)
            v = rec["v"].astype(np.float64).reshape(-1, 3)
            return _weld(v)
    text = data.decode("ascii", errors="replace")
    nums = re.findall(r"vertex\s+(\S+)\s+(\S+)\s+(\S+)", text)
    if not nums or len(nums) % 3:
        raise ReadError("not an STL file")
    v = np.array(nums, dtype=np.float64)
    return _weld(v)


def _weld(v):
    """Corners of STL facets (3 per facet) to shared points (exact matches)."""
    pts, inv = np.unique(v, axis=0, return_inverse=True)
    return pts, inv.reshape(-1, 3).astype(np.int64)


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ReadError("not a PLY file")
    header = data[:end].decode("ascii", errors="replace").splitlines()
    body = data[data.index(b"\n", end) + 1:]
    if not any(l.startswith("format ascii") for l in header):
        raise ReadError("binary PLY not read")
    elements = []  # (name, count, [property names], list?)
    for l in header:
        t = l.split()
        if t and t[0] == "element":
            elements.append([t[1], int(t[2]), []])
        elif t and t[0] == "property" and elements:
            elements[-1][2].append(t[1:])
    lines = body.decode("ascii", errors="replace").split("\n")
    lines = [l.split() for l in lines if l.strip()]
    pos, pts, polys = 0, None, []
    for name, count, props in elements:
        rows = lines[pos:pos + count]
        pos += count
        if name == "vertex":
            names = [p[-1] for p in props]
            ix = [names.index(c) for c in ("x", "y", "z")]
            pts = np.array([[float(r[i]) for i in ix] for r in rows], dtype=np.float64).reshape(-1, 3)
        elif name == "face":
            for r in rows:  # the first property is the index list
                n = int(r[0])
                polys.append([int(x) for x in r[1:1 + n]])
    if pts is None:
        raise ReadError("no vertices")
    return pts, _fan(polys)


def read_obj(path):
    pts, polys = [], []
    with open(path, "r", errors="replace") as f:
        for l in f:
            t = l.split()
            if not t:
                continue
            if t[0] == "v":
                pts.append([float(x) for x in t[1:4]])
            elif t[0] == "f":
                idx = []
                for s in t[1:]:
                    i = int(s.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(pts) + i)
                polys.append(idx)
    return np.array(pts, dtype=np.float64).reshape(-1, 3), _fan(polys)


def read_mesh(path):
    ext = path.rsplit(".", 1)[-1].lower()
    reader = {"off": read_off, "stl": read_stl, "ply": read_ply, "obj": read_obj}.get(ext)
    if reader is None:
        raise ReadError("unknown extension")
    try:
        return reader(path)
    except (ValueError, IndexError, struct.error) as e:
        raise ReadError(str(e))


def write_off(path, pts, tris):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        for p in pts:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in tris:
            f.write("3 %d %d %d\n" % tuple(t))


# ---- Simple flaws (no self-intersection test: that needs exact predicates) ----

def flaws(pts, tris):
    """Counts: zero-area faces, border edges (used once), non-manifold edges
    (used 3+ times), inconsistently oriented edges (two faces traverse it in
    the same direction), non-finite coordinates; and the area of the
    triangles and of fans closing the border loops (see hole_cap_area)."""
    out = {"triangles": int(len(tris)), "points": int(len(pts))}
    out["nonfinite_points"] = int((~np.isfinite(pts)).any(axis=1).sum())
    if len(tris) == 0:
        out.update(zero_area=0, border_edges=0, nonmanifold_edges=0, misoriented_edges=0, area=0.0,
                   cap_area=0.0)
        return out
    p = np.nan_to_num(pts)
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    dbl = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    scale = max(np.ptp(p, axis=0).max(), 1e-300)
    degenerate = (tris[:, 0] == tris[:, 1]) | (tris[:, 1] == tris[:, 2]) | (tris[:, 2] == tris[:, 0])
    out["zero_area"] = int(((dbl <= 1e-14 * scale * scale) | degenerate).sum())
    out["area"] = float(dbl.sum() / 2)
    t = tris[~degenerate]
    directed = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    und = np.sort(directed, axis=1)
    keys, inv, count = np.unique(und, axis=0, return_inverse=True, return_counts=True)
    inv = inv.reshape(-1)
    out["border_edges"] = int((count == 1).sum())
    out["nonmanifold_edges"] = int((count > 2).sum())
    forward = (directed[:, 0] < directed[:, 1]).astype(np.int64)
    fw = np.bincount(inv, weights=forward, minlength=len(keys))
    two = count == 2
    out["misoriented_edges"] = int((two & (fw != 1)).sum())
    out["cap_area"] = hole_cap_area(p, keys[count == 1])
    return out


def hole_cap_area(p, border):
    """The area of fans closing each connected set of border edges from its
    centroid: for a planar hole the area of the hole; the surface
    {w = 1/2} spans the holes of an open mesh, so the volume tolerance
    counts this area with the triangles'."""
    if len(border) == 0:
        return 0.0
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for u, v in border:
        ru, rv = find(int(u)), find(int(v))
        if ru != rv:
            parent[ru] = rv
    comp = np.array([find(int(u)) for u in border[:, 0]])
    total = 0.0
    for r in np.unique(comp):
        e = border[comp == r]
        verts = np.unique(e)
        cen = p[verts].mean(axis=0)
        total += float(np.linalg.norm(np.cross(p[e[:, 0]] - cen, p[e[:, 1]] - cen), axis=1).sum() / 2)
    return total


# ---- Generalized winding number and the volume of {w >= 1/2} -----------------

class Winding:
    def __init__(self, pts, tris):
        good = np.isfinite(pts).all(axis=1)
        tris = tris[good[tris].all(axis=1)]
        self.lo = pts[good].min(axis=0) if good.any() else np.zeros(3)
        self.hi = pts[good].max(axis=0) if good.any() else np.zeros(3)
        self.center = (self.lo + self.hi) / 2
        self.scale = max(float(np.max(self.hi - self.lo)) / 2, 1e-300)
        q = (np.nan_to_num(pts) - self.center) / self.scale  # about unit size: no cancellation far from 0
        v0, v1, v2 = q[tris[:, 0]], q[tris[:, 1]], q[tris[:, 2]]
        self.V = [v0, v1, v2]
        self.sq = [np.einsum("ij,ij->i", v, v) for v in self.V]
        self.d01 = np.einsum("ij,ij->i", v0, v1)
        self.d12 = np.einsum("ij,ij->i", v1, v2)
        self.d20 = np.einsum("ij,ij->i", v2, v0)
        self.N = np.cross(v0, v1) + np.cross(v1, v2) + np.cross(v2, v0)
        self.D0 = np.einsum("ij,ij->i", v0, np.cross(v1, v2))
        self.T = len(tris)

    def __call__(self, points, chunk_pairs=2_000_000):
        """w at the given points (model coordinates)."""
        q = (np.asarray(points, dtype=np.float64) - self.center) / self.scale
        out = np.empty(len(q))
        if self.T == 0:
            out[:] = 0
            return out
        step = max(1, chunk_pairs // self.T)
        v0, v1, v2 = self.V
        for s in range(0, len(q), step):
            p = q[s:s + step]
            pp = np.einsum("ij,ij->i", p, p)[:, None]
            p0, p1, p2 = p @ v0.T, p @ v1.T, p @ v2.T
            la = np.sqrt(np.maximum(self.sq[0] - 2 * p0 + pp, 0))
            lb = np.sqrt(np.maximum(self.sq[1] - 2 * p1 + pp, 0))
            lc = np.sqrt(np.maximum(self.sq[2] - 2 * p2 + pp, 0))
            ab = self.d01 - p0 - p1 + pp
            bc = self.d12 - p1 - p2 + pp
            ca = self.d20 - p2 - p0 + pp
            det = self.D0 - p @ self.N.T
            den = la * lb * lc + ab * lc + bc * la + ca * lb
            out[s:s + step] = np.arctan2(det, den).sum(axis=1) / (2 * math.pi)
        return out


def signed_volume(pts, tris):
    """The volume the triangles enclose by the divergence theorem (negative for
    a closed surface oriented inward)."""
    if len(tris) == 0:
        return 0.0
    p = np.nan_to_num(pts)
    c = (p.min(axis=0) + p.max(axis=0)) / 2 if len(p) else np.zeros(3)
    a, b, d = p[tris[:, 0]] - c, p[tris[:, 1]] - c, p[tris[:, 2]] - c
    return float(np.einsum("ij,ij->i", a, np.cross(b, d)).sum() / 6)


def orient_consistently(pts, tris):
    """The faces flipped so that, across every edge of exactly two faces, the
    two traverse it in opposite directions (breadth-first over those edges,
    each component from its first face), then every component flipped as a
    whole so that it is oriented outward when an even number of the other
    components enclose it and inward when an odd number do (nesting parity:
    the outward-oriented components' winding number at one of its vertices,
    summed, is the count). This is the repair bccmis applies to an
    inconsistently oriented soup before its winding number (spec/stuffing.md
    S21), written here independently so that the volume check of such a file
    measures the solid the user means rather than a winding number near 0.
    A component whose faces cannot all be made consistent (a Moebius-like
    band) keeps the first orientation reached."""
    t = np.array(tris, dtype=np.int64).copy()
    m = len(t)
    if m == 0:
        return t
    edges = {}
    for f in range(m):
        for k in range(3):
            a, b = int(t[f, k]), int(t[f, (k + 1) % 3])
            edges.setdefault((min(a, b), max(a, b)), []).append(f)
    comp = -np.ones(m, dtype=np.int64)
    ncomp = 0
    for seed in range(m):
        if comp[seed] >= 0:
            continue
        comp[seed] = ncomp
        queue = [seed]
        while queue:
            f = queue.pop()
            for k in range(3):
                a, b = int(t[f, k]), int(t[f, (k + 1) % 3])
                faces = edges[(min(a, b), max(a, b))]
                if len(faces) != 2:
                    continue
                g = faces[0] if faces[1] == f else faces[1]
                if comp[g] >= 0:
                    continue
                comp[g] = ncomp
                # g must run from b to a: if it runs from a to b, flip it.
                row = [int(x) for x in t[g]]
                if any(row[j] == a and row[(j + 1) % 3] == b for j in range(3)):
                    t[g] = t[g][::-1]
                queue.append(g)
        ncomp += 1
    parts = [t[comp == c] for c in range(ncomp)]
    for c in range(ncomp):
        if signed_volume(pts, parts[c]) < 0:
            parts[c] = parts[c][:, ::-1]
    outward = [Winding(pts, part) for part in parts]
    p = np.nan_to_num(pts)
    depth = [sum(outward[d](p[parts[c][0, 0]][None, :])[0] >= 0.5 for d in range(ncomp) if d != c)
             for c in range(ncomp)]
    return np.concatenate([part[:, ::-1] if depth[c] % 2 else part for c, part in enumerate(parts)])


def winding_volume(pts, tris, n_points, seed=1):
    """Volume of {s w >= 1/2}, s = -1 when the triangles' signed volume is
    negative (a surface oriented inward as a whole, which bccmis meshes as
    the solid it bounds), else 1: one uniform point in each cell of a k x k x k
    grid over the bounding box (k^3 ~ n_points; jittered, i.e. stratified
    sampling). The estimate is unbiased; its variance is at most the
    binomial p(1-p)/N of N independent uniform points (stratification with
    equal strata never increases it), so the binomial standard error
    reported is an upper bound. A flat bounding box (zero volume) gives 0.
    Triangles with inconsistently oriented edges are first oriented as
    bccmis orients them (orient_consistently)."""
    if len(tris) and flaws(pts, tris)["misoriented_edges"]:
        tris = orient_consistently(pts, tris)
    w = Winding(pts, tris)
    lo, hi = w.lo, w.hi
    ext = hi - lo
    box = float(np.prod(ext))
    if not box > 0:
        return 0.0, 0.0, 0, box
    k = max(2, int(round(n_points ** (1 / 3))))
    rng = np.random.default_rng(seed)
    g = np.stack(np.meshgrid(np.arange(k), np.arange(k), np.arange(k), indexing="ij"), -1).reshape(-1, 3)
    u = (g + rng.random(g.shape)) / k
    q = lo + u * ext
    sign = -1.0 if signed_volume(pts, tris) < 0 else 1.0
    inside = sign * w(q) >= 0.5
    n = len(q)
    frac = inside.mean()
    se = math.sqrt(max(frac * (1 - frac), 0.25 / n) / n) * box  # floor: one point's worth
    return frac * box, se, n, box


# ---- Tetrahedra: volume, orientation, dihedral angles --------------------------

def vtu_tets(path):
    """Points and tetrahedra of an ASCII .vtu (as bccmis writes it)."""
    with open(path) as f:
        text = f.read()
    arrays = {}
    for m in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        attrs, body = m.group(1), m.group(2)
        name = re.search(r'Name="([^"]*)"', attrs)
        key = name.group(1) if name else "Points"
        if 'format="ascii"' not in attrs:
            raise ReadError("%s: only ASCII .vtu is read" % path)
        arrays[key] = body
    pts = np.array(arrays["Points"].split(), dtype=np.float64).reshape(-1, 3)
    conn = np.array(arrays["connectivity"].split(), dtype=np.int64)
    types = np.array(arrays["types"].split(), dtype=np.int64)
    if len(types) and not (types == 10).all():
        raise ReadError("%s: cells other than tetrahedra" % path)
    return pts, conn.reshape(-1, 4)


def tetgen_tets(stem):
    def body(path):
        with open(path) as f:
            rows = [l.split("#")[0].split() for l in f]
        rows = [r for r in rows if r]
        return rows[0], rows[1:]

    h, rows = body(stem + ".node")
    n = int(h[0])
    base = int(rows[0][0]) if rows else 0
    pts = np.array([r[1:4] for r in rows[:n]], dtype=np.float64).reshape(-1, 3)
    h, rows = body(stem + ".ele")
    m = int(h[0])
    tets = np.array([r[1:5] for r in rows[:m]], dtype=np.int64).reshape(-1, 4) - base
    return pts, tets


def tet_quality(pts, tets):
    """tetrahedra, volume (sum of signed volumes), non-positive count, min and
    max dihedral angle in degrees."""
    if len(tets) == 0:
        return {"tetrahedra": 0, "volume": 0.0, "inverted": 0, "min_dihedral": None, "max_dihedral": None}
    a, b, c, d = (pts[tets[:, i]] for i in range(4))
    six = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))
    corners = [a, b, c, d]
    # Outward normal of the face opposite corner i, for a positive tetrahedron.
    faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]
    normals = []
    for (i, j, k) in faces:
        n = np.cross(corners[j] - corners[i], corners[k] - corners[i])
        n /= np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None]
        normals.append(n)
    ang = []
    for i in range(4):
        for j in range(i + 1, 4):
            cosij = np.clip(np.einsum("ij,ij->i", normals[i], normals[j]), -1, 1)
            ang.append(180 - np.degrees(np.arccos(cosij)))
    ang = np.stack(ang)
    return {"tetrahedra": int(len(tets)), "volume": float(six.sum() / 6), "inverted": int((six <= 0).sum()),
            "min_dihedral": float(ang.min()), "max_dihedral": float(ang.max())}
