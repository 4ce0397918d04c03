"""The versions a run was made with: Python, the platform and every library that can move a
regenerated number (the exact set is locked in requirements.lock).

Read from the installed metadata, so naming them imports none of the libraries.
"""

from __future__ import annotations

import platform

# the libraries pendcli computes and renders with, beside pendcli itself
DEPENDENCIES = (
    "numpy",
    "scipy",
    "mpmath",
    "sympy",
    "matplotlib",
    "typer",
    "rich",
    "jinja2",
    "latex2mathml",
    "grandalf",
)
LIBRARIES = ("pendcli", *DEPENDENCIES)


def library_versions() -> list[tuple[str, str]]:
    """(name, version) for Python, the platform and each of LIBRARIES ("not installed")."""
    from importlib.metadata import PackageNotFoundError, version

    found = [
        ("python", platform.python_version()),
        ("platform", f"{platform.system()} {platform.machine()}"),
    ]
    for name in LIBRARIES:
        try:
            found.append((name, version(name)))
        except PackageNotFoundError:
            found.append((name, "not installed"))
    return found
