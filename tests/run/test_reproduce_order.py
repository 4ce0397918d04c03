"""The order of a run's steps in one process: the claims first, so a published table that
does not match the code is its one-line error at once, not after every ledger is judged."""

from __future__ import annotations

import pytest

from pendcli.base.errors import PendcliError


def test_one_process_judges_the_claims_before_any_ledger(monkeypatch: pytest.MonkeyPatch) -> None:
    from pendcli.papers import registry
    from pendcli.run import reproduce

    judged: list[str] = []

    def claims(key: str) -> list[object]:
        judged.append(f"{key} claims")
        if key == "lecornu":
            raise PendcliError("tables/published/lecornu.toml: no claim 'x'")
        return []

    def ledger(keys: list[str], part: tuple[int, int], measure: bool = True) -> list[object]:
        judged.append(f"{keys[0]} equations {part[0]}")
        return []

    def formulas(key: str) -> list[object]:
        judged.append(f"{key} formulas")
        return []

    monkeypatch.setattr(reproduce, "claim_rows", claims)
    monkeypatch.setattr(reproduce, "formula_checks", formulas)
    monkeypatch.setattr(registry, "equation_rows", ledger)
    with pytest.raises(PendcliError, match="no claim 'x'"):
        reproduce.reproduce_all(("tisserand", "lecornu"), formulas=True, equations=True, jobs=1)
    assert judged == ["tisserand claims", "lecornu claims"]
