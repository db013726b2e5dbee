#!/usr/bin/env python3
"""`bccmis render` reads every tetrahedral format that `stuff` and `mesh`
write (spec/cli.md, render; io::read_msh, io::read_vtu): one stuffed mesh
written as .mesh, .vtu and .msh (ASCII and binary) is drawn from each; the
.vtu pictures equal the .mesh picture (the file name aside), and the .msh
picture has the same triangles at the same places (a .msh carries no
levels: they are drawn as level 0). Malformed files are refused with exit 2
and `FILE:LINE:COLUMN: message`.

Usage: render_readers_test.py BCCMIS
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail  # noqa: E402


def render(bccmis, path, d):
    svg = path + ".svg"
    r = subprocess.run([bccmis, "render", path, "-o", svg], capture_output=True, text=True)
    if r.returncode != 0:
        fail("render %s: exit %d: %s" % (path, r.returncode, r.stderr))
    return open(svg).read().replace(os.path.basename(path), "MESH")


def refused(bccmis, path, pattern):
    r = subprocess.run([bccmis, "render", path, "-o", path + ".svg"], capture_output=True, text=True)
    if r.returncode != 2 or not re.search(pattern, r.stderr) or os.path.exists(path + ".svg"):
        fail("render %s: exit %d, stderr %r (expected 2 and %r)" % (path, r.returncode, r.stderr, pattern))


def main():
    if len(sys.argv) != 2:
        fail("usage: render_readers_test.py BCCMIS")
    bccmis = sys.argv[1]
    with tempfile.TemporaryDirectory() as d:
        s = os.path.join(d, "s")
        shape = [bccmis, "stuff", "--shape", "torus", "-L", "3", "--cells", "2", "--quiet"]
        subprocess.run(shape + ["-o", s + ".mesh", "-o", s + ".vtu", "-o", s + ".msh"], check=True)
        subprocess.run(shape + ["--binary", "-o", s + "-b.vtu", "-o", s + "-b.msh"], check=True)
        subprocess.run(shape + ["--compress", "-o", s + "-z.vtu"], check=True)
        medit = render(bccmis, s + ".mesh", d)
        if medit.count('class="tri"') < 100:
            fail("the .mesh picture has %d triangles" % medit.count('class="tri"'))
        for vtu in (s + ".vtu", s + "-b.vtu", s + "-z.vtu"):
            if render(bccmis, vtu, d) != medit:
                fail("%s is drawn differently from the .mesh" % vtu)

        def places(svg):
            return sorted(re.findall(r'class="tri" data-level="\d+" points="([^"]*)"', svg))
        for msh in (s + ".msh", s + "-b.msh"):
            if places(render(bccmis, msh, d)) != places(medit):
                fail("%s's triangles are drawn elsewhere than the .mesh's" % msh)
        print("render: .mesh, .vtu (ASCII, binary, zlib) and .msh (ASCII, binary) drawn alike")

        text = open(s + ".msh").read()
        bad = os.path.join(d, "truncated.msh")
        open(bad, "w").write(text[: text.index("$EndNodes")])
        refused(bccmis, bad, r"^bccmis: .*truncated\.msh:\d+:\d+: expected '\$EndNodes', got ''")
        binary = open(s + "-b.msh", "rb").read()
        cut = os.path.join(d, "cut.msh")
        open(cut, "wb").write(binary[: binary.index(b"$EndNodes") - 8])
        refused(bccmis, cut, r"cut\.msh:\d+:\d+: unexpected end of file: expected a coordinate")
        vtu = open(s + ".vtu").read()
        conn = vtu.index('Name="connectivity" format="ascii">\n') + len('Name="connectivity" format="ascii">\n')
        first = vtu[conn:vtu.index("\n", conn)].split()
        flipped = os.path.join(d, "flipped.vtu")
        open(flipped, "w").write(vtu[:conn] + " ".join([first[1], first[0]] + first[2:]) + vtu[vtu.index("\n", conn):])
        refused(bccmis, flipped, r"flipped\.vtu:\d+:\d+: cell 0 is negatively oriented")
        z = open(s + "-z.vtu").read()
        lz4 = os.path.join(d, "lz4.vtu")
        open(lz4, "w").write(z.replace("vtkZLibDataCompressor", "vtkLZ4DataCompressor"))
        refused(bccmis, lz4, r"lz4\.vtu:2:1: compressor 'vtkLZ4DataCompressor': read uncompressed files and "
                             r"vtkZLibDataCompressor")
        # One base64 digit of the compressed connectivity changed: zlib's checksum fails.
        body = z.index("\n", z.index('Name="connectivity" format="binary">')) + 1
        at = (body + z.index("\n", body)) // 2  # inside the compressed blocks, past the short header
        spoilt = os.path.join(d, "spoilt.vtu")
        open(spoilt, "w").write(z[:at] + ("A" if z[at] != "A" else "B") + z[at + 1:])
        refused(bccmis, spoilt, r"spoilt\.vtu:\d+:\d+: compressed block \d+ does not inflate to \d+ bytes")
        print("render: malformed .msh and .vtu (also compressed) refused with their place")
    print("ok")


if __name__ == "__main__":
    main()
