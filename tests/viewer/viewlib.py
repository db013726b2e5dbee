"""Helpers of the viewer tests: read the model a `bccmis view` page embeds
(spec/viewer.md), rebuild its states independently of the page's
JavaScript, and ask the CLI for the same states and counts."""
import json
import re
import subprocess


def extract_model(html):
    m = re.search(r'<script type="application/json" id="bccmis-model">(.*?)</script>', html, re.S)
    if not m:
        raise AssertionError("no embedded model in the page")
    return json.loads(m.group(1))


def pairs(flat):
    flat = flat or []
    return [(flat[i], flat[i + 1]) for i in range(0, len(flat), 2)]


def rebuild(model, k, state=None, start=0):
    """The state of step k as {(x, y): record}, from the initial state and the deltas."""
    if state is None:
        state = {(r[0], r[1]): r for r in model["init"]}
    for step in model["steps"][start + 1:k + 1]:
        for p in pairs(step.get("del")):
            if p not in state:
                raise AssertionError("step %s deletes %s, which is not in the state" % (step["label"], p))
            del state[p]
        for r in step.get("set", []):
            state[(r[0], r[1])] = r
    return state


def canonical(model, state):
    """The canonical-state text (spec/formats.md) of a rebuilt state."""
    W, H, L = model["lattice"]
    lines = ["bccmis-state 1", "lattice %d %d %d" % (W, H, L)]
    centers = sorted(p for p, r in state.items() if r[2] >= 0)
    nodes = sorted(p for p, r in state.items() if r[2] < 0)
    for p in centers:
        r = state[p]
        lines.append(("C %d %d %d :" % (p[0], p[1], r[2])) + "".join(" %d" % v for v in r[3:]))
    for p in nodes:
        lines.append(("N %d %d :" % p) + "".join(" %d" % v for v in state[p][3:]))
    lines.append("end %d %d" % (len(centers), len(nodes)))
    return "\n".join(lines) + "\n"


def read_trace(path):
    """(lattice line, [command lines]) of a trace file, comments and blank lines dropped."""
    lattice, commands = None, []
    with open(path) as f:
        for line in f:
            tokens = line.split("#", 1)[0].split()
            if not tokens:
                continue
            if tokens[0] == "lattice":
                lattice = " ".join(tokens)
            else:
                commands.append(" ".join(tokens))
    return lattice, commands


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600, **kw)


class Cli:
    """Prefix replays through the CLI: `stats` and the canonical state of the first k commands."""

    def __init__(self, bccmis, trace, workdir):
        self.bccmis = bccmis
        self.lattice, self.commands = read_trace(trace)
        self.workdir = workdir

    def prefix(self, k):
        path = "%s/prefix_%d.trace" % (self.workdir, k)
        with open(path, "w") as f:
            f.write("\n".join([self.lattice] + self.commands[:k]) + "\n")
        return path

    def stats(self, k):
        p = run([self.bccmis, "stats", "--from-trace", "--json", self.prefix(k)])
        if p.returncode != 0:
            raise AssertionError("bccmis stats failed: " + p.stderr)
        return json.loads(p.stdout)

    def state(self, k):
        p = run([self.bccmis, "replay", "--quiet", "--check=none", self.prefix(k)])
        if p.returncode != 0:
            raise AssertionError("bccmis replay failed: " + p.stderr)
        return p.stdout[p.stdout.index("bccmis-state 1"):]

    def decisions(self):
        p = run([self.bccmis, "replay", "--quiet", "--check=none", self.prefix(len(self.commands))])
        return p.stdout[:p.stdout.index("bccmis-state 1")].splitlines()


def sample_steps(last, every_up_to=40):
    if last <= every_up_to:
        return list(range(last + 1))
    return sorted({0, 1, 2, 3, last // 4, last // 2, (3 * last) // 4, last - 1, last})
