"""Put the scenario suites' tables (`sdi bench --report benchmarks/results/suites`) into the
README's measurements section.

Each table sits between ``<!-- bench:SUITE -->`` and ``<!-- /bench:SUITE -->`` in README.md;
the text between the markers is replaced by ``benchmarks/results/suites/SUITE.md``. A marker
pair without its table, or a table without its markers, is an error (nothing is written).

Run: `python benchmarks/readme_tables.py` (the last step of `make bench`).
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TABLES = ROOT / "benchmarks" / "results" / "suites"
README = ROOT / "README.md"


def splice(readme: str, tables: dict[str, str]) -> str:
    for name, table in tables.items():
        pattern = re.compile(
            rf"(<!-- bench:{re.escape(name)} -->\n).*?(<!-- /bench:{re.escape(name)} -->)", re.S
        )
        if not pattern.search(readme):
            raise SystemExit(f"README.md has no <!-- bench:{name} --> … <!-- /bench:{name} -->")
        body = table.strip() + "\n"
        readme = pattern.sub(lambda m, body=body: m.group(1) + body + m.group(2), readme)
    missing = set(re.findall(r"<!-- bench:([\w-]+) -->", readme)) - set(tables)
    if missing:
        raise SystemExit(f"no table for README markers {sorted(missing)} in {TABLES}")
    return readme


def main() -> int:
    tables = {p.stem: p.read_text(encoding="utf-8") for p in sorted(TABLES.glob("*.md"))}
    README.write_text(splice(README.read_text(encoding="utf-8"), tables), encoding="utf-8")
    print(f"README.md: {len(tables)} tables from {TABLES.relative_to(ROOT)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
