#!/usr/bin/env python3
"""Checks the citations between code, tests and spec/ (ctest label `spec`).

Fails (exit 1, one line per problem) when
  - an equation with role = "update" has no implementation citation in src/;
  - an equation (any role) has no test citation in tests/;
  - a citation names an id that spec/equations.toml does not define;
  - a `reason=E<n>` names an erratum that spec/errata.toml does not define;
  - an erratum lists a test (Suite.Name) that no file in tests/ defines.

The 3D lattice's own equations (spec/equations3d.toml, cited as
`//= bccmis3d#<id>`) are checked the same way, and in addition the `//#` line
under each implementation citation must be the equation's `text`; a
`reason=<id>` may also name an entry of spec/choices3d.toml, whose listed
tests must exist too.
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib

here = pathlib.Path(__file__).resolve()

if sys.argv[1:2] == ["--self-test"]:
    # The check must be able to fail: plant each kind of problem in a copy of
    # the tree and expect a non-zero exit naming it.
    plants = [
        ("src/bccmis/refine.cpp", "//= erleben2009#eq-4c\n", "", "'eq-4c' has no implementation citation"),
        ("tests/refine_test.cpp", "//= erleben2009#eq-4d type=test", "//= erleben2009#eq-4z type=test", "unknown id 'eq-4z'"),
        ("src/bccmis/coarsen.cpp", "reason=E2:", "reason=E9:", "unknown erratum 'E9'"),
        ("tests/errata_test.cpp", "E4_DiagonalCoarserCellDoesNotBlockRefinement", "E4_Renamed", "lists test"),
        ("src/bccmis/d3/refine.cpp", "//= bccmis3d#eq-R2c\n", "", "'bccmis3d#eq-R2c' has no implementation citation"),
        ("tests/d3/coarsen_test.cpp", "//= bccmis3d#eq-K2d type=test", "//= bccmis3d#eq-K2d-x type=test",
         "unknown id 'bccmis3d#eq-K2d-x'"),
        ("tests/d3/coarsen_test.cpp", "//= bccmis3d#eq-K2d type=test\n", "", "'bccmis3d#eq-K2d' has no test citation"),
        ("src/bccmis/d3/coarsen.cpp", "//# J- = { b in M : level(x) <= l", "//# J- = { b in M : level(x) < l",
         "quotes 'bccmis3d#eq-K3a' as"),
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
equations = tomllib.loads((root / "spec/equations.toml").read_text())["eq"]
errata = tomllib.loads((root / "spec/errata.toml").read_text())["erratum"]
ids = {e["id"] for e in equations}
erratum_ids = {e["id"] for e in errata}
# The 3D lattice (spec/lattice3d.md): its equations and its choices.
equations3d = tomllib.loads((root / "spec/equations3d.toml").read_text())["eq"]
choices3d = tomllib.loads((root / "spec/choices3d.toml").read_text())["choice"]
ids3d = {e["id"]: e for e in equations3d}
erratum_ids |= {c["id"] for c in choices3d}

cite = re.compile(r"//= erleben2009#([A-Za-z0-9-]+)(.*)")
reason = re.compile(r"//= reason=([A-Z][0-9]+)")
cite3d = re.compile(r"//= bccmis3d#([A-Za-z0-9-]+)(.*)")
quote = re.compile(r"^\s*//# (.*)$")
problems = []
impl, tested = set(), set()
impl3d, tested3d = set(), set()


def scan(folder, is_test):
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".h") or not path.is_file():
            continue
        pending = None  # a 3D implementation citation waiting for its //# line
        for lineno, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            where = f"{path.relative_to(root)}:{lineno}"
            for m in cite.finditer(line):
                eid, rest = m.group(1), m.group(2)
                if eid not in ids:
                    problems.append(f"{where}: citation of unknown id '{eid}'")
                (tested if "type=test" in rest else impl).add(eid)
                if is_test and "type=test" not in rest:
                    problems.append(f"{where}: citation in a test without 'type=test'")
            for m in reason.finditer(line):
                if m.group(1) not in erratum_ids:
                    problems.append(f"{where}: reason names unknown erratum '{m.group(1)}'")
            # 3D citations; the //# line after an implementation citation
            # (other //= lines may come between) must be the equation's text.
            m = cite3d.search(line)
            if m:
                eid, rest = m.group(1), m.group(2)
                if eid not in ids3d:
                    problems.append(f"{where}: citation of unknown id 'bccmis3d#{eid}'")
                elif "type=test" in rest:
                    tested3d.add(eid)
                else:
                    impl3d.add(eid)
                    pending = (eid, where)
                if is_test and "type=test" not in rest:
                    problems.append(f"{where}: citation in a test without 'type=test'")
            elif pending and quote.match(line):
                eid, cited_at = pending
                text = quote.match(line).group(1)
                if text != ids3d[eid]["text"]:
                    problems.append(f"{cited_at}: quotes 'bccmis3d#{eid}' as '{text}', "
                                    f"spec/equations3d.toml says '{ids3d[eid]['text']}'")
                pending = None
            elif pending and not line.strip().startswith("//="):
                problems.append(f"{pending[1]}: citation of 'bccmis3d#{pending[0]}' without a //# line")
                pending = None


scan("src", False)
scan("tests", True)

for e in equations:
    if e["role"] == "update" and e["id"] not in impl:
        problems.append(f"spec/equations.toml: update equation '{e['id']}' has no implementation citation in src/")
    if e["id"] not in tested:
        problems.append(f"spec/equations.toml: '{e['id']}' has no test citation in tests/")

for e in equations3d:
    if e["role"] == "update" and e["id"] not in impl3d:
        problems.append(f"spec/equations3d.toml: update equation 'bccmis3d#{e['id']}' has no implementation "
                        "citation in src/")
    if e["id"] not in tested3d:
        problems.append(f"spec/equations3d.toml: 'bccmis3d#{e['id']}' has no test citation in tests/")

test_text = "\n".join(p.read_text(errors="replace") for p in (root / "tests").rglob("*.cpp"))
for file, kind, entries in (("errata.toml", "erratum", errata), ("choices3d.toml", "choice", choices3d)):
    for e in entries:
        for t in e.get("tests", []):
            suite, name = t.split(".", 1)
            if not re.search(rf"TEST(_F|_P)?\(\s*{re.escape(suite)}\s*,\s*{re.escape(name)}\s*\)", test_text):
                problems.append(f"spec/{file}: {kind} {e['id']} lists test '{t}', which tests/ does not define")

for p in problems:
    print(p)
print(f"spec coverage: {len(ids)} equations, {len(impl & ids)} cited by src/, {len(tested & ids)} by tests/; "
      f"3D: {len(ids3d)} equations, {len(impl3d & set(ids3d))} cited by src/, {len(tested3d & set(ids3d))} by tests/; "
      f"{len(erratum_ids)} errata and choices; {len(problems)} problems")
sys.exit(1 if problems else 0)
