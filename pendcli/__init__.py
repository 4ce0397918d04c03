"""pendcli: regenerate the numerical claims of three historical papers on the pendulum.

Layout: :mod:`pendcli.core` (printed numbers, verdicts, published tables, the claim and
formula engines, errors), :mod:`pendcli.render` (one renderer per output format, knowing
nothing of pendulums), :mod:`pendcli.numerics` (Bessel zeros, planar and spherical
pendulum done exactly), :mod:`pendcli.papers` (one package per paper: its model, claims,
formulas, figures and speed/accuracy families) and :mod:`pendcli.cli`, a thin adapter.
"""


# The version has one source, pyproject.toml, read through the installed metadata.
def __getattr__(name: str) -> str:
    if name == "__version__":
        from importlib.metadata import version

        return version("pendcli")
    raise AttributeError(name)
