#!/usr/bin/env python3
"""Splices the tables of a benchmark run into docs/PERFORMANCE.md, between the
<!-- generated:NAME begin --> / <!-- generated:NAME end --> markers:

  skips     the "Skips" section of cloudbench's report.md   (build/bin/cloudbench ... --out DIR)
  sequence  the table of DIR/sequence.md                     (build/bin/cloudbench --sequence --out DIR)
  render    the table printed by build/bin/render_bench      (saved as DIR/render.txt)

Usage: scripts/splice_bench_tables.py DIR [docs/PERFORMANCE.md]
Only the tables are replaced; the prose around them states what they mean and must be
re-read when the numbers move."""
import pathlib
import re
import sys


def table_from(text: str, start: str) -> str:
    i = text.index(start)
    lines = []
    for line in text[i:].splitlines():
        if not line.startswith("|"):
            break
        lines.append(line)
    return "\n".join(lines)


def main() -> int:
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    run = pathlib.Path(sys.argv[1])
    doc = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "docs/PERFORMANCE.md")
    parts = {}
    report = run / "report.md"
    if report.exists():
        text = report.read_text()
        skips = text[text.index("## Skips"):text.index("## Per scene")].strip()
        parts["skips"] = skips.replace("## Skips", "### Skip table (generated)", 1)
    if (run / "sequence.md").exists():
        parts["sequence"] = table_from((run / "sequence.md").read_text(), "| flight |")
    if (run / "render.txt").exists():
        parts["render"] = table_from((run / "render.txt").read_text(), "| preset |")
    text = doc.read_text()
    for name, body in parts.items():
        pattern = re.compile(r"(<!-- generated:%s begin[^>]*-->\n).*?(\n<!-- generated:%s end -->)" % (name, name), re.S)
        if not pattern.search(text):
            print(f"splice: no markers for {name} in {doc}", file=sys.stderr)
            return 1
        text = pattern.sub(lambda m: m.group(1) + body + m.group(2), text)
        print(f"splice: {name} <- {run}")
    doc.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
