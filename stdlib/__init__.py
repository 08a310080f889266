"""Command libraries the language loads (algebra commands, mechanisms, plots)."""
