#!/usr/bin/env python3
"""Outputs fail early and leave nothing (spec/cli.md, "Outputs"):
- an output that cannot be created (a directory that does not exist, a
  path under a regular file) ends `bccmis stuff` with exit 2 and one line
  naming the file and the reason (strerror), before any meshing: no
  progress line is printed and no other output or temporary is left;
- SIGTERM or SIGINT while `bccmis stuff` meshes (its temporaries already
  exist: they are created before the meshing) ends it by that signal and
  leaves no temporary and no output;
- under --animate the .pvd's temporary is made before the meshing and each
  frame's as the frame is written: while frame 1's exists, frame 2's and
  3's do not; SIGTERM then leaves no temporary and no output.

Usage: outputs_early_test.py BCCMIS
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail  # noqa: E402

# A sphere at level 4: a few seconds of meshing in a Debug build.
SHAPE = ["stuff", "--shape", "sphere", "-L", "4"]


def unwritable(bccmis, d):
    for bad, reason in (("/nonexistent-bccmis-dir/x.vtu", "No such file or directory"),
                        ("/etc/passwd/x.msh", "Not a directory")):
        ok = os.path.join(d, "ok.vtu")
        r = subprocess.run([bccmis] + SHAPE + ["-o", ok, "-o", bad], capture_output=True, text=True)
        want = "bccmis: %s: cannot create a temporary file in %s: %s" % (bad, os.path.dirname(bad), reason)
        if r.returncode != 2 or r.stderr.strip() != want:
            fail("-o %s: exit %d, stderr %r (expected 2 and only %r)" % (bad, r.returncode, r.stderr, want))
        if os.listdir(d):
            fail("-o %s: left %s" % (bad, os.listdir(d)))
    print("unwritable outputs: exit 2 with the reason, before meshing, nothing left")


def temporaries_until(p, d, ready, what, timeout=60):
    """The temporaries in d once ready(them) holds, polled while bccmis runs."""
    deadline = time.monotonic() + timeout
    while True:
        temporaries = sorted(f for f in os.listdir(d) if ".tmp-" in f)
        if ready(temporaries):
            return temporaries
        if p.poll() is not None or time.monotonic() > deadline:
            p.kill()
            p.wait()
            fail("%s did not appear while bccmis ran (exit %s)" % (what, p.returncode))
        time.sleep(0.001)


def ended_by(p, d, sig, what):
    """Sends sig: bccmis must end by it and leave nothing in d."""
    p.send_signal(sig)
    p.wait(timeout=60)
    if p.returncode != -sig:
        fail("%s%s: bccmis ended with %d, not by the signal" % (what, sig.name, p.returncode))
    if os.listdir(d):
        fail("%s%s: left %s" % (what, sig.name, os.listdir(d)))


def interrupted(bccmis, d, sig):
    outs = [os.path.join(d, "a.vtu"), os.path.join(d, "b.msh")]
    p = subprocess.Popen([bccmis] + SHAPE + ["--quiet", "-o", outs[0], "-o", outs[1]])
    temporaries_until(p, d, lambda t: len(t) >= 2, "%s: the two temporaries" % sig.name)
    ended_by(p, d, sig, "")
    print("%s while meshing: ended by the signal, nothing left" % sig.name)


def animated(bccmis, d, sig):
    p = subprocess.Popen([bccmis] + SHAPE + ["--animate", "3", "--quiet", "-o", os.path.join(d, "a.pvd")])
    first = temporaries_until(p, d, bool, "--animate: a temporary", timeout=120)
    temporaries = temporaries_until(p, d, lambda t: any(f.startswith(".a_0001.vtu.tmp-") for f in t),
                                    "--animate: frame 1's temporary", timeout=120)
    later = [f for f in temporaries if f.startswith((".a_0002.vtu.tmp-", ".a_0003.vtu.tmp-"))]
    wrong = ("later frames' temporaries %s exist while frame 1 is written" % later if later else
             "the first temporaries were %s, not the .pvd's alone" % first
             if len(first) != 1 or not first[0].startswith(".a.pvd.tmp-") else None)
    if wrong:
        p.kill()
        p.wait()
        fail("--animate: " + wrong)
    ended_by(p, d, sig, "--animate: ")
    print("--animate: the .pvd's temporary first, each frame's as it is written; %s leaves nothing" % sig.name)


def main():
    if len(sys.argv) != 2:
        fail("usage: outputs_early_test.py BCCMIS")
    with tempfile.TemporaryDirectory() as d:
        unwritable(sys.argv[1], d)
        interrupted(sys.argv[1], d, signal.SIGTERM)
        interrupted(sys.argv[1], d, signal.SIGINT)
        animated(sys.argv[1], d, signal.SIGTERM)
    print("ok")


if __name__ == "__main__":
    main()
