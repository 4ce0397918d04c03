"""The plumbing that knows nothing of pendulums, papers or tables: errors, files,
the console, interrupts, workers, the cache (docs/ARCHITECTURE.md).
"""
