"""What the tests share: running the CLI (cli), the committed ledgers and claims loaded
once per process (ledgers, evaluated), edits of a ledger's rows (mutations), and the
suite's own machinery (timing, the 2 s rule's durations, suite_split). Imported as
``helpers.<module>``: tests/conftest.py puts tests/ on sys.path (pytest's rootdir
conftest)."""
