"""`python served_cli.py RESULT ARGS`: `pendcli ARGS` as ``python -m pendcli`` runs it, with
``reproduce_all`` answering from the pickled computation RESULT (tests/helpers/regenerated.py),
read when the command asks for it, at the point the real computation would start."""

from __future__ import annotations

import pickle
import sys
from pathlib import Path


def main() -> None:
    from pendcli.run import reproduce

    stored = Path(sys.argv[1])

    def reproduce_all(*args: object, **kwargs: object) -> object:
        return pickle.loads(stored.read_bytes())

    reproduce.reproduce_all = reproduce_all  # type: ignore[assignment]
    sys.argv = ["pendcli", *sys.argv[2:]]
    from pendcli.cli.main import run

    run()


if __name__ == "__main__":
    main()
