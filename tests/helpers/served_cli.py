"""`python served_cli.py RESULT ARGS`: `pendcli ARGS` as ``python -m pendcli`` runs it, with
``reproduce_all`` answering from the pickled computation RESULT (tests/helpers/regenerated.py),
read when the command asks for it, at the point the real computation would start."""

from __future__ import annotations

import pickle
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any


def stand_in(stored: Path) -> Callable[..., Any]:
    """``reproduce_all`` answering from ``stored`` (what was asked, the result), or a part of
    it (fewer papers, no formulas, no ledger: :func:`part_of`); a call that asks for more
    (another paper, the stability table) is an error, not served."""

    def reproduce_all(
        keys: tuple[str, ...],
        formulas: bool = True,
        quiet: bool = True,
        stability: bool = False,
        jobs: int | None = None,
        equations: bool = False,
        cache: object = None,
        meanwhile: object = None,  # nothing is computed here for it to run beside
    ) -> object:
        computed, result = pickle.loads(stored.read_bytes())
        asked = {"keys": tuple(keys), "formulas": formulas, "equations": equations}
        if not holds(computed, asked, stability):
            raise AssertionError(f"served {computed}, asked {asked} stability={stability}")
        return part_of(result, tuple(keys), formulas, equations)

    return reproduce_all


def holds(computed: dict[str, Any], asked: dict[str, Any], stability: bool) -> bool:
    """Whether the computation ``computed`` (what it was asked) holds what ``asked`` asks."""
    return (
        not stability
        and set(asked["keys"]) <= set(computed["keys"])
        and all(computed[k] or not asked[k] for k in ("formulas", "equations"))
    )


def part_of(result: Any, papers: tuple[str, ...], formulas: bool, equations: bool) -> Any:
    """A computation of every table cut to what was asked: what ``reproduce_all`` returns
    when asked for it alone (the same rows, compared equal for four such parts)."""
    from dataclasses import replace

    def only(rows: dict[str, Any], wanted: bool = True) -> dict[str, Any]:
        return {k: rows[k] for k in papers if k in rows} if wanted else {}

    return replace(
        result,
        papers=papers,
        claims=only(result.claims),
        formulas=only(result.formulas, formulas),
        equations=only(result.equations, equations),
    )


def main() -> None:
    from pendcli.run import reproduce

    reproduce.reproduce_all = stand_in(Path(sys.argv[1]))  # type: ignore[assignment]
    sys.argv = ["pendcli", *sys.argv[2:]]
    from pendcli.cli.main import run

    run()


if __name__ == "__main__":
    main()
