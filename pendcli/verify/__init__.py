"""The verdicts: the rule for a printed number, the formula engine and the ledger
engine, the causes and the explanations (docs/ARCHITECTURE.md).
"""
