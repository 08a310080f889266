"""The mech language: grammar, parser, interpreter, printing, REPL and CLI."""
