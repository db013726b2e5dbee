#!/usr/bin/env python3
"""Checks the citations between code, tests and spec/ (ctest label `spec`).

A citation is a block of consecutive comment lines:

    //= erleben2009#<id>                 the equation (spec/equations.toml)
    //= type=deviation                   optional; then also
    //= reason=<erratum>: <one line>     an entry of spec/errata.toml
    //# <quote>                          the equation's `text`, verbatim

Several `//#` lines in a row form one quote (joined by a space). A quote must
equal the `text` of the equation cited above it, the whole text, after
normalisation: Unicode NFC, every run of white space one space, none at the
ends. Nothing else is normalised (no symbol variants, no case): a quote that
does not read as the text reads is a drifted quote.

Fails (exit 1, one line per problem) when
  - an equation with role = "update" has no implementation citation in src/;
  - an equation (any role) has no test citation in tests/;
  - a citation names an id that spec/equations.toml does not define;
  - a citation in src/ has no quote, or a quote (in src/ or tests/) differs
    from the equation's text, or a `//#` line follows no citation;
  - a `reason=` names an erratum that spec/errata.toml does not define, or one
    that the cited equation does not list in its `errata`; a deviation has no
    reason, or a reason no `type=deviation`;
  - an equation's `errata` and an erratum's `equations` disagree (each must
    list the other; entries of kind "position" list equations only);
  - an erratum lists a test (Suite.Name) that no file in tests/ defines.

The 3D lattice's own equations (spec/equations3d.toml, cited as
`//= bccmis3d#<id>`) are checked by the same rules against their own tables:
a `reason=<id>` there names an entry of spec/choices3d.toml, and since the 3D
equations are ours, a reason needs no `type=deviation`.
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
import unicodedata

here = pathlib.Path(__file__).resolve()

if sys.argv[1:2] == ["--self-test"]:
    # The check must be able to fail: plant each kind of problem in a copy of
    # the tree and expect a non-zero exit naming it.
    plants = [
        ("src/bccmis/refine.cpp", "//= erleben2009#eq-4c\n", "", "'eq-4c' has no implementation citation"),
        ("tests/refine_test.cpp", "//= erleben2009#eq-4d type=test", "//= erleben2009#eq-4z type=test", "unknown id 'eq-4z'"),
        ("src/bccmis/coarsen.cpp", "reason=E2:", "reason=E99:", "unknown erratum 'E99'"),
        ("src/bccmis/refine.cpp", "reason=E4:", "reason=E1:", "'eq-3' does not list erratum 'E1'"),
        ("src/bccmis/refine.cpp", "//= reason=E4:", "// reason=E4:", "deviation without a reason"),
        ("tests/errata_test.cpp", "E4_DiagonalCoarserCellDoesNotBlockRefinement", "E4_Renamed", "lists test"),
        # A quote that drifts from the spec, in the code or in the spec.
        ("src/bccmis/refine.cpp", "//# N(c) = Y\n", "//# N(c) = Y ∪ {c}\n", "quote of 'eq-4c' differs"),
        ("src/bccmis/coarsen.cpp", "//# N(n) = B\n", "//# N(n) = B \\ {n}\n", "quote of 'eq-12a' differs"),
        ("spec/equations.toml", 'text = "N(c) = Y"', 'text = "N(c) = {y_1, y_2, y_3, y_4}"', "quote of 'eq-4c' differs"),
        ("src/bccmis/refine.cpp", "//# ||P|| = 4 and ||Y|| = 4\n", "//# ||P|| = 4\n", "quote of 'claim-P-has-4' differs"),
        ("src/bccmis/refine.cpp", "  //# C = C ∪ Y\n", "", "'eq-4b' has no quote"),
        ("src/bccmis/refine.cpp", "  //= erleben2009#eq-4b\n", "", "quote follows no citation"),
        ("spec/errata.toml", '"eq-11d"]', '"eq-11c"]', "lists erratum 'E9', which does not list it"),
        # The 3D equations (spec/equations3d.toml) and choices (spec/choices3d.toml).
        ("src/bccmis/d3/refine.cpp", "//= bccmis3d#eq-R2c\n", "", "'bccmis3d#eq-R2c' has no implementation citation"),
        ("tests/d3/coarsen_test.cpp", "//= bccmis3d#eq-K2d type=test", "//= bccmis3d#eq-K2d-x type=test",
         "unknown id 'bccmis3d#eq-K2d-x'"),
        ("tests/d3/coarsen_test.cpp", "//= bccmis3d#eq-K2d type=test\n", "", "'bccmis3d#eq-K2d' has no test citation"),
        ("src/bccmis/d3/coarsen.cpp", "//# J- = { b in M : level(x) <= l", "//# J- = { b in M : level(x) < l",
         "quote of 'bccmis3d#eq-K3a' differs"),
        ("src/bccmis/d3/coarsen.cpp", "reason=V3:", "reason=V9:", "unknown erratum 'V9'"),
        ("tests/d3/refusals_test.cpp", "TEST(D3Refusals, MaxLevel)", "TEST(D3Refusals, MaxLevelRenamed)",
         "choice V5 lists test"),
    ]
    src_root = here.parent.parent
    failures = 0
    for path, old, new, expected in plants:
        with tempfile.TemporaryDirectory() as tmp:
            for d in ("src", "tests", "spec"):
                shutil.copytree(src_root / d, pathlib.Path(tmp) / d)
            p = pathlib.Path(tmp) / path
            text = p.read_text()
            assert old in text, f"self-test plant not found: {old!r} in {path}"
            p.write_text(text.replace(old, new, 1))
            r = subprocess.run([sys.executable, str(here), tmp], capture_output=True, text=True)
            ok = r.returncode == 1 and expected in r.stdout
            print(("caught" if ok else "MISSED") + f": {expected}")
            failures += not ok
    sys.exit(1 if failures else 0)

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else here.parent.parent)


def load(name, key):
    return tomllib.loads((root / "spec" / name).read_text())[key]


class Namespace:
    """One citation namespace: its equations, its errata (or choices), and
    the ids cited by src/ and by tests/."""

    def __init__(self, name, equations_file, equations, errata_file, errata, errata_kind, deviations):
        self.name, self.equations_file, self.errata_file = name, equations_file, errata_file
        self.equations, self.errata, self.errata_kind = equations, errata, errata_kind
        self.by_id = {e["id"]: e for e in equations}
        self.errata_by_id = {e["id"]: e for e in errata}
        self.deviations = deviations  # a reason needs `type=deviation` (the paper's equations)
        self.impl, self.tested = set(), set()

    def label(self, eid):
        return eid if self.name == "erleben2009" else f"{self.name}#{eid}"


namespaces = {
    "erleben2009": Namespace("erleben2009", "equations.toml", load("equations.toml", "eq"), "errata.toml",
                             load("errata.toml", "erratum"), "erratum", True),
    "bccmis3d": Namespace("bccmis3d", "equations3d.toml", load("equations3d.toml", "eq"), "choices3d.toml",
                          load("choices3d.toml", "choice"), "choice", False),
}

def normalise(text):
    return " ".join(unicodedata.normalize("NFC", text).split())


cite = re.compile(r"^\s*//= (erleben2009|bccmis3d)#([A-Za-z0-9-]+)(.*)$")
attribute = re.compile(r"^\s*//= (.*)$")
quote = re.compile(r"^\s*//#(?: (.*))?$")
reason = re.compile(r"reason=([^:\s]+)")
problems = []


def check_citation(c, is_test):
    """c: the citation's namespace, id, location, attribute text and quote lines."""
    ns, eid, where, attrs, quote_lines = namespaces[c["ns"]], c["id"], c["where"], " ".join(c["attrs"]), c["quote"]
    label = ns.label(eid)
    if eid not in ns.by_id:
        problems.append(f"{where}: citation of unknown id '{label}'")
        return
    (ns.tested if "type=test" in attrs else ns.impl).add(eid)
    if is_test and "type=test" not in attrs:
        problems.append(f"{where}: citation in a test without 'type=test'")
    if quote_lines:
        q, t = normalise(" ".join(quote_lines)), normalise(ns.by_id[eid]["text"])
        if q != t:
            problems.append(f"{where}: quote of '{label}' differs from spec/{ns.equations_file}: '{q}' != '{t}'")
    elif not is_test:
        problems.append(f"{where}: citation of '{label}' has no quote (//# and the equation's text)")
    reasons = reason.findall(attrs)
    if "type=deviation" in attrs and not reasons:
        problems.append(f"{where}: deviation without a reason (//= reason=<erratum>: ...)")
    if ns.deviations and reasons and "type=deviation" not in attrs:
        problems.append(f"{where}: reason without '//= type=deviation'")
    for r in reasons:
        if r not in ns.errata_by_id:
            problems.append(f"{where}: reason names unknown erratum '{r}'")
        elif r not in ns.by_id[eid].get("errata", []):
            problems.append(f"{where}: reason {r}, but spec/{ns.equations_file} '{eid}' does not list "
                            f"{ns.errata_kind} '{r}'")


