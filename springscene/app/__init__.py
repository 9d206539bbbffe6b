"""The springscene command-line app (thin: argument parsing, progress, exit codes)."""
