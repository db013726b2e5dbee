#!/usr/bin/env python3
"""spec/cli.md against `bccmis SUBCOMMAND --help`.

For every subcommand listed by `bccmis --help`, the long options its --help
names (except --help) must be exactly the long options named in the first
column of the tables in its `## SUBCOMMAND` section of spec/cli.md, and the
section must have an `Example:` and an `Exit codes:` line.

  check_cli_spec.py BCCMIS SPEC             exit 0 when they match, 1 with the differences
  check_cli_spec.py BCCMIS SPEC --self-test plant a mismatch and require that it is caught
"""
import re
import subprocess
import sys


def help_text(bccmis, *args):
    return subprocess.run([bccmis, *args, "--help"], capture_output=True, text=True, check=True).stdout


def subcommands(bccmis):
    text = help_text(bccmis)
    section = text.split("Subcommands:", 1)[1]
    return re.findall(r"^  ([a-z]+)\s", section, re.M)


def help_options(text):
    options = set()
    for line in text.splitlines():
        m = re.match(r"^\s+(?:-\w,)?(--[a-z][a-z0-9-]*)", line)
        if m and m.group(1) != "--help":
            options.add(m.group(1))
    return options


def spec_sections(spec_text):
    sections = {}
    for block in re.split(r"^## ", spec_text, flags=re.M)[1:]:
        name, _, body = block.partition("\n")
        sections[name.strip()] = body
    return sections


def spec_options(body):
    options = set()
    for line in body.splitlines():
        if line.startswith("| `"):
            first = line.split("|")[1]
            options.update(re.findall(r"(--[a-z][a-z0-9-]*)", first))
    return options


def differences(bccmis, spec_text):
    sections = spec_sections(spec_text)
    problems = []
    names = subcommands(bccmis)
    if not names:
        problems.append("bccmis --help lists no subcommands")
    for name in names:
        if name not in sections:
            problems.append(f"spec/cli.md has no '## {name}' section")
            continue
        body = sections[name]
        in_help = help_options(help_text(bccmis, name))
        in_spec = spec_options(body)
        for o in sorted(in_help - in_spec):
            problems.append(f"{name}: {o} is in --help but not in spec/cli.md")
        for o in sorted(in_spec - in_help):
            problems.append(f"{name}: {o} is in spec/cli.md but not in --help")
        for needed in ("Example:", "Exit codes:"):
            if needed not in body:
                problems.append(f"{name}: spec/cli.md's section has no '{needed}' line")
    for name in sections:
        if name not in names and name not in ("Exit codes", "Inputs, outputs and messages"):
            problems.append(f"spec/cli.md has a section '{name}' that is no subcommand")
    return problems


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    bccmis, spec_path = sys.argv[1], sys.argv[2]
    spec_text = open(spec_path, encoding="utf-8").read()
    if "--self-test" in sys.argv[3:]:
        if differences(bccmis, spec_text):
            print("self-test: the real spec does not match, fix that first", file=sys.stderr)
            return 1
        # Planted mismatches: an option dropped from a table, one added, a section removed.
        planted = {
            "dropped --state from replay": spec_text.replace("| `--state FILE` | the canonical state to FILE", "| `STATEFILE` | x", 1),
            "added --frobnicate to check": spec_text.replace("| `-q, --quiet` | print nothing", "| `--frobnicate` | x |\n| `-q, --quiet` | print nothing", 1),
            "removed the diff section": spec_text.replace("## diff\n", "## difference\n", 1),
        }
        for what, text in planted.items():
            assert text != spec_text, what
            if not differences(bccmis, text):
                print(f"self-test: FAILED: {what} was not caught", file=sys.stderr)
                return 1
        print(f"self-test: ok, {len(planted)} planted mismatches caught")
        return 0
    problems = differences(bccmis, spec_text)
    for p in problems:
        print(p)
    if not problems:
        print(f"spec/cli.md matches --help of {len(subcommands(bccmis))} subcommands")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