def scan(folder, is_test):
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".h") or not path.is_file():
            continue
        current = None  # the citation whose block is open
        for lineno, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            where = f"{path.relative_to(root)}:{lineno}"
            if m := cite.match(line):
                if current:
                    check_citation(current, is_test)
                current = {"ns": m.group(1), "id": m.group(2), "where": where, "attrs": [m.group(3)], "quote": []}
            elif current and not current["quote"] and (m := attribute.match(line)):
                current["attrs"].append(m.group(1))
            elif m := quote.match(line):
                if current:
                    current["quote"].append(m.group(1) or "")
                else:
                    problems.append(f"{where}: quote follows no citation (//= erleben2009#<id> above it)")
            else:
                if current:
                    check_citation(current, is_test)
                current = None
                if "//= reason=" in line or "//= type=" in line:
                    problems.append(f"{where}: '//=' line outside a citation")
        if current:
            check_citation(current, is_test)


scan("src", False)
scan("tests", True)

test_text = "\n".join(p.read_text(errors="replace") for p in (root / "tests").rglob("*.cpp"))
for ns in namespaces.values():
    for e in ns.equations:
        label = ns.label(e["id"])
        if e["role"] == "update" and e["id"] not in ns.impl:
            problems.append(f"spec/{ns.equations_file}: update equation '{label}' has no implementation citation in src/")
        if e["id"] not in ns.tested:
            problems.append(f"spec/{ns.equations_file}: '{label}' has no test citation in tests/")
        for r in e.get("errata", []):
            if r not in ns.errata_by_id:
                problems.append(f"spec/{ns.equations_file}: '{label}' lists unknown {ns.errata_kind} '{r}'")
            elif e["id"] not in ns.errata_by_id[r].get("equations", []):
                problems.append(f"spec/{ns.equations_file}: '{label}' lists {ns.errata_kind} '{r}', which does not list it")
    for e in ns.errata:
        for eid in e.get("equations", []):
            if eid not in ns.by_id:
                problems.append(f"spec/{ns.errata_file}: {ns.errata_kind} {e['id']} lists unknown equation '{eid}'")
            elif e["kind"] != "position" and e["id"] not in ns.by_id[eid].get("errata", []):
                problems.append(f"spec/{ns.errata_file}: {ns.errata_kind} {e['id']} lists '{eid}', "
                                "whose errata do not include it")
        for t in e.get("tests", []):
            suite, name = t.split(".", 1)
            if not re.search(rf"TEST(_F|_P)?\(\s*{re.escape(suite)}\s*,\s*{re.escape(name)}\s*\)", test_text):
                problems.append(f"spec/{ns.errata_file}: {ns.errata_kind} {e['id']} lists test '{t}', "
                                "which tests/ does not define")

for p in problems:
    print(p)
summary = "; ".join(
    f"{ns.name}: {len(ns.by_id)} equations, {len(ns.impl & set(ns.by_id))} cited by src/, "
    f"{len(ns.tested & set(ns.by_id))} by tests/, {len(ns.errata_by_id)} {ns.errata_kind} entries"
    for ns in namespaces.values())
print(f"spec coverage: {summary}; {len(problems)} problems")
sys.exit(1 if problems else 0)
