#!/usr/bin/env python3
"""Checks the citations between code, tests and spec/ (ctest label `spec`).

Fails (exit 1, one line per problem) when
  - an equation with role = "update" has no implementation citation in src/;
  - an equation (any role) has no test citation in tests/;
  - a citation names an id that spec/equations.toml does not define;
  - a `reason=E<n>` names an erratum that spec/errata.toml does not define;
  - an erratum lists a test (Suite.Name) that no file in tests/ defines.
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
        ("src/bccmis/coarsen.cpp", "reason=E2:", "reason=E99:", "unknown erratum 'E99'"),
        ("tests/errata_test.cpp", "E4_DiagonalCoarserCellDoesNotBlockRefinement", "E4_Renamed", "lists test"),
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

cite = re.compile(r"//= erleben2009#([A-Za-z0-9-]+)(.*)")
reason = re.compile(r"//= reason=([A-Z][0-9]+)")
problems = []
impl, tested = set(), set()


def scan(folder, is_test):
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in (".cpp", ".h") or not path.is_file():
            continue
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


scan("src", False)
scan("tests", True)

for e in equations:
    if e["role"] == "update" and e["id"] not in impl:
        problems.append(f"spec/equations.toml: update equation '{e['id']}' has no implementation citation in src/")
    if e["id"] not in tested:
        problems.append(f"spec/equations.toml: '{e['id']}' has no test citation in tests/")

test_text = "\n".join(p.read_text(errors="replace") for p in (root / "tests").rglob("*.cpp"))
for e in errata:
    for t in e.get("tests", []):
        suite, name = t.split(".", 1)
        if not re.search(rf"TEST(_F|_P)?\(\s*{re.escape(suite)}\s*,\s*{re.escape(name)}\s*\)", test_text):
            problems.append(f"spec/errata.toml: erratum {e['id']} lists test '{t}', which tests/ does not define")

for p in problems:
    print(p)
print(f"spec coverage: {len(ids)} equations, {len(impl & ids)} cited by src/, {len(tested & ids)} by tests/, "
      f"{len(erratum_ids)} errata; {len(problems)} problems")
sys.exit(1 if problems else 0)
