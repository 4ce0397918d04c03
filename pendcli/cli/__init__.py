"""The command-line adapter: parse arguments, call one library function, render.

Nothing here computes; every command body is a few lines. Heavy modules (numpy, scipy,
matplotlib, the paper modules) are imported inside command bodies so `pendcli --help`
and `pendcli list` start instantly.
"""
