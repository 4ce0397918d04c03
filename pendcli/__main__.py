from pendcli.cli.main import run

run()
