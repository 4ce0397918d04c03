"""Regenerate the README's sample-output section from the code (`make regen`).

The README shows real output; this module produces it, so the numbers there are never
typed in. ``python -m pendcli.docs`` rewrites the text between the markers
``<!-- sample:start -->`` and ``<!-- sample:end -->``; ``--check`` exits 1 if it is stale.
"""

from __future__ import annotations

import sys
from pathlib import Path

from pendcli.render import Column, to_markdown

START, END = "<!-- sample:start -->", "<!-- sample:end -->"


def sample_section() -> str:
    from pendcli.core.claims import PAPERS
    from pendcli.render.views import claim_columns
    from pendcli.reproduce import reproduce_all

    result = reproduce_all(PAPERS, formulas=True, quiet=True)
    counts = result.verdict_counts()
    verdicts = ["agrees", "truncated", "last-digit", "discrepant"]
    summary = [
        {
            "paper": key,
            **{v: counts[key].get(v, 0) for v in verdicts},
            "formulas holding": counts[key].get("formula holds", 0),
            "formulas failing": counts[key].get("formula fails", 0),
        }
        for key in PAPERS
    ]
    # One row of each verdict, first in paper order, plus one with an exact-model column.
    rows = [r.as_dict() for key in PAPERS for r in result.claims[key]]
    sample, seen = [], set()
    for row in rows:
        kind = (row["verdict"], row["exact"] is not None)
        if kind not in seen:
            seen.add(kind)
            sample.append(row)
    columns = [c for c in claim_columns(sample, with_note=False) if c.key != "source"]
    return "\n".join(
        [
            "Verdicts over all three papers (`pendcli reproduce`):",
            "",
            to_markdown(summary, [Column(k, k) for k in summary[0]]),
            "One row of each verdict from `pendcli reproduce --format markdown` "
            "(notes and sources in the report):",
            "",
            to_markdown(sample, columns),
        ]
    )


def splice(readme: str, section: str) -> str:
    if START not in readme or END not in readme:
        raise SystemExit(f"README has no {START} ... {END} markers")
    head, rest = readme.split(START, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{START}\n{section}\n{END}{tail}"


def main(argv: list[str]) -> int:
    path = Path(argv[argv.index("--readme") + 1]) if "--readme" in argv else Path("README.md")
    text = path.read_text(encoding="utf-8")
    new = splice(text, sample_section())
    if "--check" in argv:
        if new != text:
            print(f"{path}: sample section is stale; run `make regen`", file=sys.stderr)
            return 1
        return 0
    path.write_text(new, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
