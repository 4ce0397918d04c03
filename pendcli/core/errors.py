"""The package's one exception type: the CLI turns it into one red line and exit code 2."""


class PendcliError(Exception):
    """Bad input, a malformed table, an unknown claim: a message meant for the user."""
