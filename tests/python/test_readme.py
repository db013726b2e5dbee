"""The README's Python example runs as written (spec/python.md)."""
import os
import re
import runpy

import matplotlib

matplotlib.use("Agg")


def test_readme_example(source, tmp_path, monkeypatch):
    readme = (source / "README.md").read_text()
    section = readme.split("\n## Python\n", 1)[1]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    assert len(code.strip().splitlines()) == 5
    # The example's input path is relative to the source tree; its outputs go to tmp_path.
    os.symlink(source / "tests", tmp_path / "tests")
    monkeypatch.chdir(tmp_path)
    script = tmp_path / "example.py"
    script.write_text(code)
    runpy.run_path(str(script))
    assert (tmp_path / "cube.vtu").stat().st_size > 0
    assert (tmp_path / "dihedral.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
