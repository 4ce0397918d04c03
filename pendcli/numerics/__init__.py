"""Mathematics independent of any paper: zeros of Bessel functions (``besselzeros``), the
planar pendulum exactly by elliptic functions (``planar``) and the spherical one (``spherical``).

A numerics module imports only the standard library, numpy, scipy, mpmath and the core's
errors (a bad argument is a one-line PendcliError): never a paper, the CLI or the
orchestration (docs/ARCHITECTURE.md).
"""
