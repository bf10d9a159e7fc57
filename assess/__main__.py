from assess.cli import run

run()
