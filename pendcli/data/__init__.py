"""The tables as typed data: printed numbers, the words, the rows, the ledgers and
the reading records, loaded and validated (docs/ARCHITECTURE.md).
"""
