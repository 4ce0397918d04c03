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
    """``reproduce_all`` answering from ``stored`` (what was asked, the result); a call that
    asks for another computation (other papers, no ledger...) is an error, not served."""

    def reproduce_all(
        keys: tuple[str, ...],
        formulas: bool = True,
        quiet: bool = True,
        stability: bool = False,
        jobs: int | None = None,
        equations: bool = False,
        cache: object = None,
    ) -> object:
        computed, result = pickle.loads(stored.read_bytes())
        asked = {"keys": tuple(keys), "formulas": formulas, "equations": equations}
        if asked | {"stability": stability} != computed:
            raise AssertionError(f"served {computed}, asked {asked} stability={stability}")
        return result

    return reproduce_all


def main() -> None:
    from pendcli.run import reproduce

    reproduce.reproduce_all = stand_in(Path(sys.argv[1]))  # type: ignore[assignment]
    sys.argv = ["pendcli", *sys.argv[2:]]
    from pendcli.cli.main import run

    run()


if __name__ == "__main__":
    main()
